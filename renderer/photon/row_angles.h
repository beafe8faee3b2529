#pragma once
// The polar angles that every photon-map row stores (θ from cos θ, φ from a direction's x, y),
// as inline polynomials: glibc's acosf and atan2f took a tenth of the tracer's time on brushed
// metal, and these made it about 6% faster (bench/RESULTS.md, BRDFLight). Both stay within
// 5e-7 rad of the exact angle (a few float ulps, as libm's own float functions within 2.5e-7;
// tests/photon/row_angles_test.cpp), far below anything a splat of 0.1 rad or more resolves.

#include <algorithm>
#include <cmath>

#include "base/math.h"

namespace gonio {

// arccos(c) for c in [−1, 1] (clamped). Abramowitz & Stegun 4.4.46: for 0 ≤ x ≤ 1,
// arccos x = √(1 − x)·(a0 + a1·x + … + a7·x⁷) within 2e-8; arccos(−x) = π − arccos x.
inline float PolarAngle(float c) {
    const float x = std::min(std::fabs(c), 1.0f);
    float p = -0.0012624911f;
    p = p * x + 0.0066700901f;
    p = p * x - 0.0170881256f;
    p = p * x + 0.0308918810f;
    p = p * x - 0.0501743046f;
    p = p * x + 0.0889789874f;
    p = p * x - 0.2145988016f;
    p = p * x + 1.5707963050f;
    const float angle = std::sqrt(1 - x) * p;
    return c < 0 ? kPiF - angle : angle;
}

// atan2(y, x) in (−π, π]. The ratio of the smaller to the larger of |x|, |y| is brought into
// [0, tan π/8] (past it, by atan a = π/4 + atan((a − 1)/(a + 1)), one division either way) and
// atan there is the polynomial of Cephes' atanf (S. L. Moshier), relative error below 2e-7.
inline float Azimuth(float y, float x) {
    constexpr float kTanPi8 = 0.41421356237f;
    const float ax = std::fabs(x), ay = std::fabs(y);
    const float big = std::max(ax, ay), small = std::min(ax, ay);
    const bool reduced = small > kTanPi8 * big;
    const float num = reduced ? small - big : small, den = reduced ? small + big : big;
    const float a = den > 0 ? num / den : 0.0f;
    const float z = a * a;
    float p = 8.05374449538e-2f;
    p = p * z - 1.38776856032e-1f;
    p = p * z + 1.99777106478e-1f;
    p = p * z - 3.33329491539e-1f;
    float angle = (reduced ? kPiF / 4 : 0.0f) + (p * z * a + a);  // atan(small / big)
    if (ay > ax) angle = kPiF / 2 - angle;
    if (x < 0) angle = kPiF - angle;
    return std::copysign(angle, y);
}

}  // namespace gonio
