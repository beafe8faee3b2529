#pragma once
// RISpec §5.2 NuPatch: a tensor-product non-uniform rational B-spline surface of any order,
// tessellated like a patch mesh (tensor_grid.h) over [umin, umax] × [vmin, vmax].
//
// Density: 16 × 16 quads per non-empty knot span pair for order ≥ 3 directions, one step per
// span in a linear (order 2) direction, held to the TessellationRates vertex budget.
// Parameters: TriangleMesh::uv holds the knot parameters (u, v) themselves (RISpec: NURBS are
// not parameterised over the unit square). Uniform variables have one value per knot span
// ((nu − uorder + 1)·(nv − vorder + 1), empty spans included) and varying ones one per span
// corner ((nu − uorder + 2)·(nv − vorder + 2)); vertex variables use the B-spline basis
// without the weights of "Pw". TrimCurve is applied at hit time (SceneShape::trim, set by the
// scene builder): the tessellation itself is the whole patch.

#include <vector>

#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"
#include "renderer/geometry/tensor_grid.h"

namespace gonio {

GeometryResult<TriangleMesh> MakeNuPatch(int nu, int uorder, const std::vector<float>& uknot,
                                         float umin, float umax, int nv, int vorder,
                                         const std::vector<float>& vknot, float vmin, float vmax,
                                         const PrimVarSet& vars,
                                         const TessellationRates& rates = {});

// The order nonzero B-spline basis functions N[span−order+1 .. span] at u (The NURBS Book,
// algorithm A2.2); knots[span] <= u <= knots[span+1] must hold with a non-empty span.
std::vector<double> BSplineBasisFunctions(const std::vector<float>& knots, int span, int order,
                                          double u);

}  // namespace gonio
