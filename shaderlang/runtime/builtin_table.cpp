// The table of every built-in overload, gathered from the families' registration functions.

#include "shaderlang/runtime/builtin_table.h"

#include "shaderlang/runtime/builtins_util.h"

namespace gonio::sl {

namespace {

builtins::BuiltinList MakeTable() {
    builtins::BuiltinList list;
    builtins::AddMathBuiltins(&list);
    builtins::AddNoiseBuiltins(&list);
    builtins::AddGeometricBuiltins(&list);
    builtins::AddColorBuiltins(&list);
    builtins::AddMatrixBuiltins(&list);
    builtins::AddStringBuiltins(&list);
    builtins::AddLightingBuiltins(&list);
    builtins::AddTextureBuiltins(&list);
    builtins::AddMessageBuiltins(&list);
    builtins::AddDerivativeBuiltins(&list);
    builtins::AddBrdfBuiltins(&list);
    builtins::AddRayBuiltins(&list);
    builtins::AddGatherBuiltins(&list);
    return list;
}

}  // namespace

const std::vector<BuiltinInfo>& BuiltinTable() {
    static const builtins::BuiltinList list = MakeTable();
    return list.rows;
}

}  // namespace gonio::sl
