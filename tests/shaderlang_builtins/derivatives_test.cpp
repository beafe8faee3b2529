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
