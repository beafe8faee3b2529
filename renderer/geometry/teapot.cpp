#include "renderer/geometry/teapot.h"

#include "renderer/geometry/basis.h"
#include "renderer/geometry/bezier_patch_text.h"
#include "renderer/geometry/patches.h"
#include "renderer/geometry/teapot_text.h"

namespace gonio {
namespace {

// The patch's control points as the "vertex point P" of a Patch "bicubic".
PrimVarSet ControlPointsAsP(const BezierPatch& patch) {
    PrimVar p;
    p.decl.name = "P";
    p.decl.cls = ParamClass::Vertex;
    p.decl.type = ParamType::Point;
    p.components = 3;
    for (const V3f& point : patch.controlPoints)
        p.values.insert(p.values.end(), {point.x, point.y, point.z});
    PrimVarSet vars;
    vars.vars.push_back(std::move(p));
    return vars;
}

}  // namespace

GeometryResult<std::vector<TriangleMesh>> MakeTeapot(const TessellationRates& rates) {
    using Result = GeometryResult<std::vector<TriangleMesh>>;
    auto patches = ParseBezierPatchText(TeapotText());
    if (!patches) return Result::Error("the embedded data/teapot.txt: " + patches.Error());
    std::vector<TriangleMesh> meshes;
    for (const BezierPatch& patch : patches.Value()) {
        auto mesh =
            MakePatch("bicubic", BezierBasis(), BezierBasis(), ControlPointsAsP(patch), rates);
        if (!mesh) return Result::Error("teapot patch '" + patch.name + "': " + mesh.Error());
        meshes.push_back(mesh.Take());
    }
    return meshes;
}

}  // namespace gonio
