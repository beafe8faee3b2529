#include "renderer/geometry/nurbs.h"

#include <algorithm>
#include <string>

#include "renderer/geometry/primvar_eval.h"

namespace gonio {

std::vector<double> BSplineBasisFunctions(const std::vector<float>& knots, int span, int order,
                                          double u) {
    const int p = order - 1;
    std::vector<double> n(order, 0.0), left(order, 0.0), right(order, 0.0);
    n[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double temp = n[r] / (right[r + 1] + left[j - r]);
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    return n;
}

namespace {

struct NurbsDirection {
    int count, order;
    const std::vector<float>& knots;
    float min, max;
    const char* name;

    int FirstSpan() const { return order - 1; }
    int SpanCount() const { return count - order + 1; }  // uniform values along the direction
    int NonEmptySpansInRange() const {
        int spans = 0;
        for (int i = FirstSpan(); i < count; ++i)
            if (knots[i] < knots[i + 1] && knots[i + 1] > min && knots[i] < max) ++spans;
        return spans;
    }
};

std::optional<std::string> Check(NurbsDirection& d) {
    const std::string n = d.name;
    if (d.order < 2) return n + "order must be at least 2, got " + std::to_string(d.order);
    if (d.count < d.order)
        return "n" + n + " = " + std::to_string(d.count) + " is less than the " + n + "order " +
               std::to_string(d.order);
    if (d.knots.size() != static_cast<size_t>(d.count + d.order))
        return n + "knot needs n" + n + " + " + n + "order = " + std::to_string(d.count + d.order) +
               " values, got " + std::to_string(d.knots.size());
    for (size_t i = 1; i < d.knots.size(); ++i)
        if (d.knots[i] < d.knots[i - 1])
            return n + "knot must not decrease, but value " + std::to_string(i) + " (" +
                   std::to_string(d.knots[i]) + ") is less than the one before";
    // RISpec allows a range wider than the knot vector defines; clamp it to the valid part.
    d.min = std::max(d.min, d.knots[d.FirstSpan()]);
    d.max = std::min(d.max, d.knots[d.count]);
    if (!(d.min < d.max))
        return "the " + n + " range [" + n + "min, " + n + "max] holds no part of the surface";
    return std::nullopt;
}

GridAxis MakeAxis(const NurbsDirection& d, int steps) {
    GridAxis axis;
    axis.controlCount = d.count;
    axis.cellCount = d.SpanCount();
    axis.varyingCount = d.SpanCount() + 1;
    auto addSample = [&](int span, double u) {
        GridAxis::Sample s;
        s.param = static_cast<float>(u);
        s.firstControl = span - (d.order - 1);
        for (double w : BSplineBasisFunctions(d.knots, span, d.order, u))
            s.weights.push_back(static_cast<float>(w));
        s.varyingCell = span - d.FirstSpan();
        s.varyingT = static_cast<float>((u - d.knots[span]) / (d.knots[span + 1] - d.knots[span]));
        axis.samples.push_back(std::move(s));
    };
    for (int span = d.FirstSpan(); span < d.count; ++span) {
        const double a = std::max<double>(d.knots[span], d.min);
        const double b = std::min<double>(d.knots[span + 1], d.max);
        if (!(d.knots[span] < d.knots[span + 1]) || !(a < b)) continue;
        if (axis.samples.empty()) addSample(span, a);
        const int n = d.order == 2 ? 1 : steps;
        for (int k = 1; k <= n; ++k) {
            addSample(span, k == n ? b : a + (b - a) * k / n);
            axis.intervalCell.push_back(span - d.FirstSpan());
        }
    }
    return axis;
}

}  // namespace

GeometryResult<TriangleMesh> MakeNuPatch(int nu, int uorder, const std::vector<float>& uknot,
                                         float umin, float umax, int nv, int vorder,
                                         const std::vector<float>& vknot, float vmin, float vmax,
                                         const PrimVarSet& vars, const TessellationRates& rates) {
    using Result = GeometryResult<TriangleMesh>;
    NurbsDirection u{nu, uorder, uknot, umin, umax, "u"};
    NurbsDirection v{nv, vorder, vknot, vmin, vmax, "v"};
    if (auto bad = Check(u)) return Result::Error(*bad);
    if (auto bad = Check(v)) return Result::Error(*bad);
    const int varying = (u.SpanCount() + 1) * (v.SpanCount() + 1);
    const ClassCounts counts{u.SpanCount() * v.SpanCount(), varying, nu * nv, varying};
    if (auto bad = CheckCounts(vars, counts)) return Result::Error(*bad);
    const std::vector<float> h = ReadHomogeneousPositions(vars);
    if (h.size() != 4 * static_cast<size_t>(nu) * nv)
        return Result::Error("NuPatch needs " + std::to_string(nu * nv) +
                             " positions in \"P\" or \"Pw\"");
    const bool rational = vars.Find("P") == nullptr;

    const long spans = static_cast<long>(u.NonEmptySpansInRange()) * v.NonEmptySpansInRange();
    const int steps = rates.StepsWithinBudget(rates.curvedSteps, spans);
    return TessellateTensorGrid(MakeAxis(u, steps), MakeAxis(v, steps), h, rational, vars);
}

}  // namespace gonio
