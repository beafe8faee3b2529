#pragma once
// Parameter lists as the RIB file spells them: a token and its values, not yet typed. Typing
// needs the Declare state, which belongs to the target (see declarations.h), so the parser and
// `gonio catrib` can pass lists through untouched.

#include <array>
#include <string>
#include <vector>

#include "base/file_loc.h"

namespace gonio {

struct Param {
    std::string token;  // as written: "Kd", "uniform float Kd", "facevarying float[2] st"
    // Numbers are kept as double so that integer data (indices, counts) survives exactly.
    std::vector<double> numbers;
    std::vector<std::string> strings;
    bool isString = false;  // the values were strings (an empty list counts as numbers)
    FileLoc loc;
};

using ParamList = std::vector<Param>;

// Transform and ConcatTransform matrices, row-major with row vectors (p' = p·M), as in RIB.
using RtMatrix = std::array<float, 16>;

// A basis named as in RIB ("bezier", "b-spline", ...) or given as a matrix (name empty).
struct RtBasis {
    std::string name;
    RtMatrix matrix{};
};

// Light and object handles: RIB 3.2 uses integer sequence numbers, later RIBs use strings.
struct RtHandle {
    std::string text;
    bool isString = false;
};

}  // namespace gonio
