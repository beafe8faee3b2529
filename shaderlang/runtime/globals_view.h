#pragma once
// Read and write access to the shading globals of the batch being shaded (P, N, Ng, I, s, t, du,
// dv, Cl, L, ...), for built-in kernels flagged kReadsGlobals (faceforward without Nref reads
// Ng; texture without coordinates reads s and t; calculatenormal reads the neighbours of P).
// The interpreter implements it over its registers, so a kernel sees what the shader wrote.

#include <string>

#include "shaderlang/runtime/batch.h"

namespace gonio::sl {

struct LightResult;  // shading_context.h

class GlobalsView {
  public:
    virtual ~GlobalsView() = default;
    // The global named `name` as the shader sees it now; data == nullptr when the shader type
    // has no such global (e.g. "Ps" in a surface shader).
    virtual FloatArg Get(const std::string& name) const = 0;
    // Inside an illuminance loop, the light its body runs for (lightsource() reads it); else
    // nullptr.
    virtual const LightResult* CurrentLight() const { return nullptr; }
};

}  // namespace gonio::sl
