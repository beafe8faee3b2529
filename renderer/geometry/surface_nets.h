#pragma once
// Polygonizing the level set F = 0 of a scalar field (inside where F > 0) by naive surface nets
// (Gibson 1998, "Constrained elastic surface nets"; the dual of marching cubes): the field is
// sampled on a regular grid; every cell whose corners change sign gets one vertex, and every
// grid edge whose ends change sign becomes a quad joining the four cells around it. There is
// no case table, the mesh is watertight wherever the surface stays inside the grid, and each
// vertex is moved onto the surface by Newton steps along the field's gradient, so vertices lie
// on the exact surface and only the facets between them approximate it.
//
// Blocks of cells that cannot hold the surface (the caller says which) are neither sampled nor
// stored, so a field whose surface fills little of its bound costs little more than that
// surface, in time and in memory.

#include <cstdint>
#include <functional>
#include <vector>

#include "renderer/geometry/shape.h"

namespace gonio {

// Points and cells per block side: the unit of skipping.
constexpr int kSurfaceNetsBlock = 8;

// F and its gradient at a point.
using IsoEvaluator = std::function<void(const V3f& p, float* value, V3f* gradient)>;

struct IsoField {
    // An evaluator for points inside `box`, or an empty one when F < 0 throughout the box for
    // certain (the block is then not sampled).
    std::function<IsoEvaluator(const Box3f& box)> near;
};

struct IsoMesh {
    std::vector<V3f> positions;
    std::vector<V3f> gradients;     // ∇F at each position
    std::vector<uint32_t> indices;  // three per triangle; (b − a) × (c − a) points to F < 0
    long sampledPoints = 0;         // grid points evaluated (the cost)
};

// The surface inside `box` on cubic cells of side `cell` (one more cell of margin around the
// box, so that a surface inside the box closes).
IsoMesh PolygonizeSurfaceNets(const IsoField& field, const Box3f& box, float cell);

}  // namespace gonio
