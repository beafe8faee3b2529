#pragma once
// The passes after the parser (type checking, optimisation, code generation) recurse over the
// syntax tree, a stack frame or more a level. A tree deeper than kMaxTreeDepth (a sum of 20,000
// terms is a tree 20,000 deep) would overflow the stack, so it is refused before them, at the
// place it gets too deep. No shader written by hand comes near.

#include "base/diagnostics.h"
#include "shaderlang/compiler/ast.h"

namespace gonio::sl {

constexpr int kMaxTreeDepth = 500;

// False after reporting the first node nested deeper than kMaxTreeDepth.
bool CheckTreeDepth(const SyntaxTree& tree, Diagnostics& diagnostics);

}  // namespace gonio::sl
