// The polynomial angles of the photon-map rows (photon/row_angles.h) against the exact ones.
#include "renderer/photon/row_angles.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/math.h"

namespace gonio {
namespace {

// A few float ulps of angles up to π; libm's own acosf and atan2f are off by up to 2.5e-7.
constexpr double kTolerance = 5e-7;

TEST(RowAngles, PolarAngleMatchesArccos) {
    for (int i = 0; i <= 200000; ++i) {
        const float c = -1 + 2.0f * float(i) / 200000;
        ASSERT_NEAR(PolarAngle(c), std::acos(double(c)), kTolerance) << "cos θ = " << c;
    }
    // Near the pole the angle itself is small: the error must shrink with it.
    for (int k = 1; k < 24; ++k) {
        const float c = 1 - std::ldexp(1.0f, -k);
        const double exact = std::acos(double(c));
        EXPECT_NEAR(PolarAngle(c) / exact, 1.0, 1e-6) << "cos θ = 1 - 2^-" << k;
    }
    EXPECT_EQ(PolarAngle(1), 0.0f);
    EXPECT_EQ(PolarAngle(1.0000001f), 0.0f);  // rounding past the pole: clamped, not NaN
}

TEST(RowAngles, AzimuthMatchesAtan2AllRound) {
    for (int i = 0; i < 100000; ++i) {
        const double phi = -kPi + 2 * kPi * (i + 0.5) / 100000;
        for (double r : {1e-3, 1.0, 7.5}) {
            const float x = float(r * std::cos(phi)), y = float(r * std::sin(phi));
            ASSERT_NEAR(Azimuth(y, x), std::atan2(double(y), double(x)), kTolerance)
                << "x " << x << " y " << y;
        }
    }
    EXPECT_EQ(Azimuth(0, 1), 0.0f);
    EXPECT_FLOAT_EQ(Azimuth(1, 0), float(kPi / 2));
    EXPECT_FLOAT_EQ(Azimuth(0, -1), float(kPi));
    EXPECT_FLOAT_EQ(Azimuth(-1, 0), float(-kPi / 2));
    EXPECT_FLOAT_EQ(Azimuth(1, 1), float(kPi / 4));
    EXPECT_FLOAT_EQ(Azimuth(-1, -1), float(-3 * kPi / 4));
    EXPECT_EQ(Azimuth(0, 0), 0.0f);
}

}  // namespace
}  // namespace gonio
