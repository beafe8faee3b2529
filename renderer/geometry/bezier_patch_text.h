#pragma once
// Reads a set of bicubic Bézier patches from the text format of data/teapot.txt: '#' comment
// lines, then 'vertices N' and N lines 'x y z', then 'patches M' and M lines 'name i0 ... i15'
// (0-based vertex indices of the 4 × 4 control points, row by row, u fastest).

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

struct BezierPatch {
    std::string name;
    std::array<V3f, 16> controlPoints;  // u fastest
};

// A message naming the line of the first thing wrong, for text that does not follow the format
// (a missing count, a short line, an index out of range, trailing text).
GeometryResult<std::vector<BezierPatch>> ParseBezierPatchText(std::string_view text);

}  // namespace gonio
