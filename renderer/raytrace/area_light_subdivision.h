#pragma once
// A subdivision surface as triangles on its limit surface, for sampling area lights: the
// Catmull-Clark cage refined three times (Catmull & Clark 1978; boundary edges by the cubic
// B-spline curve rules when "interpolateboundary" is set), every refined vertex then moved to
// its limit position (Halstead, Kass & DeRose 1993, eq. 7: (n²v + 4Σeⱼ + Σfⱼ) / (n(n+5))
// inside, (e₀ + 4v + e₁) / 6 on the boundary). Hole faces are left out; without
// "interpolateboundary" so are the faces that touch the boundary, as Embree's no-boundary mode
// renders them. Crease and corner sharpness are not followed: the sampled surface is the
// smooth one there.

#include "renderer/geometry/shape.h"

namespace gonio {

TriangleMesh SubdivisionLimitMesh(const SubdivisionCage& cage);

}  // namespace gonio
