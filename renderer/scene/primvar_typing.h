#pragma once
// Types RIB parameter lists: primitive variables, shader instance and Option/Attribute values.

#include <string>

#include "base/diagnostics.h"
#include "renderer/geometry/primvar.h"
#include "renderer/rib/declarations.h"
#include "renderer/rib/param_list.h"

namespace gonio {

// Returns false (after reporting every problem) if a token is undeclared or its values have the
// wrong kind. Whether the counts fit the primitive's topology is checked by the geometry code
// (geometry/primvar_eval.h CheckCounts), which knows the topology.
bool TypePrimVars(const ParamList& params, const Declarations& declarations, int colorComponents,
                  Diagnostics& diagnostics, PrimVarSet* out);

// Types parameters outside any primitive (shader instances, Option, Attribute): every value
// count must be a whole number of the declared type's components.
bool TypeParam(const Param& param, const Declarations& declarations, int colorComponents,
               Diagnostics& diagnostics, PrimVar* out);

}  // namespace gonio
