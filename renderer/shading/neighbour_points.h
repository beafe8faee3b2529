#pragma once
// The neighbour points of a ray hit, for derivatives in a ray tracer (Pixie's three points per
// ray hit): the points that the rays one pixel away (NeighbourRays) meet on the same surface.
// A shader that takes derivatives runs on a hit and its two neighbours together, and Du, area,
// calculatenormal and texture footprints difference across them.

#include <Imath/ImathVec.h>

#include "renderer/raytrace/ray_scene.h"
#include "renderer/raytrace/surface_point.h"

namespace gonio {

// The point where the ray (org, dir) meets the surface of `centre`, which the ray
// (centreOrg, centreDir) hit. Where the ray meets another surface or nothing (at a silhouette),
// the ray mirrored about the centre ray is tried, as a backward difference; where that fails
// too, the point on the tangent plane of `centre`, with centre's values and its (u, v) moved
// along. Writes the point and its incident vector I (from the ray's origin); returns how many
// rays it traced (1 or 2).
int FindNeighbourPoint(const RayScene& scene, const SurfacePoint& centre,
                       const Imath::V3f& centreOrg, const Imath::V3f& centreDir,
                       const Imath::V3f& org, const Imath::V3f& dir, float tnear, float time,
                       SurfacePoint* out, Imath::V3f* incident);

// The change (Δu, Δv) that moves `sp` by dP over its tangent plane: the least-squares solution
// of dPdu·Δu + dPdv·Δv = dP; (0, 0) where dPdu and dPdv do not span a plane.
Imath::V2f ParametricStep(const SurfacePoint& sp, const Imath::V3f& dP);

}  // namespace gonio
