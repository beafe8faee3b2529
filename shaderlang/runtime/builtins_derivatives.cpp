// Derivative built-ins (RISpec §15.1-15.2): Du, Dv, Deriv, area, calculatenormal, as finite
// differences over the neighbouring points of the batch that the ShadingContext names
// (UNeighbours/VNeighbours). A point with no neighbour along u uses the point whose neighbour it
// is (a backward difference); with neither, the difference is 0. Du and Dv divide by the
// globals du and dv; Deriv, area and calculatenormal need no step size, the steps cancel.

#include "shaderlang/runtime/builtins_derivatives.h"

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

namespace {

V3 DeltaTriple(const Stencil& s, const FloatArg& a, int p) {
    return V3(Delta(s, a, 0, p), Delta(s, a, 1, p), Delta(s, a, 2, p));
}

FloatArg Global(const BuiltinCall& call, const char* name) {
    return call.globals ? call.globals->Get(name) : FloatArg{};
}

// Du(x) / Dv(x): the difference across one grid step divided by the step du (dv).
template <bool AlongU>
void PartialKernel(const BuiltinCall& call) {
    const Stencil s = AlongU ? UStencil(call) : VStencil(call);
    const FloatArg step = Global(call, AlongU ? "du" : "dv");
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        float h = step.data ? step.At(0, p) : 0.0f;
        for (int c = 0; c < w; ++c) {
            call.result.At(c, p) = h != 0.0f ? Delta(s, call.args[0], c, p) / h : 0.0f;
        }
    });
}

// Deriv(num, den) = Du(num)/Du(den) + Dv(num)/Dv(den); each term is 0 where den does not change.
void DerivKernel(const BuiltinCall& call) {
    const Stencil su = UStencil(call), sv = VStencil(call);
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        float du = Delta(su, call.args[1], 0, p), dv = Delta(sv, call.args[1], 0, p);
        for (int c = 0; c < w; ++c) {
            float value = 0.0f;
            if (du != 0.0f) value += Delta(su, call.args[0], c, p) / du;
            if (dv != 0.0f) value += Delta(sv, call.args[0], c, p) / dv;
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

// calculatenormal(P): the unit normal Du(P) ^ Dv(P), turned to the side of Ng (when the
// shader has Ng), so that a bump shader's new N faces as the surface's did whatever the
// handedness of the parametrisation.
void CalculateNormalKernel(const BuiltinCall& call) {
    const Stencil su = UStencil(call), sv = VStencil(call);
    const FloatArg ng = Global(call, "Ng");
    ForEachPoint(call, [&](int p) {
        V3 n = Normalized(DeltaTriple(su, call.args[0], p).cross(DeltaTriple(sv, call.args[0], p)));
        if (ng.data && Dot(n, Triple(ng, p)) < 0.0f) n = -n;
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
