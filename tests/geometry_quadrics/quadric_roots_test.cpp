// The polynomial root finder behind the torus.
#include "renderer/geometry/quadric_roots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace gonio::quadric {
namespace {

// The coefficients (lowest first) of Π (t − r_i).
std::vector<double> FromRoots(const std::vector<double>& roots) {
    std::vector<double> c = {1};
    for (double r : roots) {
        std::vector<double> next(c.size() + 1, 0);
        for (size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= r * c[i];
        }
        c = next;
    }
    return c;
}

TEST(QuadricRoots, QuadraticIsFreeOfCancellation) {
    double r[2];
    ASSERT_EQ(SolveQuadratic(1, -1e8, 1, r), 2);
    EXPECT_NEAR(r[0], 1e-8, 1e-22);  // the naive formula gets this small root wrong
    EXPECT_NEAR(r[1], 1e8, 1e-6);
    ASSERT_EQ(SolveQuadratic(0, 2, -1, r), 1);
    EXPECT_EQ(r[0], 0.5);
    EXPECT_EQ(SolveQuadratic(1, 0, 1, r), 0);
    EXPECT_EQ(SolveQuadratic(0, 0, 1, r), 0);
}

TEST(QuadricRoots, QuarticRootsInAnInterval) {
    const std::vector<double> c = FromRoots({-3, -0.5, 1, 2.25});
    double r[4];
    ASSERT_EQ(PolynomialRootsIn(c.data(), 4, -10, 10, r), 4);
    EXPECT_NEAR(r[0], -3, 1e-14);
    EXPECT_NEAR(r[1], -0.5, 1e-14);
    EXPECT_NEAR(r[2], 1, 1e-14);
    EXPECT_NEAR(r[3], 2.25, 1e-14);
    ASSERT_EQ(PolynomialRootsIn(c.data(), 4, -1, 2, r), 2);
    EXPECT_NEAR(r[0], -0.5, 1e-14);
    EXPECT_NEAR(r[1], 1, 1e-14);
}

TEST(QuadricRoots, CloseRootsAreSeparated) {
    const std::vector<double> c = FromRoots({1, 1 + 1e-6, 3, 4});
    double r[4];
    ASSERT_EQ(PolynomialRootsIn(c.data(), 4, 0, 5, r), 4);
    EXPECT_NEAR(r[0], 1, 1e-9);
    EXPECT_NEAR(r[1], 1 + 1e-6, 1e-9);
}

TEST(QuadricRoots, RandomQuarticsWithRealAndComplexRoots) {
    std::mt19937 random(9);
    std::uniform_real_distribution<double> uniform(-5, 5);
    for (int k = 0; k < 1000; ++k) {
        std::vector<double> real = {uniform(random), uniform(random)};
        // Times (t² − 2a·t + a² + b²): a complex pair a ± ib.
        std::vector<double> c = FromRoots(real);
        const double a = uniform(random), b = 0.1 + std::fabs(uniform(random));
        const double quadratic[3] = {a * a + b * b, -2 * a, 1};
        std::vector<double> product(5, 0);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) product[i + j] += c[i] * quadratic[j];
        std::sort(real.begin(), real.end());
        if (real[1] - real[0] < 1e-3) continue;
        double r[4];
        ASSERT_EQ(PolynomialRootsIn(product.data(), 4, -6, 6, r), 2) << k;
        EXPECT_NEAR(r[0], real[0], 1e-9);
        EXPECT_NEAR(r[1], real[1], 1e-9);
    }
}

}  // namespace
}  // namespace gonio::quadric
