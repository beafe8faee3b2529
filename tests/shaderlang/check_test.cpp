// The front end: preprocessor, syntax errors and the type checker's messages (exact text).

#include <gtest/gtest.h>

#include "sl_test_util.h"

namespace gonio::sl {
namespace {

using testing::Errors;

TEST(ShadeCheck, SyntaxErrorsAreAllReportedWithLocations) {
    std::string e = Errors("surface t() {\n  float x = ;\n  Ci = 1 +;\n}\n");
    EXPECT_NE(e.find("test.sl:2:13: error: syntax error"), std::string::npos) << e;
    EXPECT_NE(e.find("test.sl:3:11: error: syntax error"), std::string::npos) << e;
}

// Inputs that would hang or exhaust memory are located errors: an include of a device, and a
// macro that doubles itself 30 times (2^30 copies).
TEST(ShadeCheck, RunawayPreprocessingIsAnError) {
    std::string e = Errors("#include \"/dev/zero\"\nsurface t() {}\n");
    EXPECT_NE(e.find("test.sl:1:1: error: cannot include '/dev/zero': not a regular file"),
              std::string::npos)
        << e;
    std::string doubling = "#define A0 x\n";
    for (int i = 0; i < 30; ++i)
        doubling += "#define A" + std::to_string(i + 1) + " A" + std::to_string(i) + " A" +
                    std::to_string(i) + "\n";
    e = Errors(doubling + "surface t() { float x = 1; float y = A30; }\n");
    EXPECT_NE(e.find("test.sl:32:1: error: the macros of this line expand to more than 1 MiB"),
              std::string::npos)
        << e;
}

TEST(ShadeCheck, TypeErrorsAreAllReported) {
    std::string e = Errors(
        "surface t() {\n"
        "  point p = P;\n"
        "  color c = \"p\";\n"
        "  float f = nosuch(1);\n"
        "  Ci = Cs + p;\n"
        "  float g = (u < 1);\n"
        "  Ci = undefinedvar;\n"
        "}\n");
    EXPECT_NE(
        e.find("test.sl:3:13: error: in the initialiser of 'c': cannot convert string to color"),
        std::string::npos)
        << e;
    EXPECT_NE(e.find("test.sl:4:13: error: unknown function 'nosuch'"), std::string::npos) << e;
    EXPECT_NE(e.find("test.sl:5:11: error: cannot apply '+' to color and point (points and colors "
                     "do not mix)"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("test.sl:6:16: error: a comparison result can only be used as a condition"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("test.sl:7:8: error: unknown variable 'undefinedvar'"), std::string::npos)
        << e;
}

TEST(ShadeCheck, UniformVaryingRules) {
    std::string e = Errors(
        "surface t() {\n"
        "  uniform float a = u;\n"
        "  uniform float b = 1;\n"
        "  if (u > 0.5) b = 2;\n"
        "  b = s;\n"
        "  uniform float c = 0;\n"
        "  if (b > 0) c = 3;\n"
        "}\n");
    EXPECT_NE(e.find("test.sl:2:21: error: cannot initialise uniform 'a' with a varying value"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("test.sl:4:16: error: cannot assign to uniform 'b' under a varying condition"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("test.sl:5:3: error: cannot assign a varying value to uniform 'b'"),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find("test.sl:7:"), std::string::npos) << "a uniform condition is fine: " << e;
}

TEST(ShadeCheck, ReadOnlyGlobalsAndParametersNeedDefaults) {
    std::string e = Errors("surface t(float Kd;) { Ng = 0; L = 0; }\n");
    EXPECT_NE(e.find("test.sl:1:17: error: shader parameter 'Kd' needs a default value"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("error: cannot assign to 'Ng': it is read-only in surface shaders"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("error: cannot assign to 'L': it is read-only in surface shaders"),
              std::string::npos)
        << e;
    // I is writable in surface shaders only (as Pixie has it, docs/shading-language.md).
    e = Errors("displacement t() { I = 0; }\n");
    EXPECT_NE(e.find("error: cannot assign to 'I': it is read-only in displacement shaders"),
              std::string::npos)
        << e;
}

TEST(ShadeCheck, OverloadsResolveOnExpectedReturnType) {
    testing::CapturedDiagnostics d;
    auto shader =
        testing::Compile("surface t() { float f = noise(P); color c = noise(P); Ci = c + f; }", d);
    EXPECT_TRUE(shader) << d.Text();
    std::string e = Errors("surface t() { Ci = normalize(\"x\"); }");
    EXPECT_NE(e.find("error: no version of 'normalize' takes (string)"), std::string::npos) << e;
}

// A call that matches no version of a user function (here one with an output parameter) is
// an error, not a crash (found by the shader fuzzer).
TEST(ShadeCheck, UserFunctionWithNoMatchingVersion) {
    std::string e = Errors(
        "void f(output float x) { x = 1; }\n"
        "surface t() {\n"
        "  f(\"a\");\n"
        "}\n");
    EXPECT_NE(e.find("test.sl:3:3: error: no version of function 'f' takes (string)"),
              std::string::npos)
        << e;
}

TEST(ShadeCheck, ControlFlowErrors) {
    std::string e = Errors(
        "surface t() {\n"
        "  break;\n"
        "  while (1 < 2) { continue 2; }\n"
        "  illuminate (P) { }\n"
        "}\n");
    EXPECT_NE(e.find("test.sl:2:3: error: break outside a loop"), std::string::npos) << e;
    EXPECT_NE(e.find("test.sl:3:19: error: continue 2 leaves more loops than enclose it"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("test.sl:4:3: error: illuminate is only allowed in light shaders"),
              std::string::npos)
        << e;
}

TEST(ShadeCheck, RecursionIsAnError) {
    std::string e = Errors("float f(float x) { return f(x); }\nsurface t() { Ci = f(1); }\n");
    EXPECT_NE(e.find("error: recursive call of 'f'"), std::string::npos) << e;
}

// Deeply nested #if expressions are an error, not a stack overflow (found by the fuzzer); a
// reasonable depth still works.
TEST(ShadePreprocessor, DeeplyNestedConditionIsAnError) {
    const std::string deep = "#if " + std::string(5000, '(') + "1" + std::string(5000, ')') +
                             "\n#endif\nsurface t() {}\n";
    EXPECT_NE(Errors(deep).find("test.sl:1:1: error: invalid #if expression"), std::string::npos);
    const std::string unary = "#if " + std::string(5000, '!') + "1\n#endif\nsurface t() {}\n";
    EXPECT_NE(Errors(unary).find("invalid #if expression"), std::string::npos);
    testing::CapturedDiagnostics d;
    const std::string fine =
        "#if " + std::string(50, '(') + "1" + std::string(50, ')') + "\nsurface t() {}\n#endif\n";
    EXPECT_TRUE(testing::Compile(fine, d)) << d.Text();
}

TEST(ShadePreprocessor, DefinesConditionalsAndLineNumbers) {
    auto r = testing::Shade(
        "#define SCALE(x) ((x) * 2)\n"
        "#define ONE 1\n"
        "#if defined(ONE) && ONE + 1 == 2\n"
        "#define VALUE SCALE(3)\n"
        "#else\n"
        "#define VALUE 0\n"
        "#endif\n"
        "/* a comment\n   over lines */\n"
        "surface t() { Ci = VALUE; }\n",
        1, 1, "Ci");
    ASSERT_EQ(r.width, 3) << r.diagnostics;
    EXPECT_EQ(r.At(0, 0), 6);
    std::string e = Errors("#ifdef NOTHING\n#endif\n/* x\n*/\nsurface t() {\n  Ci = oops;\n}\n");
    EXPECT_NE(e.find("test.sl:6:8: error: unknown variable 'oops'"), std::string::npos) << e;
    e = Errors("#line 40 \"other.sl\"\nsurface t() { Ci = oops; }\n");
    EXPECT_NE(e.find("other.sl:40:20: error: unknown variable 'oops'"), std::string::npos) << e;
    e = Errors("#if 1\nsurface t() {}\n");
    EXPECT_NE(e.find("error: #if without #endif"), std::string::npos) << e;
    e = Errors("#include \"missing.h\"\nsurface t() {}\n");
    EXPECT_NE(e.find("test.sl:1:1: error: cannot find include file 'missing.h'"), std::string::npos)
        << e;
}

}  // namespace
}  // namespace gonio::sl
