// transform(), vtransform() and ntransform() with named spaces use the renderer's coordinate
// systems even for a constant operand: folding them at compile time, where every space is the
// identity, once turned transform("world", "current", point(0, 0, 0)) into the origin of
// current space, wherever the camera was.

#include <gtest/gtest.h>

#include "tests/shaderlang/sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::Compile;
using testing::Grid;

// World space lies 5 units along current +z (a camera at world z = -5).
class CameraContext : public SimpleShadingContext {
  public:
    using SimpleShadingContext::SimpleShadingContext;
    bool CurrentFromSpace(const std::string& space, int point, Imath::M44f* m) const override {
        if (space != "world") return SimpleShadingContext::CurrentFromSpace(space, point, m);
        m->setTranslation(Imath::V3f(0, 0, 5));
        return true;
    }
};

TEST(SpaceFolding, ConstantPointsAreTransformedWhenTheShaderRuns) {
    test::CapturedDiagnostics d;
    auto shader = Compile(R"(surface t(point at = point(0, 0, 0)) {
        point a = point(0, 0, 1);
        Ci = color(zcomp(transform("world", "current", at)), zcomp(transform("world", a)),
                   zcomp(vtransform("world", "current", vector(0, 0, 1))));
    })",
                          d);
    ASSERT_TRUE(shader) << d.Text();
    ShaderInstance instance(shader);
    Grid grid(1, 1);
    CameraContext context(d.Get());
    context.BeginBatch(grid.globals, 3);
    ShaderExecutor exec;
    exec.Run(instance, grid.globals, context);
    FloatArg ci = exec.Output("Ci");
    EXPECT_FLOAT_EQ(ci.At(0, 0), 5.0f);   // world origin in current space
    EXPECT_FLOAT_EQ(ci.At(1, 0), -4.0f);  // current (0, 0, 1) in world space
    EXPECT_FLOAT_EQ(ci.At(2, 0), 1.0f);   // vectors do not move
    EXPECT_EQ(d.Text(), "");
}

}  // namespace
}  // namespace gonio::sl
