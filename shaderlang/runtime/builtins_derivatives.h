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

}  // namespace gonio::sl::builtins
