#pragma once
// The functions that run the opcodes of opcodes.h (internal to the runtime).

#include "shaderlang/runtime/opcodes.h"

namespace gonio::sl {

#define GONIO_SL_DECLARE(name, flags, fn) void fn(ExecState& x, const Instr& in);
GONIO_SL_OPCODES(GONIO_SL_DECLARE)
#undef GONIO_SL_DECLARE

}  // namespace gonio::sl
