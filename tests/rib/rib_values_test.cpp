// Lexical details and value forms: numbers, strings and escapes, arrays, handles, colours with
// ColorSamples, positional arguments given as one array, and streaming through many requests.

#include <gtest/gtest.h>

#include "rib_test_util.h"

namespace gonio {
namespace {

std::string Calls(const std::string& rib) {
    const ParseResult result = ParseText(rib);
    EXPECT_EQ(result.messages, "") << rib;
    return result.target.Text();
}

TEST(Values, NumbersInEveryForm) {
    EXPECT_EQ(Calls("Translate 1 -2 +3"), "Translate 1 -2 3\n");
    EXPECT_EQ(Calls("Translate .5 -.25 5."), "Translate 0.5 -0.25 5\n");
    EXPECT_EQ(Calls("Translate 1e2 -2.5E-1 3e+1"), "Translate 100 -0.25 30\n");
    EXPECT_EQ(Calls("Translate 1e-400 0 0"), "Translate 0 0 0\n");  // underflow is zero
}

TEST(Values, ParameterNumbersKeepDoublePrecision) {
    // Indices and large integers survive exactly (Param::numbers is double).
    EXPECT_EQ(Calls("Polygon \"P\" [16777217 0.1]"), "Polygon {\"P\"=[16777217 0.1]}\n");
}

TEST(Values, NoSpaceNeededBetweenTokens) {
    EXPECT_EQ(Calls("Surface\"plastic\"\"Kd\"[.5]Sphere[1 -1 1 360]"),
              "Surface \"plastic\" {\"Kd\"=[0.5]}\nSphere 1 -1 1 360 {}\n");
}

TEST(Values, StringEscapes) {
    EXPECT_EQ(Calls(R"(Attribute "user" "string a" "q\"b\\s\tt\101\x42")"),
              "Attribute \"user\" {\"string a\"=[\"q\"b\\s\tt"
              "AB\"]}\n");
}

TEST(Values, ScalarOrBracketedParameterValues) {
    EXPECT_EQ(Calls("Surface \"matte\" \"Kd\" 0.5"), Calls("Surface \"matte\" \"Kd\" [0.5]"));
    EXPECT_EQ(Calls("Display \"a\" \"file\" \"rgb\" \"string compression\" [\"lzw\"]"),
              Calls("Display \"a\" \"file\" \"rgb\" \"string compression\" \"lzw\""));
}

TEST(Values, EmptyArrays) { EXPECT_EQ(Calls("Polygon \"P\" []"), "Polygon {\"P\"=[]}\n"); }

TEST(Values, ScalarArgumentsMayBeOneElementArrays) {
    EXPECT_EQ(Calls("Sides [2]"), "Sides 2\n");
    EXPECT_EQ(Calls("Surface [\"matte\"]"), "Surface \"matte\" {}\n");
}

TEST(Values, ColorFollowsColorSamples) {
    EXPECT_EQ(Calls("ColorSamples [1 1 1 0 0 0] [1 0 0 1 0 0]\nColor 0.5 0.25\nOpacity [1 1]"),
              "ColorSamples [1 1 1 0 0 0] [1 0 0 1 0 0]\nColor [0.5 0.25]\nOpacity [1 1]\n");
    EXPECT_EQ(Calls("ColorSamples 1 [1 1 1] [1 1 1]\nColor [0.5]"),
              "ColorSamples [1 1 1] [1 1 1]\nColor [0.5]\n");
    const ParseResult result = ParseText("ColorSamples [1 1 1] [1 1 1]\nColor 1 1 1");
    EXPECT_EQ(result.messages, "test.rib:2:1: error: Color expects 1 number, got 3\n");
}

TEST(Values, InlineDeclarationsPassThroughUntouched) {
    EXPECT_EQ(Calls("Patch \"bilinear\" \"facevarying float[2] st\" [0 0 1 0 0 1 1 1]"),
              "Patch \"bilinear\" {\"facevarying float[2] st\"=[0 0 1 0 0 1 1 1]}\n");
}

TEST(Values, ManyRequestsStreamThrough) {
    std::string rib;
    for (int i = 0; i < 2000; ++i)
        rib += "Translate " + std::to_string(i) + " 0 0 Surface \"s" + std::to_string(i) +
               "\" \"Kd\" [" + std::to_string(i) + "]\n";
    const ParseResult result = ParseText(rib);
    ASSERT_EQ(result.target.calls.size(), 4000u);
    EXPECT_EQ(result.target.calls[3998], "Translate 1999 0 0");
    EXPECT_EQ(result.target.calls[3999], "Surface \"s1999\" {\"Kd\"=[1999]}");
}

TEST(Values, CarriageReturnsAreWhiteSpace) {
    EXPECT_EQ(Calls("WorldBegin\r\nWorldEnd\r\n"), "WorldBegin\nWorldEnd\n");
}

}  // namespace
}  // namespace gonio
