// The quadrics' angles: AngleRange, the test of a direction against a partial sweep (or φ range)
// without atan2, must agree with the angle itself, for spans up to and beyond half a turn, in
// either sense and from any start; Atan2 must agree with std::atan2 to a few units in the last
// place everywhere, its special values included.
#include "renderer/geometry/quadric_angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace gonio::quadric {
namespace {

// Whether the angle of (x, y) lies in [start, start + span] by atan2: the reference, together
// with how far (radians) the direction lies from the nearer end of the range.
bool ContainsByAngle(double start, double span, double x, double y, double* margin) {
    double turned = std::atan2(y, x) - start;
    if (span < 0) turned = -turned;
    turned = std::fmod(turned, 2 * kPi);
    if (turned < 0) turned += 2 * kPi;
    const double width = std::fabs(span);
    *margin = std::min({std::fabs(turned - width), turned, 2 * kPi - turned});
    return turned <= width;
}

TEST(QuadricAngleRange, AgreesWithTheAngleAwayFromTheEnds) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> angle(-4 * kPi, 4 * kPi), span(-2 * kPi, 2 * kPi);
    std::uniform_real_distribution<double> length(1e-3, 1e3);
    int inside = 0, outside = 0;
    for (int range = 0; range < 200; ++range) {
        const double start = angle(random), width = span(random);
        const AngleRange arc(start, width);
        for (int k = 0; k < 500; ++k) {
            const double a = angle(random), r = length(random);
            const double x = r * std::cos(a), y = r * std::sin(a);
            double margin;
            const bool expected = ContainsByAngle(start, width, x, y, &margin);
            if (margin < 1e-9) continue;  // on an end: rounding may decide either way
            EXPECT_EQ(arc.Contains(x, y), expected)
                << "start " << start << " span " << width << " angle " << a;
            (expected ? inside : outside)++;
        }
    }
    EXPECT_GT(inside, 10000);
    EXPECT_GT(outside, 10000);
}

TEST(QuadricAngleRange, HalfTurnsQuarterTurnsAndFullTurns) {
    // Exactly half a turn from +x counterclockwise: the upper half plane.
    const AngleRange upper(0, kPi);
    EXPECT_TRUE(upper.Contains(0, 1));
    EXPECT_TRUE(upper.Contains(1, 1e-9));
    EXPECT_TRUE(upper.Contains(-1, 1e-9));
    EXPECT_FALSE(upper.Contains(0, -1));
    EXPECT_FALSE(upper.Contains(1, -1e-9));
    // Clockwise a quarter turn from +y: the first quadrant, reached backwards.
    const AngleRange backwards(kPi / 2, -kPi / 2);
    EXPECT_TRUE(backwards.Contains(1, 1));
    EXPECT_FALSE(backwards.Contains(-1, 1));
    EXPECT_FALSE(backwards.Contains(1, -1));
    EXPECT_FALSE(backwards.Contains(-1, -1));
    // Three quarter turns from +x: everything but the fourth quadrant.
    const AngleRange most(0, 1.5 * kPi);
    EXPECT_TRUE(most.Contains(-1, -1));
    EXPECT_TRUE(most.Contains(0.5, 1));
    EXPECT_FALSE(most.Contains(1, -1));
    // A full turn (or more) and the default range take every direction.
    for (const AngleRange& all : {AngleRange(), AngleRange(1, 2 * kPi), AngleRange(1, -7)}) {
        for (double a = 0; a < 2 * kPi; a += 0.1)
            EXPECT_TRUE(all.Contains(std::cos(a), std::sin(a))) << a;
    }
}

// The error of Atan2 against std::atan2 (itself within an ulp), in units of the last place of
// the reference.
double UlpError(double y, double x) {
    const double reference = std::atan2(y, x), actual = Atan2(y, x);
    const double ulp = std::nextafter(std::fabs(reference), 10.0) - std::fabs(reference);
    return std::fabs(actual - reference) / ulp;
}

TEST(QuadricAtan2, WithinTwoUlpsOfTheLibrary) {
    std::mt19937 random(12);
    std::uniform_real_distribution<double> angle(-kPi, kPi), exponent(-30, 30);
    double worst = 0;
    for (int k = 0; k < 1000000; ++k) {
        const double a = angle(random), r = std::exp2(exponent(random));
        worst = std::max(worst, UlpError(r * std::sin(a), r * std::cos(a)));
    }
    // Near the octant and quadrant boundaries, where the reduction changes branch, and near the
    // axes, where the result is tiny or next to ±π/2 and ±π.
    for (double base : {0.0, 0.66, 1.0, 1 / 0.66}) {
        for (int k = -2000; k <= 2000; ++k) {
            const double t = base + k * 1e-6;
            for (double sx : {1.0, -1.0})
                for (double sy : {1.0, -1.0}) {
                    worst = std::max(worst, UlpError(sy * t, sx * 1.0));
                    worst = std::max(worst, UlpError(sy * 1.0, sx * t));
                }
        }
    }
    for (double tiny : {1e-300, 1e-20, 1e-9})
        for (double sx : {1.0, -1.0})
            for (double sy : {1.0, -1.0}) {
                worst = std::max(worst, UlpError(sy * tiny, sx * 3.0));
                worst = std::max(worst, UlpError(sy * 3.0, sx * tiny));
            }
    EXPECT_LE(worst, 2.0);
}

TEST(QuadricAtan2, SpecialValuesAsTheLibrary) {
    const double inf = std::numeric_limits<double>::infinity();
    for (double y : {0.0, -0.0, 1.0, -1.0, inf, -inf})
        for (double x : {0.0, -0.0, 1.0, -1.0, inf, -inf}) {
            const double expected = std::atan2(y, x), actual = Atan2(y, x);
            EXPECT_EQ(actual, expected) << y << " " << x;
            EXPECT_EQ(std::signbit(actual), std::signbit(expected)) << y << " " << x;
        }
    EXPECT_TRUE(std::isnan(Atan2(std::nan(""), 1.0)));
    EXPECT_TRUE(std::isnan(Atan2(1.0, std::nan(""))));
    // The axes exactly: the same doubles as the library, which the sphere's full φ range and
    // the sweep's start edge rely on.
    for (double r : {1e-3, 1.0, 7.5}) {
        EXPECT_EQ(Atan2(r, 0.0), std::atan2(r, 0.0));
        EXPECT_EQ(Atan2(-r, 0.0), std::atan2(-r, 0.0));
        EXPECT_EQ(Atan2(0.0, -r), std::atan2(0.0, -r));
        EXPECT_EQ(Atan2(0.0, r), 0.0);
    }
}

}  // namespace
}  // namespace gonio::quadric
