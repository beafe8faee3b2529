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
    // Level of detail (RISpec 3.2's Detail and DetailRange): the raster area of the
    // current Detail bound times RelativeDetail (infinite until a Detail is given, or when the
    // bound reaches behind the eye), and the range minvisible lowertransition uppertransition
    // maxvisible of detail in which the primitives that follow are shown (ShownAtDetail).
    float detail = std::numeric_limits<float>::infinity();
    float detailRange[4] = {0, 0, std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::infinity()};
    bool matte = false;
    PatchBasis ubasis, vbasis;  // bezier unless Basis says otherwise
    // TrimCurve: the region of (u,v) the following NuPatches keep; null: untrimmed.
    std::shared_ptr<const TrimRegion> trimCurves;
    std::string identifier;  // Attribute "identifier" "name"
    // Every Attribute request by name, merged and typed (attribute() reads them too).
    std::map<std::string, ParamDict> user;
};

// Whether primitives of the level-of-detail range `range` (DetailRange) show at `detail`. A
// representation is wholly visible between the transitions and fades linearly to nothing at
// minvisible and maxvisible; gonio does not dissolve one into the next but shows it where it is
// more than half visible, and at exactly half where it fades out, so that of two
// representations whose transitions meet exactly one shows at every detail.
bool ShownAtDetail(float detail, const float range[4]);

}  // namespace gonio
