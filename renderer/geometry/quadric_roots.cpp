#include "renderer/geometry/quadric_roots.h"

#include <algorithm>
#include <cmath>

namespace gonio::quadric {

double EvaluatePolynomial(const double* c, int degree, double t) {
    double p = c[degree];
    for (int i = degree - 1; i >= 0; --i) p = p * t + c[i];
    return p;
}

namespace {

double EvaluateWithDerivative(const double* c, int degree, double t, double* derivative) {
    double p = c[degree], dp = 0;
    for (int i = degree - 1; i >= 0; --i) {
        dp = dp * t + p;
        p = p * t + c[i];
    }
    *derivative = dp;
    return p;
}

// The single root in [a, b] of a polynomial monotonic there with fa, fb of opposite signs.
double BracketedRoot(const double* c, int degree, double a, double b, double fa) {
    // Keep `neg` where the polynomial is negative and `pos` where it is positive.
    double neg = fa < 0 ? a : b, pos = fa < 0 ? b : a;
    double x = 0.5 * (a + b);
    const double tolerance = 4 * 2.2e-16 * (std::fabs(a) + std::fabs(b));
    for (int iteration = 0; iteration < 200; ++iteration) {
        double df;
        const double f = EvaluateWithDerivative(c, degree, x, &df);
        if (f == 0) return x;
        (f < 0 ? neg : pos) = x;
        double next = df != 0 ? x - f / df : 0.5 * (neg + pos);
        const double lo = std::min(neg, pos), hi = std::max(neg, pos);
        if (!(next > lo && next < hi)) next = 0.5 * (neg + pos);
        if (std::fabs(next - x) <= tolerance || hi - lo <= tolerance) return next;
        x = next;
    }
    return x;
}

}  // namespace

int PolynomialRootsIn(const double* c, int degree, double lo, double hi, double* roots) {
    while (degree > 0 && c[degree] == 0) --degree;
    if (degree <= 0) return 0;
    if (degree <= 2) {
        double all[2];
        const int n = SolveQuadratic(degree == 2 ? c[2] : 0, c[1], c[0], all);
        int kept = 0;
        for (int i = 0; i < n; ++i)
            if (all[i] > lo && all[i] < hi) roots[kept++] = all[i];
        return kept;
    }
    double derivative[4];
    for (int i = 0; i < degree; ++i) derivative[i] = (i + 1) * c[i + 1];
    double ends[5];
    ends[0] = lo;
    const int critical = PolynomialRootsIn(derivative, degree - 1, lo, hi, ends + 1);
    ends[critical + 1] = hi;

    int n = 0;
    double fa = EvaluatePolynomial(c, degree, lo);
    for (int i = 0; i <= critical; ++i) {
        const double a = ends[i], b = ends[i + 1];
        const double fb = EvaluatePolynomial(c, degree, b);
        if (fb == 0 && b < hi) {
            roots[n++] = b;  // exactly zero at a critical point (or at the start of a run)
        } else if (fa != 0 && fb != 0 && (fa < 0) != (fb < 0)) {
            roots[n++] = BracketedRoot(c, degree, a, b, fa);
        }
        fa = fb;
    }
    return n;
}

}  // namespace gonio::quadric
