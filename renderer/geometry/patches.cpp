#include "renderer/geometry/patches.h"

#include <cmath>

#include "renderer/geometry/primvar_eval.h"

namespace gonio {
namespace {

// One direction of a patch mesh: its control count, wrap mode and basis.
struct PatchDirection {
    bool cubic = false;
    int count = 0;
    bool periodic = false;
    PatchBasis basis;

    int Step() const { return cubic ? basis.step : 1; }
    // RISpec §5.2: nupatches for each type and wrap mode.
    int PatchCount() const {
        if (!cubic) return periodic ? count : count - 1;
        return periodic ? count / basis.step : (count - 4) / basis.step + 1;
    }
    int VaryingCount() const { return periodic ? PatchCount() : PatchCount() + 1; }
};

std::optional<std::string> CheckDirection(const PatchDirection& d, const char* name) {
    const std::string n = name;
    if (d.cubic && d.basis.step < 1)
        return "the " + n + " basis step must be at least 1, got " + std::to_string(d.basis.step);
    if (!d.cubic) {
        if (d.count < 2)
            return "a bilinear patch mesh needs n" + n + " >= 2, got " + std::to_string(d.count);
        return std::nullopt;
    }
    if (d.periodic) {
        if (d.count < 4 && d.count < d.basis.step)
            return "a periodic bicubic patch mesh needs n" + n + " >= 4, got " +
                   std::to_string(d.count);
        if (d.count % d.basis.step != 0)
            return "periodic n" + n + " = " + std::to_string(d.count) +
                   " is not a multiple of the " + n + " step " + std::to_string(d.basis.step);
        return std::nullopt;
    }
    if (d.count < 4 || (d.count - 4) % d.basis.step != 0)
        return "nonperiodic bicubic n" + n + " = " + std::to_string(d.count) +
               " must be 4 plus a multiple of the " + n + " step " + std::to_string(d.basis.step);
    return std::nullopt;
}

GridAxis MakeAxis(const PatchDirection& d, int steps) {
    GridAxis axis;
    const int patches = d.PatchCount();
    axis.controlCount = d.count;
    axis.varyingCount = d.VaryingCount();
    axis.cellCount = patches;
    const int last = patches * steps;
    for (int k = 0; k <= last; ++k) {
        // The closing sample of a periodic axis is its first sample again, at parameter 1.
        const int kk = d.periodic && k == last ? 0 : k;
        const int cell = std::min(kk / steps, patches - 1);
        const float t = static_cast<float>(kk - cell * steps) / steps;
        GridAxis::Sample s;
        s.param = static_cast<float>(k) / last;
        s.firstControl = cell * d.Step();
        if (d.cubic) {
            const auto w = BasisWeights(d.basis.matrix, t);
            s.weights.assign(w.begin(), w.end());
        } else {
            s.weights = {1 - t, t};
        }
        s.varyingCell = cell;
        s.varyingT = t;
        axis.samples.push_back(std::move(s));
        if (k < last) axis.intervalCell.push_back(k / steps);
    }
    return axis;
}

// Whether every bilinear patch is a parallelogram with one w: two triangles are then exact.
bool AllParallelograms(const std::vector<float>& h, const PatchDirection& u,
                       const PatchDirection& v) {
    auto at = [&](int i, int j) {
        return h.data() + 4 * (static_cast<size_t>(j % v.count) * u.count + i % u.count);
    };
    for (int j = 0; j < v.PatchCount(); ++j)
        for (int i = 0; i < u.PatchCount(); ++i) {
            const float *a = at(i, j), *b = at(i + 1, j), *c = at(i, j + 1), *d = at(i + 1, j + 1);
            float size = 0;
            for (int k = 0; k < 3; ++k)
                size = std::max(size, std::abs(b[k] - a[k]) + std::abs(c[k] - a[k]));
            for (int k = 0; k < 4; ++k)
                if (std::abs(a[k] + d[k] - b[k] - c[k]) > 1e-6f * size) return false;
            if (a[3] != b[3] || a[3] != c[3]) return false;
        }
    return true;
}

bool HasInterpolatedVars(const PrimVarSet& vars) {
    for (const PrimVar& v : vars.vars)
        if (!IsPositionVar(v.decl.name) && v.decl.cls != ParamClass::Constant &&
            v.decl.cls != ParamClass::Uniform)
            return true;
    return false;
}

// Homogeneous control points from P, Pw or Pz (a height field over the unit square).
std::optional<std::vector<float>> ControlPoints(const PrimVarSet& vars, const PatchDirection& u,
                                                const PatchDirection& v, bool* rational,
                                                std::string* error) {
    *rational = false;
    if (const PrimVar* pz = vars.Find("Pz"); pz && !vars.Find("P") && !vars.Find("Pw")) {
        if (u.periodic || v.periodic) {
            *error = "a height field (\"Pz\") cannot be periodic";
            return std::nullopt;
        }
        std::vector<float> h;
        for (int j = 0; j < v.count; ++j)
            for (int i = 0; i < u.count; ++i) {
                const float z = pz->values[static_cast<size_t>(j) * u.count + i];
                h.insert(h.end(), {static_cast<float>(i) / (u.count - 1),
                                   static_cast<float>(j) / (v.count - 1), z, 1.0f});
            }
        return h;
    }
    std::vector<float> h = ReadHomogeneousPositions(vars);
    if (h.empty()) {
        *error = "the patch needs positions: \"P\", \"Pw\" or \"Pz\"";
        return std::nullopt;
    }
    *rational = vars.Find("Pw") != nullptr && vars.Find("P") == nullptr;
    return h;
}

}  // namespace

GeometryResult<TriangleMesh> MakePatchMesh(const std::string& type, int nu,
                                           const std::string& uwrap, int nv,
                                           const std::string& vwrap, const PatchBasis& ubasis,
                                           const PatchBasis& vbasis, const PrimVarSet& vars,
                                           const TessellationRates& rates) {
    using Result = GeometryResult<TriangleMesh>;
    if (type != "bilinear" && type != "bicubic")
        return Result::Error("unknown patch type \"" + type +
                             "\" (expected \"bilinear\" or \"bicubic\")");
    for (const std::string* wrap : {&uwrap, &vwrap})
        if (*wrap != "periodic" && *wrap != "nonperiodic")
            return Result::Error("unknown wrap mode \"" + *wrap +
                                 "\" (expected \"periodic\" or \"nonperiodic\")");
    const bool cubic = type == "bicubic";
    const PatchDirection u{cubic, nu, uwrap == "periodic", ubasis};
    const PatchDirection v{cubic, nv, vwrap == "periodic", vbasis};
    if (auto bad = CheckDirection(u, "u")) return Result::Error(*bad);
    if (auto bad = CheckDirection(v, "v")) return Result::Error(*bad);

    const int varying = u.VaryingCount() * v.VaryingCount();
    const ClassCounts counts{u.PatchCount() * v.PatchCount(), varying, nu * nv, varying};
    if (auto bad = CheckCounts(vars, counts)) return Result::Error(*bad);
    bool rational = false;
    std::string error;
    const auto h = ControlPoints(vars, u, v, &rational, &error);
    if (!h) return Result::Error(error);
    if (h->size() != 4 * static_cast<size_t>(nu) * nv)
        return Result::Error("the patch mesh needs " + std::to_string(nu * nv) +
                             " positions, got " + std::to_string(h->size() / 4));

    int steps = rates.curvedSteps;
    if (!cubic)
        steps = AllParallelograms(*h, u, v) && !HasInterpolatedVars(vars)
                    ? 1
                    : rates.curvedBilinearSteps;
    steps = rates.StepsWithinBudget(steps, static_cast<long>(u.PatchCount()) * v.PatchCount());
    return TessellateTensorGrid(MakeAxis(u, steps), MakeAxis(v, steps), *h, rational, vars);
}

GeometryResult<TriangleMesh> MakePatch(const std::string& type, const PatchBasis& ubasis,
                                       const PatchBasis& vbasis, const PrimVarSet& vars,
                                       const TessellationRates& rates) {
    const int n = type == "bicubic" ? 4 : 2;
    return MakePatchMesh(type, n, "nonperiodic", n, "nonperiodic", ubasis, vbasis, vars, rates);
}

}  // namespace gonio
