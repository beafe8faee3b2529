#pragma once
// The attribute state of RISpec §4.2: everything AttributeBegin saves and AttributeEnd restores
// except the transform, which the builder keeps beside it. Primitives share an immutable
// snapshot of the attributes they were declared with.

#include <Imath/ImathMatrix.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "base/file_loc.h"
#include "renderer/geometry/basis.h"
#include "renderer/geometry/trim_curves.h"
#include "renderer/rib/param_list.h"
#include "renderer/scene/param_dict.h"

namespace gonio {

using Imath::M44f;

// A shader named in the RIB with its instance parameters (typed later by the shading system).
struct ShaderInstance {
    std::string name;
    ParamList params;
    M44f worldFromShader;  // "shader" space: the transform current when the shader was declared
    FileLoc loc;

    bool IsSet() const { return !name.empty() && name != "null"; }
};

// A light source declared by LightSource or AreaLightSource (whose geometry is
// SceneLight::shapes).
struct LightInstance {
    ShaderInstance shader;
    RtHandle handle;
    bool isArea = false;
};

struct Attributes {
    std::vector<float> color{1, 1, 1};    // ncomps values (ColorSamples)
    std::vector<float> opacity{1, 1, 1};  // ncomps values
    std::vector<float> textureCoordinates{0, 0, 1, 0, 0, 1, 1, 1};
    ShaderInstance surface;
    ShaderInstance displacement;
    ShaderInstance atmosphere;
    ShaderInstance interior;
    ShaderInstance exterior;
    std::set<int> activeLights;  // indices into Frame::lights that illuminate this primitive
    // The Frame::lights index of the AreaLightSource of this attribute block, whose geometry
    // the following primitives become (RISpec §4.1.3); −1: none.
    int areaLight = -1;
    // Orientation: "outside" keeps the geometrically outward normal of every primitive,
    // "inside" reverses it; "lh"/"rh" ask for the normal dPdu×dPdv gives in a space of that
    // handedness, resolved per primitive against the handedness of its camera-from-object
    // transform (camera space is left-handed).
    enum class Orientation { Outside, Inside, LeftHanded, RightHanded };
    Orientation orientation = Orientation::Outside;
    bool twoSided = true;  // Sides 2
    // ShadingRate: the raster area, in pixels, one shading point stands for. Camera samples
    // whose hits lie within it on the same surface share one shaded colour (docs/user-guide.md,
    // "Shading rate"); 1 by default, as in RenderMan.
    float shadingRate = 1;
    bool matte = false;
    PatchBasis ubasis, vbasis;  // bezier unless Basis says otherwise
    // TrimCurve: the region of (u,v) the following NuPatches keep; null: untrimmed.
    std::shared_ptr<const TrimRegion> trimCurves;
    std::string identifier;  // Attribute "identifier" "name"
    // Every Attribute request by name, merged and typed (attribute() reads them too).
    std::map<std::string, ParamDict> user;
};

}  // namespace gonio
