#pragma once
// RISpec §5.1 polygons as triangle meshes. Every face is triangulated by ear clipping on its
// best-fit plane (the Newell normal of its outline); holes are first bridged into the outline.
// Triangles keep the winding of the face: cross(p1 − p0, p2 − p0) points along the Newell
// normal of the outline as the RIB gives it.
//
// Primitive variables: constant -> Constant, uniform -> PerFace, varying and vertex ->
// PerVertex (one value per "P"), facevarying -> PerCorner. "N" becomes TriangleMesh::normals
// (vertex, varying, constant) or cornerNormals (facevarying, uniform). Faces whose outline has
// fewer than three vertices or no area produce no triangles but keep their face number.

#include <array>
#include <cstdint>
#include <vector>

#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

GeometryResult<TriangleMesh> MakePolygon(const PrimVarSet& vars);
GeometryResult<TriangleMesh> MakeGeneralPolygon(const std::vector<int>& nverts,
                                                const PrimVarSet& vars);
GeometryResult<TriangleMesh> MakePointsPolygons(const std::vector<int>& nverts,
                                                const std::vector<int>& vertices,
                                                const PrimVarSet& vars);
GeometryResult<TriangleMesh> MakePointsGeneralPolygons(const std::vector<int>& nloops,
                                                       const std::vector<int>& nverts,
                                                       const std::vector<int>& vertices,
                                                       const PrimVarSet& vars);

// The triangulation itself: `points` holds the loops one after another (the first the outline,
// the others holes), `loopSizes` their lengths. Returns triangles as indices into `points`,
// wound like the outline. Holes of either orientation are accepted.
std::vector<std::array<uint32_t, 3>> TriangulateLoops(const std::vector<V3f>& points,
                                                      const std::vector<int>& loopSizes);

// Newell's normal of a closed loop: its direction follows the loop by the right-hand rule and
// its length is twice the area of the loop's projection on the plane it defines.
V3f NewellNormal(const std::vector<V3f>& loop);

}  // namespace gonio
