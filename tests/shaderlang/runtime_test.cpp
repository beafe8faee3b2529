// Instances: parameter descriptions, overrides, constant folding and instance specialisation,
// uniform inference, run-time warnings once per line, lights through illuminance.

#include <gtest/gtest.h>

#include "shaderlang/compiler/optimizer.h"
#include "shaderlang/runtime/opcodes.h"
#include "shaderlang/runtime/program.h"
#include "sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::CapturedDiagnostics;
using testing::Compile;

TEST(ShadeRuntime, DescribesParameters) {
    CapturedDiagnostics d;
    auto s = Compile(R"(surface t(float Kd = 0.5 * 2; varying color c = (1, 0, 0);
                                  output float aov = 0; string name = "x";
                                  point from = point "world" (0, 0, 1); float w[2] = {3, 4};) {
        Ci = c;
    })",
                     d);
    ASSERT_TRUE(s) << d.Text();
    ASSERT_EQ(s->Params().size(), 6u);
    EXPECT_EQ(s->Type(), ShaderType::Surface);
    EXPECT_EQ(s->Name(), "t");
    const ShaderParam& kd = s->Params()[0];
    EXPECT_EQ(kd.detail, Detail::Uniform);
    EXPECT_EQ(kd.defaultFloats, std::vector<float>{1.0f});
    EXPECT_EQ(s->Params()[1].detail, Detail::Varying);
    EXPECT_EQ(s->Params()[1].defaultFloats, (std::vector<float>{1, 0, 0}));
    EXPECT_TRUE(s->Params()[2].output);
    EXPECT_EQ(s->Params()[3].defaultStrings, std::vector<std::string>{"x"});
    EXPECT_FALSE(s->Params()[4].defaultIsConstant);  // a space cast needs the renderer
    EXPECT_EQ(s->Params()[5].defaultFloats, (std::vector<float>{3, 4}));
}

TEST(ShadeRuntime, SpecialisationFoldsInstanceConstants) {
    CapturedDiagnostics d;
    auto s = Compile(R"(surface t(float Kd = 0.5; float mode = 0;) {
        float k = Kd * 2;
        if (mode > 0) { Ci = color(k, 0, 0); } else { Ci = color(0, k, 0); }
    })",
                     d);
    ASSERT_TRUE(s) << d.Text();
    ShaderInstance instance(s);
    std::string error;
    ASSERT_TRUE(instance.SetParameter("mode", std::vector<float>{1}, &error)) << error;
    ASSERT_TRUE(instance.SetParameter("Kd", std::vector<float>{0.25f}, &error)) << error;
    auto r = testing::Run(instance, 2, 1, "Ci");
    EXPECT_FLOAT_EQ(r.At(0, 1), 0.5f);
    EXPECT_FLOAT_EQ(r.At(1, 1), 0.0f);
    // Everything folded: one store of a constant into Ci, no branch left.
    const Program& code = instance.Code();
    EXPECT_LE(code.code.size(), 2u) << Disassemble(code);
    for (const Instr& in : code.code) EXPECT_NE(in.op, uint16_t(Op::If)) << Disassemble(code);
    EXPECT_FALSE(instance.SetParameter("Kd", std::vector<float>{1, 2}, &error));
    EXPECT_EQ(error, "parameter 'Kd' (float) takes 1 numbers, not 2");
}

TEST(ShadeRuntime, LocalsAreUniformUnlessAVaryingValueReachesThem) {
    CapturedDiagnostics d;
    auto s = Compile(R"(surface t(float Kd = 0.5;) {
        float a = Kd * 3;
        float b = a + u;
        float c = 1;
        if (u > 0.5) c = 2;
        Ci = a + b + c;
    })",
                     d);
    ASSERT_TRUE(s) << d.Text();
    ShaderInstance instance(s);
    instance.KeepVariables();
    instance.Specialize();
    const Program& p = instance.Code();
    EXPECT_FALSE(p.regs[p.named.at("a")].varying);
    EXPECT_TRUE(p.regs[p.named.at("b")].varying);
    EXPECT_TRUE(p.regs[p.named.at("c")].varying);  // assigned under a varying condition
    auto r = testing::Run(instance, 2, 1, "c");
    EXPECT_EQ(r.At(0, 0), 1);
    EXPECT_EQ(r.At(0, 1), 2);
}

TEST(ShadeRuntime, DivisionByZeroAndNaNAreReportedOncePerLine) {
    CapturedDiagnostics d;
    auto s = Compile(
        "surface t() {\n  float z = u - u;\n  float a = 1 / z;\n"
        "  float b = sqrt(-1 - u);\n  Ci = a + b;\n}\n",
        d);
    ASSERT_TRUE(s) << d.Text();
    ShaderInstance instance(s);
    auto r = testing::Run(instance, 4, 4, "Ci");
    const std::string& text = r.diagnostics;
    EXPECT_NE(text.find("test.sl:3: warning: division by zero (the result is 0)"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find("division by zero"), text.rfind("division by zero")) << text;
    EXPECT_NE(text.find("test.sl:4: warning: NaN from sqrt()"), std::string::npos) << text;
}

TEST(ShadeRuntime, IlluminanceLoopsOverIlluminateLights) {
    CapturedDiagnostics d;
    auto light = Compile(R"(light pt(float intensity = 1; point from = (0, 0, -1);) {
        illuminate (from) { Cl = intensity / (L . L); }
    })",
                         d);
    auto amb = Compile("light amb(float intensity = 0.25;) { Cl = intensity; }", d);
    auto surf = Compile(R"(surface s() {
        color sum = 0;
        illuminance (P, N, PI / 2) { sum += Cl * (normalize(L) . normalize(N)); }
        Ci = sum + ambient();
    })",
                        d);
    ASSERT_TRUE(light && amb && surf) << d.Text();
    auto lightInstance = std::make_shared<ShaderInstance>(light);
    auto ambInstance = std::make_shared<ShaderInstance>(amb);
    ShaderInstance instance(surf);
    auto r = testing::Run(instance, 2, 2, "Ci", {lightInstance, ambInstance});
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    // Point (0.25, 0.25, 0): d² = 0.125 + 1, cosine = 1 / d.
    const float d2 = 0.25f * 0.25f * 2 + 1;
    EXPECT_NEAR(r.At(0, 0), 1 / d2 / std::sqrt(d2) + 0.25f, 1e-5) << r.diagnostics;
}

}  // namespace
}  // namespace gonio::sl
