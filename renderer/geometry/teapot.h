#pragma once
// RISpec §5.7 Geometry "teapot": the standard Newell teapot, z up, standing on z = 0 and 3.15
// high, as its 32 bicubic Bézier patches (data/teapot.txt, embedded at build time) tessellated
// by MakePatch, one triangle mesh per patch with (u, v) over that patch.

#include <vector>

#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"
#include "renderer/geometry/tensor_grid.h"

namespace gonio {

GeometryResult<std::vector<TriangleMesh>> MakeTeapot(const TessellationRates& rates = {});

}  // namespace gonio
