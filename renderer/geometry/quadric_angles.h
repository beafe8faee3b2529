#pragma once
// Angles for the quadrics' hit tests and parameters, in double precision: a range of directions
// tested without trigonometry, and an atan2 without the C library's slow paths. Internal to the
// quadrics (quadric_*.cpp).

#include <cmath>
#include <limits>

#include "base/math.h"

namespace gonio::quadric {

inline double Radians(double degrees) { return degrees * (kPi / 180); }
// +1 for zero, so that a degenerate factor never zeroes a normal.
inline double SignOf(double x) { return x < 0 ? -1.0 : 1.0; }

// The directions in a plane at the angles [start, start + span] (span signed; the default, and a
// span of a full turn or more, take every direction). Contains tests a direction against the
// range's end directions with a dot and a cross product instead of finding its angle (atan2):
// deciding a hit on a partial sweep needs no trigonometry.
class AngleRange {
  public:
    AngleRange() = default;
    AngleRange(double start, double span) {
        if (!(std::fabs(span) < 2 * kPi)) return;  // every direction
        kind_ = std::fabs(span) <= kPi ? Kind::kAtMostHalfTurn : Kind::kBeyondHalfTurn;
        cosStart_ = std::cos(start);
        sinStart_ = std::sin(start);
        sense_ = SignOf(span);
        cosSpan_ = std::cos(std::fabs(span));
        sinSpan_ = std::sin(std::fabs(span));
    }

    // Whether the direction of (x, y) lies in the range, its end directions included. Rounding
    // may decide a direction on an end either way; (0, 0) counts as inside.
    bool Contains(double x, double y) const {
        if (kind_ == Kind::kAll) return true;
        // The direction in the frame of the start direction, turned in the range's sense: its
        // angle must then lie in [0, |span|].
        const double qx = cosStart_ * x + sinStart_ * y;
        const double qy = sense_ * (cosStart_ * y - sinStart_ * x);
        // cross(end, q) > 0: q lies less than half a turn beyond the end direction.
        const double pastEnd = cosSpan_ * qy - sinSpan_ * qx;
        // Up to half a turn: q lies in the upper half plane and not beyond the end. Beyond
        // half a turn: q lies outside the excluded wedge (end, start), which is under half a
        // turn wide.
        if (kind_ == Kind::kAtMostHalfTurn) return qy >= 0 && pastEnd <= 0;
        return !(qy < 0 && pastEnd > 0);
    }

  private:
    enum class Kind { kAll, kAtMostHalfTurn, kBeyondHalfTurn };
    Kind kind_ = Kind::kAll;
    double cosStart_ = 1, sinStart_ = 0, sense_ = 1, cosSpan_ = 1, sinSpan_ = 0;
};

// std::atan2(y, x) to within two units in the last place, for the (u, v) of every shaded hit,
// at half the library's time on coherent rays. S. L. Moshier's Cephes atan: the ratio of the
// smaller to the larger of |x|, |y| is brought into [0, 0.66] (beyond 0.66 through atan t = π/4
// + atan((t − 1)/(t + 1)), formed from |x| and |y| without rounding t first), where atan r = r +
// r³·P(r²)/Q(r²) with Cephes's degree 4/5 minimax rational; the octant and the quadrant follow
// from the swap and the signs, with the rounding error of π/2 added back. Selects rather than
// branches, whose directions rays at random angles cannot predict. Zeros, infinities and NaNs
// go to std::atan2.
inline double Atan2(double y, double x) {
    const double ax = std::fabs(x), ay = std::fabs(y);
    const bool swapped = ay > ax;
    const double small = swapped ? ax : ay, large = swapped ? ay : ax;
    if (!(small >= 0 && large > 0 && large <= std::numeric_limits<double>::max()))
        return std::atan2(y, x);
    constexpr double kQuarterPi = kPi / 4, kHalfPi = kPi / 2;
    constexpr double kHalfPiError = 6.123233995736765886130e-17;  // π/2 − kHalfPi
    const bool reduced = small > 0.66 * large;
    // small − large is exact (Sterbenz).
    const double r = (reduced ? small - large : small) / (reduced ? small + large : large);
    const double z = r * r;
    const double p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z -
                       7.500855792314704667340e1) *
                          z -
                      1.228866684490136173410e2) *
                         z -
                     6.485021904942025371773e1;
    const double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z +
                       4.328810604912902668951e2) *
                          z +
                      4.853903996359136964868e2) *
                         z +
                     1.945506571482613964425e2;
    // atan(small / large), in [0, π/4].
    double angle =
        (reduced ? kQuarterPi : 0.0) + (r + r * z * p / q + (reduced ? 0.5 * kHalfPiError : 0.0));
    const double fromAxis = (kHalfPi - angle) + kHalfPiError;
    angle = swapped ? fromAxis : angle;
    const double fromBack = (2 * kHalfPi - angle) + 2 * kHalfPiError;
    angle = x < 0 ? fromBack : angle;
    return std::copysign(angle, y);
}

}  // namespace gonio::quadric
