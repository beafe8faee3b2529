#include "renderer/geometry/points.h"

#include "renderer/geometry/primvar_eval.h"

namespace gonio {

GeometryResult<PointSet> MakePoints(const PrimVarSet& vars) {
    using Result = GeometryResult<PointSet>;
    std::string error;
    auto centers = ReadPositions(vars, &error);
    if (!centers) return Result::Error(error);
    const int n = static_cast<int>(centers->size());
    if (auto bad = CheckCounts(vars, ClassCounts{1, n, n, n})) return Result::Error(*bad);

    PointSet set;
    set.centers = std::move(*centers);
    float constantWidth = 1.0f;
    if (const PrimVar* cw = vars.Find("constantwidth"); cw && !cw->values.empty())
        constantWidth = cw->values[0];
    set.radii.assign(n, 0.5f * constantWidth);
    const PrimVar* width = vars.Find("width");
    if (width && width->components == 1 && width->ValueCount() == n)
        for (int i = 0; i < n; ++i) set.radii[i] = 0.5f * width->values[i];
    for (const PrimVar& var : vars.vars) {
        const std::string& name = var.decl.name;
        if (!IsPositionVar(name) && name != "width" && name != "constantwidth")
            set.vars.vars.push_back(var);
    }
    return set;
}

}  // namespace gonio
