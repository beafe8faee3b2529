// ParamDict: typed entries by bare name, later entries replacing earlier ones, read marks shared
// by copies, and the report of what nobody read.

#include "renderer/scene/param_dict.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "tests/support/captured_diagnostics.h"

namespace gonio {
namespace {

TypedParam Number(const char* name, double value) {
    TypedParam p;
    p.decl.name = name;
    p.numbers = {value};
    return p;
}

TypedParam Text(const char* name, const char* value) {
    TypedParam p;
    p.decl.name = name;
    p.decl.type = ParamType::String;
    p.strings = {value};
    return p;
}

FileLoc Line(int line) { return FileLoc{std::make_shared<const std::string>("s.rib"), line, 0}; }

// What ReportUnused prints for `dict`.
std::string Unused(const ParamDict& dict) {
    test::CapturedDiagnostics diagnostics;
    dict.ReportUnused("Option \"trace\"", diagnostics.Get());
    return diagnostics.Text();
}

TEST(ParamDict, TypedValuesByBareName) {
    ParamDict dict;
    dict.Set(Number("maxdepth", 7), Line(1));
    dict.Set(Text("shadows", "on"), Line(2));
    EXPECT_EQ(dict.GetInt("maxdepth", 0), 7);
    EXPECT_FLOAT_EQ(dict.GetFloat("maxdepth", 0), 7.0f);
    EXPECT_EQ(dict.GetString("shadows", "off"), "on");
    EXPECT_EQ(dict.GetInt("missing", 3), 3);
    EXPECT_EQ(dict.GetString("maxdepth", "none"), "none") << "a number is not a string";
    EXPECT_EQ(dict.Location("shadows").line, 2);
}

TEST(ParamDict, NumbersStayExact) {
    ParamDict dict;
    dict.Set(Number("seed", 123456789012.0), Line(1));
    EXPECT_EQ(dict.GetNumber("seed", 0), 123456789012.0);
}

TEST(ParamDict, ALaterEntryReplacesAnEarlierOne) {
    ParamDict dict;
    dict.Set(Number("maxdepth", 2), Line(1));
    dict.Set(Number("maxdepth", 5), Line(4));
    EXPECT_EQ(dict.GetInt("maxdepth", 0), 5);
    EXPECT_EQ(dict.Location("maxdepth").line, 4);
}

TEST(ParamDict, ReportsWhatNobodyRead) {
    ParamDict dict;
    dict.Set(Number("maxdepth", 2), Line(3));
    dict.Set(Number("maxdeph", 2), Line(4));
    dict.GetInt("maxdepth", 0);
    EXPECT_EQ(Unused(dict),
              "s.rib:4: warning: Option \"trace\" parameter \"maxdeph\" had no effect on this "
              "frame\n");
}

TEST(ParamDict, AnUnreadStandardParameterIsANote) {
    ParamDict dict;
    TypedParam gridsize = Number("gridsize", 256);
    gridsize.standard = true;
    dict.Set(gridsize, Line(2));
    EXPECT_EQ(Unused(dict),
              "s.rib:2: note: Option \"trace\" parameter \"gridsize\" had no effect on this "
              "frame\n");
}

TEST(ParamDict, CopiesShareTheirReadMarks) {
    ParamDict dict;
    dict.Set(Number("bias", 0.01), Line(2));
    const ParamDict copy = dict;
    copy.GetFloat("bias", 0);
    EXPECT_EQ(Unused(dict), "") << "read through a copy (another shape's attributes)";
}

TEST(ParamDict, LocationIsNotARead) {
    ParamDict dict;
    dict.Set(Number("bias", 0.01), Line(2));
    dict.Location("bias");
    EXPECT_NE(Unused(dict), "");
}

}  // namespace
}  // namespace gonio
