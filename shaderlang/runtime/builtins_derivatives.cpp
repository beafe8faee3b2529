// Derivative built-ins (RISpec §15.1-15.2): Du, Dv, Deriv, area, calculatenormal, as finite
// differences over the neighbouring points of the batch that the ShadingContext names
// (UNeighbours/VNeighbours). A point with no neighbour in a direction uses the point whose
// neighbour it is (a backward difference); with neither, the difference is 0. Du and Dv turn
// the two differences into parametric derivatives (PartialSolver); area and calculatenormal
// use the differences themselves: the surface element that the two neighbours span (a grid
// cell, or a pixel's footprint in a render).

#include "shaderlang/runtime/builtins_derivatives.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/runtime/globals_view.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

Stencil MakeStencil(const BuiltinCall& call, const int* neighbours) {
    const int n = call.n;
    Stencil s{std::vector<int>(n, -1), std::vector<int>(n, -1)};
    if (!neighbours) return s;
    std::vector<int> previous(n, -1);
    for (int p = 0; p < n; ++p) {
        if (neighbours[p] >= 0 && neighbours[p] < n) previous[neighbours[p]] = p;
    }
    for (int p = 0; p < n; ++p) {
        if (neighbours[p] >= 0 && neighbours[p] < n) {
            s.from[p] = p, s.to[p] = neighbours[p];
        } else if (previous[p] >= 0) {
            s.from[p] = previous[p], s.to[p] = p;
        }
    }
    return s;
}

Stencil UStencil(const BuiltinCall& call) {
    return MakeStencil(call, call.context ? call.context->UNeighbours() : nullptr);
}
Stencil VStencil(const BuiltinCall& call) {
    return MakeStencil(call, call.context ? call.context->VNeighbours() : nullptr);
}

PartialSolver::PartialSolver(const BuiltinCall& call)
    : call_(call),
      u_(UStencil(call)),
      v_(VStencil(call)),
      steps_(call.context ? call.context->NeighbourSteps() : nullptr) {
    if (call.globals) du_ = call.globals->Get("du"), dv_ = call.globals->Get("dv");
}

void PartialSolver::Solve(const FloatArg& a, int c, int p, bool unitSteps, float* alongU,
                          float* alongV) const {
    *alongU = *alongV = 0.0f;
    const float changeU = Delta(u_, a, c, p), changeV = Delta(v_, a, c, p);
    if (!steps_) {
        const float hu = unitSteps ? 1.0f : du_.data ? du_.At(0, p) : 0.0f;
        const float hv = unitSteps ? 1.0f : dv_.data ? dv_.At(0, p) : 0.0f;
        if (hu != 0.0f) *alongU = changeU / hu;
        if (hv != 0.0f) *alongV = changeV / hv;
        return;
    }
    if (u_.from[p] < 0 || v_.from[p] < 0) return;
    // Each stencil's step is that of its `from` point (forward, or backward at an edge):
    // changeU = x_u·au + x_v·av and changeV = x_u·bu + x_v·bv (Cramer's rule).
    const int n = call_.n;
    const float au = steps_[u_.from[p]], av = steps_[n + u_.from[p]];
    const float bu = steps_[2 * n + v_.from[p]], bv = steps_[3 * n + v_.from[p]];
    const float det = au * bv - av * bu;
    if (std::fabs(det) <= 1e-6f * (std::fabs(au * bv) + std::fabs(av * bu))) return;
    *alongU = (changeU * bv - changeV * av) / det;
    *alongV = (changeV * au - changeU * bu) / det;
}

namespace {

V3 DeltaTriple(const Stencil& s, const FloatArg& a, int p) {
    return V3(Delta(s, a, 0, p), Delta(s, a, 1, p), Delta(s, a, 2, p));
}

FloatArg Global(const BuiltinCall& call, const char* name) {
    return call.globals ? call.globals->Get(name) : FloatArg{};
}

// Du(x) / Dv(x): the parametric derivative along u (v).
template <bool AlongU>
void PartialKernel(const BuiltinCall& call) {
    const PartialSolver solver(call);
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) {
            float alongU, alongV;
            solver.Solve(call.args[0], c, p, false, &alongU, &alongV);
            call.result.At(c, p) = AlongU ? alongU : alongV;
        }
    });
}

// Deriv(num, den) = Du(num)/Du(den) + Dv(num)/Dv(den) (RISpec §15.1); each term is 0 where den
// does not change. On a grid the steps du and dv cancel. Solved derivatives are not exactly 0
// where den does not change, so a term counts only where den changes along it by more than
// 1e-3 of its larger change.
void DerivKernel(const BuiltinCall& call) {
    const PartialSolver solver(call);
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        float denU, denV;
        solver.Solve(call.args[1], 0, p, true, &denU, &denV);
        const float least = 1e-3f * std::max(std::fabs(denU), std::fabs(denV));
        for (int c = 0; c < w; ++c) {
            float numU, numV, value = 0.0f;
            solver.Solve(call.args[0], c, p, true, &numU, &numV);
            if (std::fabs(denU) > least) value += numU / denU;
            if (std::fabs(denV) > least) value += numV / denV;
            call.result.At(c, p) = value;
        }
    });
}

// area(P) = length(Du(P)·du ^ Dv(P)·dv): the area of the micro-facet at each point.
void AreaKernel(const BuiltinCall& call) {
    const Stencil su = UStencil(call), sv = VStencil(call);
    ForEachPoint(call, [&](int p) {
        V3 a = DeltaTriple(su, call.args[0], p), b = DeltaTriple(sv, call.args[0], p);
        call.result.At(0, p) = a.cross(b).length();
    });
}

// calculatenormal(P): the unit normal Du(P) ^ Dv(P), turned to the side of Ng (or of N when
// the shader has no Ng), so that a bump shader's new N faces as the surface's did whatever the
// handedness of the parametrisation. Where Du(P) and Dv(P) are not determined (no parametric
// steps), the cross product of the two differences stands in for them.
void CalculateNormalKernel(const BuiltinCall& call) {
    const PartialSolver solver(call);
    const Stencil su = UStencil(call), sv = VStencil(call);
    FloatArg side = Global(call, "Ng");
    if (!side.data) side = Global(call, "N");
    ForEachPoint(call, [&](int p) {
        V3 alongU, alongV;
        for (int c = 0; c < 3; ++c) solver.Solve(call.args[0], c, p, true, &alongU[c], &alongV[c]);
        V3 n = Normalized(alongU.cross(alongV));
        if (n.length2() == 0.0f)
            n = Normalized(
                DeltaTriple(su, call.args[0], p).cross(DeltaTriple(sv, call.args[0], p)));
        if (side.data && Dot(n, Triple(side, p)) < 0.0f) n = -n;
        SetTriple(call.result, p, n);
    });
}

}  // namespace

void AddDerivativeBuiltins(BuiltinList* list) {
    const unsigned derivatives = kNeedsDerivatives | kReadsGlobals;
    for (const char* t : {"f", "c", "p", "v", "n"}) {
        const char* result = t[0] == 'p' ? "v" : t;  // the derivative of a point is a vector
        list->Add("Du", result, t, PartialKernel<true>, derivatives);
        list->Add("Dv", result, t, PartialKernel<false>, derivatives);
        list->Add("Deriv", result, std::string(t) + "f", DerivKernel, kNeedsDerivatives);
    }
    list->Add("area", "f", "p", AreaKernel, kNeedsDerivatives | kVaryingResult);
    list->Add("calculatenormal", "n", "p", CalculateNormalKernel, derivatives | kVaryingResult);
}

}  // namespace gonio::sl::builtins
