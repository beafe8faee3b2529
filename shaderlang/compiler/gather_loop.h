#pragma once
// gather(category, P, dir, angle, samples, ...) { hit } else { miss } (PRMan's ray-traced
// loop) as the parser's tree of plain statements over four built-ins
// (runtime/builtins_gather.cpp), so that the checker, code generator and optimizer need
// nothing new:
//
//     gather(category, P, dir, angle, samples, options..., "__outputs", "a,b", "__id", k);
//     while (__gather_next(k)) {
//         ray outputs = __gather_value(k, "ray:...");      // every sample
//         if (__gather_hit(k)) { other outputs = __gather_value(k, "..."); hit }
//         else miss
//     }
//
// The loop runs over the samples, uniformly: sample j's body runs for the points whose ray j
// hit something, its else for the others; break and continue act on it as on any loop.

#include "shaderlang/compiler/parse_state.h"

namespace gonio::sl {

// `call` is the parsed argument list (a Call node); `miss` may be null. Reports malformed
// option lists at their location and returns the statement.
Node* MakeGatherLoop(ParseState* state, const SourceLoc& loc, Node* call, Node* hit, Node* miss);

}  // namespace gonio::sl
