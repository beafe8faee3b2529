// Every class of bad input gives a compiler-style message with file:line:col, the request in
// error is dropped, and parsing goes on with the next request.

#include <gtest/gtest.h>

#include "rib_test_util.h"

namespace gonio {
namespace {

struct ErrorCase {
    const char* rib;      // each ends with a good request, "WorldBegin", on its own line
    const char* message;  // the one diagnostic expected
};

const ErrorCase kCases[] = {
    {"Frobnicate 1 \"a\" [2]\nWorldBegin", "test.rib:1:1: error: unknown request 'Frobnicate'"},
    {"  Sphere 1 -1 1\nWorldBegin", "test.rib:1:3: error: Sphere expects 4 numbers, got 3"},
    {"Translate 1 2 3 4\nWorldBegin", "test.rib:1:1: error: Translate expects 3 numbers, got 4"},
    {"Sphere [1 -1 1]\nWorldBegin", "test.rib:1:8: error: Sphere expects 4 numbers, got 3"},
    {"Display \"out.tif\" \"file\"\nWorldBegin",
     "test.rib:1:1: error: Display expects 3 arguments, got 2"},
    {"LightSource 1 2\nWorldBegin",
     "test.rib:1:13: error: LightSource argument 1 must be a string, got a number"},
    {"PointsPolygons [3] [0 1.5 2]\nWorldBegin",
     "test.rib:1:20: error: PointsPolygons argument 2 must be an array of integers, got an "
     "array of 3 numbers"},
    {"Format 640.5 480 1\nWorldBegin",
     "test.rib:1:8: error: Format argument 1 must be an integer, got 640.5"},
    {"Surface \"plastic\nWorldBegin",
     "test.rib:1:9: error: unterminated string (strings end on the line they start on)"},
    {"Polygon \"P\" [0 \"a\" 1]\nWorldBegin",
     "test.rib:1:13: error: array mixes numbers and strings (an array holds one or the other)"},
    {"Polygon \"P\" [0 0 0\nWorldBegin",
     "test.rib:2:1: error: expected ']' to close the array opened at 1:13, found request "
     "'WorldBegin'"},
    {"Polygon \"P\" [0 [0] 0]\nWorldBegin",
     "test.rib:1:16: error: arrays cannot be nested (the array opened at 1:13 is still open)"},
    {"Sphere 1 -1 1 360 ]\nWorldBegin", "test.rib:1:19: error: ']' without a matching '['"},
    {"1 2 \"x\"\nWorldBegin", "test.rib:1:1: error: expected a request name, found a number"},
    {"Surface \"plastic\" \"Kd\"\nWorldBegin",
     "test.rib:1:19: error: parameter \"Kd\" has no value"},
    {"Surface \"plastic\" 0.5 1\nWorldBegin",
     "test.rib:1:19: error: expected a parameter name (a string) in the parameter list of "
     "Surface, got a number"},
    {"WorldEnd \"Kd\" 1\nWorldBegin", "test.rib:1:10: error: WorldEnd takes no parameter list"},
    {"Translate 1e999 0 0\nWorldBegin", "test.rib:1:11: error: number out of range: 1e999"},
    {"Translate @ 0 0\nWorldBegin", "test.rib:1:11: error: unexpected character '@'"},
    {"\x01\nWorldBegin", "test.rib:1:1: error: unexpected byte 0x01"},
};

class ErrorTest : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(ErrorTest, ReportsAndGoesOn) {
    const ParseResult result = ParseText(GetParam().rib);
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.errors, 1);
    EXPECT_EQ(result.messages, std::string(GetParam().message) + "\n");
    ASSERT_FALSE(result.target.calls.empty());
    EXPECT_EQ(result.target.calls.back(), "WorldBegin");  // parsing went on after the error
}

INSTANTIATE_TEST_SUITE_P(BadInput, ErrorTest, ::testing::ValuesIn(kCases));

TEST(Errors, GoodRequestsAroundABadOneAllArrive) {
    const ParseResult result = ParseText("WorldBegin\nSphere 1\nSphere 1 -1 1 360\nWorldEnd\n");
    EXPECT_EQ(result.errors, 1);
    EXPECT_EQ(result.target.Text(), "WorldBegin\nSphere 1 -1 1 360 {}\nWorldEnd\n");
}

TEST(Errors, ConsecutiveBadRequestsAreEachReported) {
    const ParseResult result = ParseText("Sphere ]\nSphere ]\nFoo\nWorldBegin\n");
    EXPECT_EQ(result.errors, 3) << result.messages;
    EXPECT_EQ(result.target.Text(), "WorldBegin\n");
}

TEST(Errors, StopsAfterTooManyErrors) {
    std::string rib;
    for (int i = 0; i < 500; ++i) rib += "Bogus\n";
    const ParseResult result = ParseText(rib + "WorldBegin\n");
    EXPECT_EQ(result.errors, 100);
    EXPECT_NE(result.messages.find("note: too many errors; the rest of the input is skipped"),
              std::string::npos);
    EXPECT_TRUE(result.target.calls.empty());
}

TEST(Errors, UnclosedArrayAtEndOfFile) {
    const ParseResult result = ParseText("WorldBegin\nPolygon \"P\" [0 0");
    EXPECT_EQ(result.messages,
              "test.rib:2:17: error: expected ']' to close the array opened at 2:13, found the "
              "end of the file\n");
    EXPECT_EQ(result.target.Text(), "WorldBegin\n");
}

TEST(Errors, UnreadableFileIsReported) {
    const ParseResult result = ParseFile("/nonexistent/scene.rib");
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.messages,
              "/nonexistent/scene.rib: error: cannot open the file: No such file or directory\n");
}

TEST(Errors, NeverCrashesOnTruncatedInput) {
    // Every prefix of a valid file parses without a crash (errors are fine).
    const std::string rib =
        "FrameBegin 1 Display \"a\\\"b\" \"file\" \"rgb\" WorldBegin Color [1 0 0]\n"
        "Surface \"plastic\" \"Kd\" .5 Sphere 1 -1 1 360 PointsPolygons [3] [0 1 2] "
        "\"P\" [0 0 0 1 0 0 0 1 0] WorldEnd FrameEnd\n";
    for (std::size_t n = 0; n <= rib.size(); ++n) ParseText(rib.substr(0, n));
}

}  // namespace
}  // namespace gonio
