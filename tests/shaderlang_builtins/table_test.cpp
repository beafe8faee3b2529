// The table itself: every row well-formed, no duplicate overloads, the checklist's P0/P1 names
// present.

#include <set>

#include "builtin_test_util.h"

namespace gonio::sl::testing {
namespace {

bool ValidCodes(const std::string& codes, bool allowVoid) {
    for (size_t i = 0; i < codes.size(); ++i) {
        char c = codes[i];
        if (c == '*') return i + 1 == codes.size();
        if (c == '[') {
            if (i + 1 >= codes.size() || codes[i + 1] != ']') return false;
            ++i;
            continue;
        }
        if (std::string("fscpvnmFSCPVNM").find(c) == std::string::npos &&
            !(allowVoid && c == 'x')) {
            return false;
        }
    }
    return true;
}

TEST(BuiltinTable, RowsAreWellFormedAndUnique) {
    std::set<std::string> seen;
    for (const BuiltinInfo& row : BuiltinTable()) {
        EXPECT_NE(row.kernel, nullptr) << row.name;
        EXPECT_EQ(std::string(row.returnType).size(), 1u) << row.name;
        EXPECT_TRUE(ValidCodes(row.returnType, true)) << row.name;
        EXPECT_TRUE(ValidCodes(row.arguments, false)) << row.name << "(" << row.arguments << ")";
        std::string key = std::string(row.name) + ":" + row.returnType + ":" + row.arguments;
        EXPECT_TRUE(seen.insert(key).second) << "duplicate row " << key;
    }
}

TEST(BuiltinTable, CoversTheChecklist) {
    std::set<std::string> names;
    for (const BuiltinInfo& row : BuiltinTable()) names.insert(row.name);
    for (const char* name :
         {"radians",    "degrees",     "sin",         "asin",        "cos",
          "acos",       "tan",         "atan",        "pow",         "exp",
          "sqrt",       "inversesqrt", "log",         "mod",         "abs",
          "sign",       "floor",       "ceil",        "round",       "min",
          "max",        "clamp",       "mix",         "step",        "smoothstep",
          "filterstep", "spline",      "Du",          "Dv",          "Deriv",
          "random",     "noise",       "pnoise",      "cellnoise",   "xcomp",
          "ycomp",      "zcomp",       "setxcomp",    "setycomp",    "setzcomp",
          "length",     "normalize",   "distance",    "ptlined",     "rotate",
          "area",       "faceforward", "reflect",     "refract",     "fresnel",
          "transform",  "vtransform",  "ntransform",  "depth",       "calculatenormal",
          "comp",       "setcomp",     "ctransform",  "luminance",   "determinant",
          "translate",  "scale",       "printf",      "format",      "concat",
          "match",      "ambient",     "diffuse",     "specular",    "specularbrdf",
          "phong",      "trace",       "texture",     "environment", "shadow",
          "attribute",  "option",      "rendererinfo"}) {
        EXPECT_TRUE(names.count(name)) << name;
    }
}

}  // namespace
}  // namespace gonio::sl::testing
