#pragma once
// RISpec §5.2 Patch and PatchMesh, bilinear or bicubic in the current Basis, tessellated into
// triangle meshes (see tensor_grid.h for the grid and how variables are evaluated).
//
// Density: a bicubic patch becomes a 16×16 grid of quads (512 triangles); a whole primitive is
// held to about 2^18 grid vertices by lowering that to as little as 4×4 per patch. A bilinear
// patch stays two triangles when it is a parallelogram and carries no varying or vertex
// variables besides its position (the two triangles are then exactly the bilinear patch);
// otherwise it gets 8×8 quads. TessellationRates changes these numbers.
//
// Parameters: (u, v) run from 0 to 1 over the whole mesh (RISpec: "A patch mesh is
// parameterized by a (u,v) which goes from 0 to 1 for the entire mesh"), stored per vertex in
// TriangleMesh::uv. faceOfTriangle is the patch number, u fastest. Varying and facevarying
// variables are blended bilinearly between patch corners; vertex variables use the basis.
//
// Positions: "P", "Pw" (rational: divided by w after interpolation) or "Pz", a height field
// whose control point (i, j) lies at x = i / (nu − 1), y = j / (nv − 1) (nonperiodic only).

#include <string>

#include "renderer/geometry/basis.h"
#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"
#include "renderer/geometry/tensor_grid.h"

namespace gonio {

// type: "bilinear" (4 points, order (0,0) (1,0) (0,1) (1,1)) or "bicubic" (16 points, u fastest).
GeometryResult<TriangleMesh> MakePatch(const std::string& type, const PatchBasis& ubasis,
                                       const PatchBasis& vbasis, const PrimVarSet& vars,
                                       const TessellationRates& rates = {});

// uwrap and vwrap: "periodic" or "nonperiodic".
GeometryResult<TriangleMesh> MakePatchMesh(const std::string& type, int nu,
                                           const std::string& uwrap, int nv,
                                           const std::string& vwrap, const PatchBasis& ubasis,
                                           const PatchBasis& vbasis, const PrimVarSet& vars,
                                           const TessellationRates& rates = {});

}  // namespace gonio
