#include "renderer/geometry/trim_curves.h"

#include <algorithm>
#include <string>

#include "renderer/geometry/nurbs.h"

namespace gonio {
namespace {

using Imath::V2f;

// Polyline segments per non-empty knot span of a curved trim curve: a circle made of four
// rational quadratic spans loses (2π/128)²/6 ≈ 0.04% of its area to the inscribed polygon.
constexpr int kSegmentsPerSpan = 32;

struct CurveArgs {
    int order, count;
    const float* knots;  // count + order values
    float min, max;
    const float *u, *v, *w;  // count homogeneous control points
};

// The point of the rational curve at t in span `span` (RISpec: (u, v, w) homogeneous).
V2f CurvePoint(const CurveArgs& c, const std::vector<float>& knots, int span, double t) {
    const std::vector<double> basis = BSplineBasisFunctions(knots, span, c.order, t);
    double su = 0, sv = 0, sw = 0;
    for (int k = 0; k < c.order; ++k) {
        const int j = span - c.order + 1 + k;
        su += basis[k] * c.u[j], sv += basis[k] * c.v[j], sw += basis[k] * c.w[j];
    }
    return V2f(static_cast<float>(su / sw), static_cast<float>(sv / sw));
}

void AppendPolyline(const CurveArgs& c, std::vector<V2f>* loop) {
    const std::vector<float> knots(c.knots, c.knots + c.count + c.order);
    const float lo = std::max(c.min, knots[c.order - 1]), hi = std::min(c.max, knots[c.count]);
    for (int span = c.order - 1; span < c.count; ++span) {
        const double a = std::max(lo, knots[span]), b = std::min(hi, knots[span + 1]);
        if (!(knots[span] < knots[span + 1]) || !(a < b)) continue;
        const int steps = c.order == 2 ? 1 : kSegmentsPerSpan;
        if (loop->empty()) loop->push_back(CurvePoint(c, knots, span, a));
        for (int k = 1; k <= steps; ++k)
            loop->push_back(CurvePoint(c, knots, span, k == steps ? b : a + (b - a) * k / steps));
    }
}

std::string CurveError(std::size_t curve, const std::string& what) {
    return "TrimCurve: curve " + std::to_string(curve) + " " + what;
}

}  // namespace

TrimRegion::TrimRegion(std::vector<std::vector<V2f>> loops) : loops_(std::move(loops)) {
    lo_ = V2f(1e30f), hi_ = V2f(-1e30f);
    for (const auto& loop : loops_)
        for (const V2f& p : loop)
            lo_ = V2f(std::min(lo_.x, p.x), std::min(lo_.y, p.y)),
            hi_ = V2f(std::max(hi_.x, p.x), std::max(hi_.y, p.y));
}

bool TrimRegion::Contains(const V2f& uv) const {
    if (uv.x < lo_.x || uv.x > hi_.x || uv.y < lo_.y || uv.y > hi_.y) return false;
    // Crossings of the ray from uv towards +u (half-open in v, so a vertex counts once).
    bool inside = false;
    for (const auto& loop : loops_) {
        for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
            const V2f &a = loop[i], &b = loop[j];
            if ((a.y > uv.y) != (b.y > uv.y) &&
                uv.x < a.x + (uv.y - a.y) / (b.y - a.y) * (b.x - a.x))
                inside = !inside;
        }
    }
    return inside;
}

GeometryResult<TrimRegion> MakeTrimRegion(
    const std::vector<int>& ncurves, const std::vector<int>& order, const std::vector<float>& knot,
    const std::vector<float>& min, const std::vector<float>& max, const std::vector<int>& n,
    const std::vector<float>& u, const std::vector<float>& v, const std::vector<float>& w) {
    using Result = GeometryResult<TrimRegion>;
    std::size_t curves = 0;
    for (int c : ncurves) {
        if (c < 1) return Result::Error("TrimCurve: every loop needs at least one curve");
        curves += static_cast<std::size_t>(c);
    }
    if (order.size() != curves || n.size() != curves || min.size() != curves ||
        max.size() != curves)
        return Result::Error("TrimCurve: order, min, max and n need one value per curve (" +
                             std::to_string(curves) + ")");
    std::size_t knots = 0, points = 0;
    for (std::size_t i = 0; i < curves; ++i) {
        if (order[i] < 2) return Result::Error(CurveError(i, "has an order below 2"));
        if (n[i] < order[i]) return Result::Error(CurveError(i, "has fewer points than its order"));
        knots += static_cast<std::size_t>(n[i] + order[i]);
        points += static_cast<std::size_t>(n[i]);
    }
    if (knot.size() != knots)
        return Result::Error("TrimCurve: knot needs " + std::to_string(knots) + " values, got " +
                             std::to_string(knot.size()));
    if (u.size() != points || v.size() != points || w.size() != points)
        return Result::Error("TrimCurve: u, v and w need " + std::to_string(points) + " values");
    std::vector<std::vector<V2f>> loops;
    std::size_t curve = 0, k = 0, p = 0;
    for (int count : ncurves) {
        std::vector<V2f> loop;
        for (int c = 0; c < count; ++c, ++curve) {
            const CurveArgs args{order[curve], n[curve], &knot[k], min[curve],
                                 max[curve],   &u[p],    &v[p],    &w[p]};
            for (int i = 1; i < args.count + args.order; ++i)
                if (args.knots[i] < args.knots[i - 1])
                    return Result::Error(CurveError(curve, "has decreasing knots"));
            for (int i = 0; i < args.count; ++i)
                if (!(args.w[i] > 0)) return Result::Error(CurveError(curve, "has a weight <= 0"));
            AppendPolyline(args, &loop);
            k += static_cast<std::size_t>(args.count + args.order);
            p += static_cast<std::size_t>(args.count);
        }
        if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    return TrimRegion(std::move(loops));
}

}  // namespace gonio
