#pragma once
// Finite differences over the neighbouring points of a batch (internal to the built-ins): the
// derivative kernels, filterstep and texture footprints all difference the same way.

#include <vector>

#include "shaderlang/runtime/batch.h"

namespace gonio::sl::builtins {

// For each point, the pair (from, to) whose difference value[to] - value[from] spans one grid
// step at that point: the point and its neighbour, or, where it has none, the point whose
// neighbour it is (a backward difference); -1 where neither exists.
struct Stencil {
    std::vector<int> from, to;
};

Stencil MakeStencil(const BuiltinCall& call, const int* neighbours);
Stencil UStencil(const BuiltinCall& call);  // from the context's UNeighbours()
Stencil VStencil(const BuiltinCall& call);

// The change of component c of `a` across one grid step at p (0 for a uniform value).
inline float Delta(const Stencil& s, const FloatArg& a, int c, int p) {
    if (!a.varying || s.from[p] < 0) return 0.0f;
    return a.At(c, s.to[p]) - a.At(c, s.from[p]);
}

// The parametric derivatives ∂x/∂u, ∂x/∂v of a value x from its changes over the two
// stencils. With the context's NeighbourSteps the two changes are solved for them (the
// neighbours may lie in any direction of (u, v)); without, the stencils are steps along u and v
// and the changes are divided by the globals du and dv.
class PartialSolver {
  public:
    explicit PartialSolver(const BuiltinCall& call);
    // Component c of `a` at point p. unitSteps: on a grid without NeighbourSteps, divide by 1
    // instead of du and dv (for ratios of derivatives, where the steps cancel). Where the
    // derivatives are not determined (no neighbours, a step of 0) they are 0.
    void Solve(const FloatArg& a, int c, int p, bool unitSteps, float* alongU, float* alongV) const;

  private:
    const BuiltinCall& call_;
    Stencil u_, v_;
    const float* steps_ = nullptr;
    FloatArg du_, dv_;
};

}  // namespace gonio::sl::builtins
