// The RIB type system: predeclared names, Declare, inline declarations, and clear errors.

#include "renderer/rib/declarations.h"

#include <gtest/gtest.h>

namespace gonio {
namespace {

ParamDecl MustResolve(const Declarations& declarations, const std::string& token) {
    std::string error;
    const std::optional<ParamDecl> decl = declarations.Resolve(token, &error);
    EXPECT_TRUE(decl.has_value()) << token << ": " << error;
    return decl.value_or(ParamDecl{});
}

std::string Describe(const ParamDecl& decl) {
    return decl.name + ": " + ToString(decl.cls) + " " + ToString(decl.type) + "[" +
           std::to_string(decl.arraySize) + "]";
}

TEST(Declarations, StandardNamesArePredeclared) {
    const Declarations d;
    EXPECT_EQ(Describe(MustResolve(d, "P")), "P: vertex point[1]");
    EXPECT_EQ(Describe(MustResolve(d, "Pz")), "Pz: vertex float[1]");
    EXPECT_EQ(Describe(MustResolve(d, "Pw")), "Pw: vertex hpoint[1]");
    EXPECT_EQ(Describe(MustResolve(d, "N")), "N: varying normal[1]");
    EXPECT_EQ(Describe(MustResolve(d, "Np")), "Np: uniform normal[1]");
    EXPECT_EQ(Describe(MustResolve(d, "Cs")), "Cs: varying color[1]");
    EXPECT_EQ(Describe(MustResolve(d, "Os")), "Os: varying color[1]");
    EXPECT_EQ(Describe(MustResolve(d, "s")), "s: varying float[1]");
    EXPECT_EQ(Describe(MustResolve(d, "st")), "st: varying float[2]");
    EXPECT_EQ(Describe(MustResolve(d, "width")), "width: varying float[1]");
    EXPECT_EQ(Describe(MustResolve(d, "constantwidth")), "constantwidth: constant float[1]");
    EXPECT_EQ(Describe(MustResolve(d, "texturename")), "texturename: uniform string[1]");
    EXPECT_EQ(Describe(MustResolve(d, "lightcolor")), "lightcolor: uniform color[1]");
    EXPECT_EQ(Describe(MustResolve(d, "from")), "from: uniform point[1]");
    EXPECT_EQ(Describe(MustResolve(d, "rays")), "rays: uniform integer[1]");
    EXPECT_EQ(Describe(MustResolve(d, "area")), "area: uniform float[1]");
    for (const char* name :
         {"Ka", "Kd", "Ks", "Kr", "roughness", "specularcolor", "intensity", "to", "coneangle",
          "conedeltaangle", "beamdistribution", "mindistance", "maxdistance", "background",
          "distance", "amplitude", "fov", "origin", "flatness"})
        MustResolve(d, name);
}

TEST(Declarations, DeclareWithEveryClassAndType) {
    Declarations d;
    std::string error;
    ASSERT_TRUE(d.Declare("a", "facevarying float[2]", &error)) << error;
    EXPECT_EQ(Describe(MustResolve(d, "a")), "a: facevarying float[2]");
    ASSERT_TRUE(d.Declare("b", "int", &error)) << error;  // class defaults to uniform
    EXPECT_EQ(Describe(MustResolve(d, "b")), "b: uniform integer[1]");
    ASSERT_TRUE(d.Declare("c", "constant matrix [ 3 ]", &error)) << error;
    EXPECT_EQ(Describe(MustResolve(d, "c")), "c: constant matrix[3]");
    for (const char* cls : {"constant", "uniform", "varying", "vertex", "facevarying"})
        for (const char* type : {"float", "integer", "string", "color", "point", "vector", "normal",
                                 "hpoint", "matrix"})
            EXPECT_TRUE(d.Declare("x", std::string(cls) + " " + type, &error)) << error;
}

TEST(Declarations, InlineDeclarationsDoNotDeclare) {
    const Declarations d;
    EXPECT_EQ(Describe(MustResolve(d, "varying color Cq")), "Cq: varying color[1]");
    EXPECT_EQ(Describe(MustResolve(d, "point from")), "from: uniform point[1]");
    EXPECT_EQ(Describe(MustResolve(d, "facevarying float[2] st")), "st: facevarying float[2]");
    std::string error;
    EXPECT_FALSE(d.Resolve("Cq", &error).has_value());
    EXPECT_EQ(error,
              "parameter \"Cq\" is not declared (use Declare or an inline type, e.g. \"uniform "
              "float Cq\")");
}

TEST(Declarations, ComponentCounts) {
    const Declarations d;
    EXPECT_EQ(MustResolve(d, "P").ComponentCount(3), 3);
    EXPECT_EQ(MustResolve(d, "Pw").ComponentCount(3), 4);
    EXPECT_EQ(MustResolve(d, "Cs").ComponentCount(5), 5);
    EXPECT_EQ(MustResolve(d, "st").ComponentCount(3), 2);
    EXPECT_EQ(MustResolve(d, "uniform matrix[2] m").ComponentCount(3), 32);
}

TEST(Declarations, BadDeclarationsSayWhy) {
    Declarations d;
    std::string error;
    EXPECT_FALSE(d.Declare("a", "varying flaot", &error));
    EXPECT_EQ(error,
              "bad declaration of \"a\": unknown type 'flaot' (expected [class] type ['[' n ']'], "
              "e.g. \"varying float[2]\")");
    EXPECT_FALSE(d.Declare("a", "float[0]", &error));
    EXPECT_EQ(error,
              "bad declaration of \"a\": bad array size in declaration \"float[0]\" (expected "
              "'[' n ']' with n a positive integer)");
    EXPECT_FALSE(d.Declare("a", "float[2", &error));
    EXPECT_FALSE(d.Declare("a", "varying", &error));
    EXPECT_EQ(error,
              "bad declaration of \"a\": the declaration has no type (expected [class] type ['[' "
              "n ']'], e.g. \"varying float[2]\")");
    EXPECT_FALSE(d.Declare("a", "float extra", &error));
    EXPECT_EQ(error, "bad declaration of \"a\": unexpected 'extra' in declaration \"float extra\"");
    EXPECT_FALSE(d.Declare("two words", "float", &error));
    EXPECT_FALSE(d.Resolve("varying florp Cq", &error).has_value());
    EXPECT_EQ(error,
              "bad inline declaration \"varying florp Cq\": unknown type 'florp' (expected "
              "[class] type ['[' n ']'], e.g. \"varying float[2]\")");
}

}  // namespace
}  // namespace gonio
