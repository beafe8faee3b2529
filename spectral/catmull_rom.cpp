#include "spectral/catmull_rom.h"

#include <algorithm>

namespace gonio::spectral {

double UniformCatmullRom(double p0, double p1, double p2, double p3, double s) {
    // Thesis §6.2.2: Q(s) = 1/2 (s³, s², s, 1) M (P_{i-3}, P_{i-2}, P_{i-1}, P_i)ᵀ with
    // M = [-1 3 -3 1; 2 -5 4 -1; -1 0 1 0; 0 2 0 0] (third row corrected).
    const double a = -p0 + 3 * p1 - 3 * p2 + p3;
    const double b = 2 * p0 - 5 * p1 + 4 * p2 - p3;
    const double c = -p0 + p2;
    const double d = 2 * p1;
    return 0.5 * (((a * s + b) * s + c) * s + d);
}

double CatmullRomHermite(const std::vector<double>& t, const std::vector<double>& p, double before,
                         double after, double x) {
    const size_t n = t.size();
    size_t i = std::upper_bound(t.begin(), t.end(), x) - t.begin();
    i = std::clamp<size_t>(i, 1, n - 1) - 1;  // segment [t[i], t[i+1]]
    auto knot = [&](long j) {
        if (j < 0) return t[0] - (t[1] - t[0]);
        if (j >= long(n)) return t[n - 1] + (t[n - 1] - t[n - 2]);
        return t[j];
    };
    auto value = [&](long j) {
        if (j < 0) return before;
        if (j >= long(n)) return after;
        return p[j];
    };
    auto tangent = [&](long j) {
        return (value(j + 1) - value(j - 1)) / (knot(j + 1) - knot(j - 1));
    };
    const double h = t[i + 1] - t[i];
    const double u = (x - t[i]) / h;
    const double u2 = u * u, u3 = u2 * u;
    // Cubic Hermite basis (e.g. Foley et al., Computer Graphics, §11.2.1).
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
    const double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return h00 * p[i] + h10 * h * tangent(i) + h01 * p[i + 1] + h11 * h * tangent(i + 1);
}

}  // namespace gonio::spectral
