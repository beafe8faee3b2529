// Matrix built-ins: comp/setcomp, determinant, translate, rotate, scale (row vectors).

#include <Imath/ImathMatrix.h>

#include <cmath>

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

using M44 = Imath::M44f;

std::vector<float> Flat(const M44& m) { return std::vector<float>(m[0], m[0] + 16); }

M44 RunMatrix(const std::string& name, const std::string& args, const M44& m,
              std::vector<std::vector<float>> rest) {
    TestCall call(1);
    call.Uniform(TypeFromCode("m"), Flat(m));
    for (size_t i = 1; i < args.size(); ++i)
        call.Uniform(TypeFromCode(args.substr(i, 1)), rest[i - 1]);
    call.Result(TypeFromCode("m"), false);
    call.Run(FindKernel(name, "m", args));
    M44 out;
    for (int i = 0; i < 16; ++i) out[i / 4][i % 4] = call.R(i);
    return out;
}

Imath::V3f Apply(const M44& m, const Imath::V3f& p) {
    Imath::V3f out;
    m.multVecMatrix(p, out);
    return out;
}

TEST(MatrixBuiltins, CompSetcompDeterminant) {
    M44 m(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    ExpectAllVariants(
        "comp", "f", "mff", {{Flat(m), Flat(m)}, {{1}, {3}}, {{2}, {0}}},
        [&](const PointArgs& a) { return std::vector<float>{m[int(a[1][0])][int(a[2][0])]}; });
    M44 diag;
    diag.setScale(Imath::V3f(2, 3, 4));
    ExpectAllVariants("determinant", "f", "m", {{Flat(diag), Flat(m)}}, [&](const PointArgs& a) {
        return std::vector<float>{a[0][0] == 2 ? 24.0f : 0.0f};
    });
    TestCall set(1);
    set.Uniform(TypeFromCode("M"), Flat(m)).Float(2).Float(3).Float(-1);
    set.Run(FindKernel("setcomp", "x", "Mfff"));
    EXPECT_EQ(set.Arg(0, 11), -1.0f);
}

TEST(MatrixBuiltins, TranslateRotateScaleFollowRiOrder) {
    M44 identity;
    M44 t = RunMatrix("translate", "mv", identity, {{1, 2, 3}});
    EXPECT_EQ(Apply(t, Imath::V3f(0)), Imath::V3f(1, 2, 3));
    // rotate by 90° about z takes x to y.
    M44 r = RunMatrix("rotate", "mfv", identity, {{float(M_PI / 2)}, {0, 0, 1}});
    Imath::V3f y = Apply(r, Imath::V3f(1, 0, 0));
    EXPECT_NEAR(y.x, 0.0f, 1e-6f);
    EXPECT_NEAR(y.y, 1.0f, 1e-6f);
    // translate(scale(I, 2), t): the translation applies first, then the scale (RiTranslate
    // inside RiScale), so the origin lands at 2·t.
    M44 s = RunMatrix("scale", "mp", identity, {{2, 2, 2}});
    M44 st = RunMatrix("translate", "mv", s, {{1, 0, 0}});
    EXPECT_EQ(Apply(st, Imath::V3f(0)), Imath::V3f(2, 0, 0));
}

}  // namespace
}  // namespace gonio::sl::testing
