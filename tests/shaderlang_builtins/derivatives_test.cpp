// Derivatives over a 3×3 grid of points with u/v neighbours: Du, Dv, Deriv, area,
// calculatenormal.

#include <cmath>

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

// A 3×3 grid, u along x (step 0.5), v along y (step 0.25); point i = 3·row + column.
struct Grid {
    Grid() : context(9), globals(9) {
        for (int p = 0; p < 9; ++p) {
            int col = p % 3, row = p / 3;
            context.uNeighbours.push_back(col < 2 ? p + 1 : -1);
            context.vNeighbours.push_back(row < 2 ? p + 3 : -1);
            u.push_back({0.5f * col});
            v.push_back({0.25f * row});
        }
        globals.SetUniform("du", {0.5f});
        globals.SetUniform("dv", {0.25f});
        globals.SetUniform("Ng", {0, 0, -1});
    }
    FakeContext context;
    FakeGlobals globals;
    std::vector<std::vector<float>> u, v;
};

TEST(DerivativeBuiltins, DuDvOfPolynomials) {
    Grid grid;
    // f = 3u + 2v² -> Du = 3 exactly; Dv by forward difference = 2(2v + dv).
    std::vector<std::vector<float>> f;
    for (int p = 0; p < 9; ++p) f.push_back({3 * grid.u[p][0] + 2 * grid.v[p][0] * grid.v[p][0]});
    TestCall du(9);
    du.Varying(TypeFromCode("f"), f).Result(TypeFromCode("f"), true);
    du.Context(&grid.context).Globals(&grid.globals).Run(FindKernel("Du", "f", "f"));
    TestCall dv(9);
    dv.Varying(TypeFromCode("f"), f)
        .Mask({1, 1, 1, 1, 0, 1, 1, 1, 1})
        .Result(TypeFromCode("f"), true);
    dv.Context(&grid.context).Globals(&grid.globals).Run(FindKernel("Dv", "f", "f"));
    for (int p = 0; p < 9; ++p) {
        EXPECT_NEAR(du.R(0, p), 3.0f, 1e-5f);
        if (p == 4) {
            EXPECT_EQ(dv.R(0, p), kSentinel);
            continue;
        }
        float v0 = p / 3 < 2 ? grid.v[p][0] : grid.v[p][0] - 0.25f;  // backward at the edge
        EXPECT_NEAR(dv.R(0, p), 2 * (2 * v0 + 0.25f), 1e-5f);
    }
    // A uniform value has zero derivatives.
    TestCall constant(9);
    constant.Float(4).Result(TypeFromCode("f"), true).Context(&grid.context).Globals(&grid.globals);
    constant.Run(FindKernel("Du", "f", "f"));
    EXPECT_EQ(constant.R(0, 4), 0.0f);
}

TEST(DerivativeBuiltins, DerivAreaAndNormal) {
    Grid grid;
    // P(u, v) = (2u, 3v, 0): Du(P) = (2,0,0), Dv(P) = (0,3,0).
    std::vector<std::vector<float>> P, x;
    for (int p = 0; p < 9; ++p) {
        P.push_back({2 * grid.u[p][0], 3 * grid.v[p][0], 0});
        x.push_back({P.back()[0]});
    }
    // Deriv(P, x) with x = 2u: dP/dx along u = (1, 0, 0); x does not change along v.
    TestCall deriv(9);
    deriv.Varying(TypeFromCode("p"), P)
        .Varying(TypeFromCode("f"), x)
        .Result(TypeFromCode("v"), true);
    deriv.Context(&grid.context).Run(FindKernel("Deriv", "v", "pf"));
    EXPECT_NEAR(deriv.R(0, 4), 1.0f, 1e-5f);
    EXPECT_NEAR(deriv.R(1, 4), 0.0f, 1e-5f);

    TestCall area(9);
    area.Varying(TypeFromCode("p"), P).Result(TypeFromCode("f"), true).Context(&grid.context);
    area.Run(FindKernel("area", "f", "p"));
    for (int p = 0; p < 9; ++p) EXPECT_NEAR(area.R(0, p), (2 * 0.5f) * (3 * 0.25f), 1e-5f);

    TestCall normal(9);
    normal.Varying(TypeFromCode("p"), P).Result(TypeFromCode("n"), true);
    normal.Context(&grid.context).Globals(&grid.globals);
    normal.Run(FindKernel("calculatenormal", "n", "p"));
    for (int p = 0; p < 9; ++p) EXPECT_NEAR(normal.R(2, p), -1.0f, 1e-6f);  // turned to Ng
}

}  // namespace
}  // namespace gonio::sl::testing

namespace gonio::sl::testing {
namespace {

// A ray tracer's layout (renderer/shading/shader_shading.cpp): m points, then each one's
// neighbour a pixel along x, then along y; the pixel steps run in any direction of (u, v), and
// NeighbourSteps says which. The neighbours have steps of their own (back to the point, across
// to the other neighbour), so that every point has both derivatives.
struct PixelNeighbours {
    static constexpr int m = 2, n = 3 * m;
    PixelNeighbours() : context(n), globals(n) {
        const float a = 0.01f * std::cos(0.5f), b = -0.01f * std::sin(0.5f);  // step along x
        const float c = 0.004f, d = 0.012f;                                   // step along y
        context.uNeighbours.assign(n, -1);
        context.vNeighbours.assign(n, -1);
        context.neighbourSteps.assign(4 * n, 0.0f);
        auto step = [&](int point, int direction, float du, float dv) {
            context.neighbourSteps[2 * direction * n + point] = du;
            context.neighbourSteps[(2 * direction + 1) * n + point] = dv;
        };
        u.resize(n), v.resize(n);
        for (int i = 0; i < m; ++i) {
            u[i] = 0.2f + 0.3f * i, v[i] = 0.4f;
            u[m + i] = u[i] + a, v[m + i] = v[i] + b;
            u[2 * m + i] = u[i] + c, v[2 * m + i] = v[i] + d;
            context.uNeighbours[i] = m + i, context.vNeighbours[i] = 2 * m + i;
            context.vNeighbours[m + i] = 2 * m + i;
            context.uNeighbours[2 * m + i] = i;
            step(i, 0, a, b), step(i, 1, c, d);
            step(m + i, 1, c - a, d - b);
            step(2 * m + i, 0, -c, -d);
        }
        globals.SetUniform("Ng", {0, 0, 1});
    }
    FakeContext context;
    FakeGlobals globals;
    std::vector<float> u, v;
};

TEST(DerivativeBuiltins, DuDvFromNeighbourStepsInAnyDirection) {
    PixelNeighbours grid;
    // f = 3u + 2v (+ 1): Du = 3 and Dv = 2 at every point, neighbours included.
    std::vector<std::vector<float>> f, g;
    for (int p = 0; p < grid.n; ++p) {
        f.push_back({3 * grid.u[p] + 2 * grid.v[p] + 1});
        g.push_back({grid.u[p] - grid.v[p]});
    }
    for (const char* name : {"Du", "Dv"}) {
        TestCall call(grid.n);
        call.Varying(TypeFromCode("f"), f).Result(TypeFromCode("f"), true);
        call.Context(&grid.context).Globals(&grid.globals).Run(FindKernel(name, "f", "f"));
        for (int p = 0; p < grid.n; ++p)
            EXPECT_NEAR(call.R(0, p), name[1] == 'u' ? 3.0f : 2.0f, 2e-3f) << name << " " << p;
    }
    // Deriv(f, g) = Du(f)/Du(g) + Dv(f)/Dv(g) = 3/1 + 2/-1.
    TestCall deriv(grid.n);
    deriv.Varying(TypeFromCode("f"), f).Varying(TypeFromCode("f"), g);
    deriv.Result(TypeFromCode("f"), true).Context(&grid.context);
    deriv.Run(FindKernel("Deriv", "f", "ff"));
    for (int p = 0; p < grid.n; ++p) EXPECT_NEAR(deriv.R(0, p), 1.0f, 2e-3f) << p;
}

TEST(DerivativeBuiltins, CalculateNormalIsDuPCrossDvP) {
    PixelNeighbours grid;
    // P = (2u, 3v, u + v): Du(P) ^ Dv(P) = (2, 0, 1) ^ (0, 3, 1) = (-3, -2, 6), length 7.
    std::vector<std::vector<float>> P;
    for (int p = 0; p < grid.n; ++p)
        P.push_back({2 * grid.u[p], 3 * grid.v[p], grid.u[p] + grid.v[p]});
    TestCall normal(grid.n);
    normal.Varying(TypeFromCode("p"), P).Result(TypeFromCode("n"), true);
    normal.Context(&grid.context).Globals(&grid.globals);
    normal.Run(FindKernel("calculatenormal", "n", "p"));
    for (int p = 0; p < grid.n; ++p) {
        EXPECT_NEAR(normal.R(0, p), -3.0f / 7, 1e-3f) << p;
        EXPECT_NEAR(normal.R(1, p), -2.0f / 7, 1e-3f) << p;
        EXPECT_NEAR(normal.R(2, p), 6.0f / 7, 1e-3f) << p;
    }
}

}  // namespace
}  // namespace gonio::sl::testing
