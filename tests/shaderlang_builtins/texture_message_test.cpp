// Texture, environment and shadow through the context (channel selection, footprints,
// options), and attribute/option/rendererinfo.

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

TEST(TextureBuiltins, ChannelSelectionCoordinatesAndFootprint) {
    FakeContext context(2);
    context.uNeighbours = {1, -1};
    TestCall call(2);
    call.String("wood.tx")
        .Varying(TypeFromCode("f"), {{0.1f}, {0.3f}})
        .Varying(TypeFromCode("f"), {{0.5f}, {0.5f}})
        .String("swidth")
        .Float(2)
        .String("firstchannel")
        .Float(1)
        .Result(TypeFromCode("c"), true)
        .Context(&context);
    call.Run(FindKernel("texture", "c", "s*"));
    EXPECT_EQ(context.lastTexture, "wood.tx");
    EXPECT_EQ(context.lastFirstChannel, 1);
    EXPECT_NEAR(call.R(0, 0), 0.1f + 5 + 100, 1e-5f);
    EXPECT_NEAR(call.R(2, 1), 0.3f + 5 + 300, 1e-5f);
    EXPECT_NEAR(context.lastDsdx[0], 0.4f, 1e-6f);  // 0.2 to the neighbour, times swidth 2
    EXPECT_NEAR(context.lastDsdx[1], 0.4f, 1e-6f);  // backward difference at the edge
}

TEST(TextureBuiltins, DefaultCoordinatesComeFromTheGlobals) {
    FakeContext context(2);
    FakeGlobals globals(2);
    globals.SetVarying("s", 1, {0.25f, 0.5f});
    globals.SetVarying("t", 1, {0.0f, 0.1f});
    TestCall call(2);
    call.String("a.tx").Mask({0, 1}).Result(TypeFromCode("f"), true).Context(&context);
    call.Globals(&globals).Run(FindKernel("texture", "f", "s*"));
    EXPECT_EQ(call.R(0, 0), kSentinel);
    EXPECT_NEAR(call.R(0, 1), 1.5f, 1e-6f);
}

// PRMan's "swrap", "twrap" and "wrap" parameters reach the context as wrap modes; "wrap" sets
// both, a later "twrap" overrides it; an unknown mode is warned about and leaves the file's.
TEST(TextureBuiltins, WrapParametersReachTheContext) {
    FakeContext context(1);
    TestCall call(1);
    call.String("a.tx").Float(0.5f).Float(0.5f).String("wrap").String("periodic");
    call.String("twrap").String("clamp").Result(TypeFromCode("f"), true).Context(&context);
    call.Run(FindKernel("texture", "f", "s*"));
    EXPECT_EQ(context.lastWrap.s, TextureWrap::Periodic);
    EXPECT_EQ(context.lastWrap.t, TextureWrap::Clamp);
    EXPECT_TRUE(context.warnings.empty());

    TestCall unknown(1);
    unknown.String("a.tx").Float(0.5f).Float(0.5f).String("swrap").String("mirrorball");
    unknown.String("twrap").String("black").Result(TypeFromCode("f"), true).Context(&context);
    unknown.Run(FindKernel("texture", "f", "s*"));
    EXPECT_EQ(context.lastWrap.s, TextureWrap::Default);
    EXPECT_EQ(context.lastWrap.t, TextureWrap::Black);
    ASSERT_EQ(context.warnings.size(), 1u);
    EXPECT_NE(context.warnings.begin()->second.find("\"swrap\" \"mirrorball\""), std::string::npos);
}

// The context knows why a file cannot be read and reports it (render_imager checks the
// message); the built-in adds no second warning.
TEST(TextureBuiltins, MissingTextureIsBlackAndTheContextReportsIt) {
    FakeContext context(1);
    TestCall call(1);
    call.String("missing.tx").Float(0.5f).Float(0.5f).Result(TypeFromCode("f"), true);
    call.Context(&context).Run(FindKernel("texture", "f", "s*"));
    EXPECT_EQ(call.R(0), 0.0f);
    EXPECT_TRUE(context.warnings.empty());
}

TEST(TextureBuiltins, EnvironmentAndShadow) {
    FakeContext context(2);
    TestCall env(2);
    env.String("sky.tx").Varying(TypeFromCode("v"), {{1, 2, 3}, {4, 5, 6}});
    env.Result(TypeFromCode("c"), true).Context(&context).Run(FindKernel("environment", "c", "s*"));
    EXPECT_EQ(env.R(1, 1), 5.0f);
    TestCall shadow(2);
    shadow.String("shadow.z").Varying(TypeFromCode("p"), {{1, 0, 0}, {-1, 0, 0}});
    shadow.String("bias").Float(0.01f);
    shadow.String("samples").Float(64);
    shadow.String("blur").Float(0.125f);
    shadow.String("twidth").Float(3);
    shadow.Result(TypeFromCode("f"), true).Context(&context).Run(FindKernel("shadow", "f", "s*"));
    EXPECT_EQ(shadow.R(0, 0), 1.0f);
    EXPECT_EQ(shadow.R(0, 1), 0.0f);
    // The filter's parameters reach the renderer (RISpec §15.7.3, PRMan's names).
    EXPECT_EQ(context.lastShadowOptions.bias, 0.01f);
    EXPECT_EQ(context.lastShadowOptions.samples, 64.0f);
    EXPECT_EQ(context.lastShadowOptions.sblur, 0.125f);
    EXPECT_EQ(context.lastShadowOptions.tblur, 0.125f);
    EXPECT_EQ(context.lastShadowOptions.swidth, 1.0f);
    EXPECT_EQ(context.lastShadowOptions.twidth, 3.0f);
}

TEST(MessageBuiltins, AttributeOptionRendererinfo) {
    FakeContext context(3);
    context.floatInfo["Format"] = {640, 480, 1};
    context.floatInfo["attr:ShadingRate"] = {1};
    context.stringInfo["renderer:renderer"] = "gonio";
    auto query = [&](const std::string& name, const std::string& what, const std::string& out,
                     bool varying) {
        auto call = std::make_unique<TestCall>(3);
        call->String(what);
        if (out == "S")
            call->String("unchanged");
        else if (varying)
            call->Varying(TypeFromCode(out),
                          std::vector<std::vector<float>>(3, std::vector<float>(16, -1)));
        else
            call->Uniform(TypeFromCode(out), std::vector<float>(16, -1));
        call->Result(TypeFromCode("f"), varying).Context(&context);
        call->Run(FindKernel(name, "f", "s" + out));
        return call;
    };
    TestCall arrayCall(3);
    arrayCall.String("Format").Uniform(TypeSpec{BaseType::Float, 3}, {0, 0, 0});
    arrayCall.Result(TypeFromCode("f"), false).Context(&context);
    arrayCall.Run(FindKernel("option", "f", "sF[]"));
    EXPECT_EQ(arrayCall.R(0), 1.0f);
    EXPECT_EQ(arrayCall.Arg(1, 1), 480.0f);

    auto rate = query("attribute", "ShadingRate", "F", false);
    EXPECT_EQ(rate->R(0), 1.0f);
    EXPECT_EQ(rate->Arg(1, 0), 1.0f);
    auto unknown = query("attribute", "nothing", "F", false);
    EXPECT_EQ(unknown->R(0), 0.0f);
    EXPECT_EQ(unknown->Arg(1, 0), -1.0f);  // left unchanged
    auto perPoint = query("attribute", "user:perpoint", "F", true);
    EXPECT_EQ(perPoint->Arg(1, 0, 2), 2.0f);
    auto renderer = query("rendererinfo", "renderer", "S", false);
    EXPECT_EQ(renderer->R(0), 1.0f);
    EXPECT_EQ(renderer->StringArgValue(1), "gonio");
}

}  // namespace
}  // namespace gonio::sl::testing
