#pragma once
// Real roots of the low-degree polynomials that ray-quadric intersection produces, in double
// precision. Internal to the quadrics (quadric_*.cpp); nothing else should need it.

#include <cmath>
#include <utility>

namespace gonio::quadric {

// The real roots of c2·t² + c1·t + c0 = 0 in ascending order; returns how many (0, 1 or 2).
// Uses the cancellation-free form q = -(c1 + sign(c1)·√disc)/2, roots q/c2 and c0/q, and
// degrades to the linear root when c2 is zero. Inline: every quadric ray test calls it.
inline int SolveQuadratic(double c2, double c1, double c0, double roots[2]) {
    if (c2 == 0) {
        if (c1 == 0) return 0;
        roots[0] = -c0 / c1;
        return std::isfinite(roots[0]) ? 1 : 0;
    }
    const double disc = c1 * c1 - 4 * c2 * c0;
    if (disc < 0) return 0;
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    if (q == 0) {  // c1 = 0 and c0 = 0: a double root at zero
        roots[0] = 0;
        return 1;
    }
    double r0 = q / c2, r1 = c0 / q;
    if (r0 > r1) std::swap(r0, r1);
    int n = 0;
    if (std::isfinite(r0)) roots[n++] = r0;
    if (std::isfinite(r1)) roots[n++] = r1;
    return n;
}

// The real roots of Σ c[i]·t^i (degree 1 to 4) in the open interval (lo, hi), ascending;
// returns how many. The interval must be finite.
//
// Method (instead of Ferrari's closed form, whose resolvent cubic loses most digits for rays
// that start far from a torus): the roots of the derivative, found recursively down to a
// closed-form quadratic, split (lo, hi) into intervals on which the polynomial is monotonic;
// each interval whose ends differ in sign holds exactly one root, found by Newton's method kept
// inside the bracket (bisection whenever a Newton step would leave it). Every root is thus
// converged to full double precision. A root of even multiplicity (a ray exactly tangent to the
// surface) is reported only when the polynomial is exactly zero at the critical point.
int PolynomialRootsIn(const double* c, int degree, double lo, double hi, double* roots);

// Σ c[i]·t^i by Horner's rule.
double EvaluatePolynomial(const double* c, int degree, double t);

}  // namespace gonio::quadric
