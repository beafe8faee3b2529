#pragma once
// RiBlobby (RISpec 3.2 §5.6): an implicit surface, the level set 0.5 of the field the code
// array builds (blobby_program.h, blobby_field.h), tessellated into a triangle mesh by surface
// nets (surface_nets.h) with every vertex on the exact surface and shading normals from the
// field's analytic gradient.
//
// Why a tessellation and not a ray-marched user geometry: the mesh path already gives Embree's
// BVH, area lights, motion blur of the object, shading normals and per-vertex primitive
// variables; an exact intersection would need a guaranteed root finder (interval or Lipschitz
// bounds through every operation, including divide) per ray, per shadow ray, per bounce. The
// mesh's only error is its flat facets between exact vertices: with cells of an eighth of
// the smallest leaf's radius (at ShadingRate 1) a sphere's facets stray from it by well under
// 1% of its radius (tests/geometry_meshes/blobby_test.cpp), and shading normals hide them.
//
// Resolution: cells of side (smallest leaf surface radius) / (kCellsPerRadius / √ShadingRate),
// enlarged until the blocks of 8³ points the leaves' supports reach hold at most kGridBudget
// points (and the grid at most kBlockBudget blocks). The other blocks are neither sampled nor
// stored.
//
// Primitive variables: constant and uniform ones as given; vertex, varying (and facevarying)
// ones have one value per leaf, blended at each mesh vertex by BlobbyField::LeafWeights.

#include <string>
#include <vector>

#include "renderer/geometry/blobby_depth_map.h"
#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

struct BlobbyTessellation {
    static constexpr float kCellsPerRadius = 8;
    static constexpr long kGridBudget = 1L << 22;
    static constexpr long kBlockBudget = 1L << 22;
    float shadingRate = 1;

    // The cell side for leaves whose smallest surface radius is `feature`, whose supports are
    // `supports`, in their bound `box`.
    float CellSize(float feature, const std::vector<Box3f>& supports, const Box3f& box) const;
};

struct BlobbyMesh {
    TriangleMesh mesh;  // empty when the field has no ellipsoid or segment (nothing closed)
    long sampledPoints = 0;
    float cell = 0;  // the grid's cell side
};

// `notes` receives warnings (see DecodeBlobby) and says when nothing was rendered.
// `findDepthMap` gives each repelling plane its depth map; without one, or where it finds none,
// the plane is z = 0 of object space, with a note.
GeometryResult<BlobbyMesh> MakeBlobby(int nleaf, const std::vector<int>& code,
                                      const std::vector<float>& floats,
                                      const std::vector<std::string>& strings,
                                      const PrimVarSet& vars, const BlobbyTessellation& rates,
                                      std::vector<std::string>* notes,
                                      const BlobbyDepthMapLookup& findDepthMap = {});

}  // namespace gonio
