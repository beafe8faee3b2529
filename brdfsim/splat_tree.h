#pragma once
// A bounding-box tree over the splat centres, so that a grid lookup visits only the splats near
// the query instead of every entry of its cell (issue 4). The sum it computes is the one of
// SplatSet::Accumulate over every splat image that reaches the query (the same float terms,
// summed in double), only found faster:
// * the splats are copied in leaf order into structure-of-arrays blocks of kLeafSize, so a leaf
//   is one straight, branch-free loop that the compiler vectorises (no gather, no indirection);
// * a subtree is skipped when a lower bound of its distance to the query, in the splat's norm,
//   is at least R (exact: chord lengths bound great-circle distances from below);
// * on x86-64 the traversal is compiled twice (AVX2 and the baseline SSE2) and picked at run time
//   (GCC/Clang target_clones), so the default build stays portable.
// Built at load time from the splat set: the .grd format does not change.

#include <cstdint>
#include <vector>

#include "splat_set.h"

namespace gonio {

class SplatTree {
  public:
    static constexpr int kLeafSize = 32;

    SplatTree() = default;
    explicit SplatTree(const SplatSet& splats);

    // Adds Σ over active images v of query q and over all splats k of splats.Accumulate(k, v, q)
    // to acc[0..ncomps). Thread-safe.
    void Accumulate(const SplatQuery& q, double* acc) const;

    std::size_t MemoryBytes() const;
    std::size_t NumNodes() const { return nodes_.size(); }

    // Public for the traversal kernels in splat_tree.cpp.
    struct alignas(64) Node {
        float lo[6],
            hi[6];  // box of the centres: in x, y, z (θ_in for isotropic sets), out x, y, z
        std::uint32_t skip;  // next node once this subtree is done
        std::uint32_t leaf;  // first block + 1 for a leaf, 0 for an inner node (its child follows)
        std::uint32_t pad[2];
    };
    // One leaf's splats, structure of arrays. Unused slots lie far outside every query's reach
    // and weigh nothing.
    struct Coordinates {
        std::vector<float> inX, inY, inZ, outX, outY, outZ;  // inX holds θ_in for isotropic sets
    };

  private:
    int ncomps_ = 0;
    bool isotropic_ = false;
    Norm norm_ = Norm::kL2;
    float radius_ = 0.0f, chordRadius2_ = 0.0f, invRadius_ = 0.0f;
    std::vector<Node> nodes_;  // depth first; the root first
    Coordinates centres_;
    std::vector<float> weights_;  // per leaf, per component, kLeafSize values
};

}  // namespace gonio
