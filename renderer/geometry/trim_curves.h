#pragma once
// RISpec 3.2 §5.2 TrimCurve: loops of rational B-spline curves in the (u,v) parameter space of
// the NuPatches that follow. Each curve is evaluated into a polyline (32 segments per knot span
// of order >= 3, one per span of a linear curve); a parameter point is kept when a ray from it
// crosses the loops an odd number of times (RISpec's odd winding rule: the inside is rendered,
// so a square patch trimmed by a circle renders a disc).

#include <Imath/ImathVec.h>

#include <vector>

#include "renderer/geometry/geometry_result.h"

namespace gonio {

class TrimRegion {
  public:
    TrimRegion() = default;  // no loops: contains nothing
    explicit TrimRegion(std::vector<std::vector<Imath::V2f>> loops);

    // Whether the parameter point (u, v) lies inside the trim loops (odd crossing count).
    bool Contains(const Imath::V2f& uv) const;
    const std::vector<std::vector<Imath::V2f>>& Loops() const { return loops_; }

  private:
    std::vector<std::vector<Imath::V2f>> loops_;  // closed polylines (last point joins the first)
    Imath::V2f lo_{0, 0}, hi_{0, 0};              // their bounding box
};

// Evaluates TrimCurve's arguments (RISpec §5.2: ncurves per loop; then per curve its order, knots,
// [min, max] range, control point count n and homogeneous control points (u, v, w)).
GeometryResult<TrimRegion> MakeTrimRegion(
    const std::vector<int>& ncurves, const std::vector<int>& order, const std::vector<float>& knot,
    const std::vector<float>& min, const std::vector<float>& max, const std::vector<int>& n,
    const std::vector<float>& u, const std::vector<float>& v, const std::vector<float>& w);

}  // namespace gonio
