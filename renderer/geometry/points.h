#pragma once
// RISpec §5.5 Points: one disc (or sphere) per "P", of diameter "width" (varying, one per
// point) or "constantwidth", 1 when neither is given.

#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

// PointSet::vars keeps every other variable as given: varying and vertex one value per point,
// constant and uniform one value (the set is a single RIB face).
GeometryResult<PointSet> MakePoints(const PrimVarSet& vars);

}  // namespace gonio
