#pragma once
// The Catmull-Rom spline of the thesis's SPD editor (§6.2.2), as a function of wavelength.
//
// Thesis §6.2.2 prints the uniform basis matrix with the third row `-1 0 1 1`; that row must be
// `-1 0 1 0` (the matrix then interpolates P_{i-2} at t = 0 and P_{i-1} at t = 1, and its rows
// sum to the cubic's derivative conditions). Over unevenly spaced knots the uniform form would
// bend the curve in wavelength, so we use a cubic Hermite with Catmull-Rom tangents
// m_i = (p_{i+1} - p_{i-1}) / (t_{i+1} - t_{i-1}); on evenly spaced knots the two agree exactly.

#include <vector>

namespace gonio::spectral {

// The thesis's uniform segment, matrix corrected: Q(s) for s in [0, 1] between p1 and p2.
double UniformCatmullRom(double p0, double p1, double p2, double p3, double s);

// The Hermite form at x over strictly increasing knots `t` with values `p` (at least 2 knots).
// `before` and `after` are the phantom control points' values; a phantom sits one neighbouring
// spacing beyond its end knot (mirrored), so a phantom equal to its end knot gives the uniform
// spline's end condition. x must lie in [t.front(), t.back()]. Not clamped.
double CatmullRomHermite(const std::vector<double>& t, const std::vector<double>& p, double before,
                         double after, double x);

}  // namespace gonio::spectral
