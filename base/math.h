#pragma once
// The mathematical constants every stage uses, defined once (pbrt's util/math.h in spirit).
// Double precision; float code converts with float(kPi), which rounds to the nearest float.

namespace gonio {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
constexpr double kHalfPi = kPi / 2;
constexpr double kInvPi = 1 / kPi;
constexpr double kDegree = kPi / 180;  // one degree in radians

// The same, rounded to float, for single-precision kernels.
constexpr float kPiF = float(kPi);
constexpr float kTwoPiF = float(kTwoPi);
constexpr float kHalfPiF = float(kHalfPi);
constexpr float kInvPiF = float(kInvPi);

}  // namespace gonio
