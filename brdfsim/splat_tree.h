#pragma once
// A bounding-box tree over the splat centres, so that a grid lookup visits only the splats near
// the query instead of every entry of its cell (issue 4). The sum it computes is the one of
// SplatSet::Accumulate over every splat image that reaches the query (the same float terms, from
// SplatKernelFromChords, summed in double), only found faster:
// * the tree is 8 wide: a node holds its children's boxes side by side, so one vector pass tests
//   all eight and the traversal takes few, well-predicted branches;
// * a child is skipped when a lower bound of its distance to the query, in the splat's norm, is
//   at least R (exact: chord lengths bound great-circle distances from below);
// * the splats are copied in leaf order into blocks of kLeafSize, structure of arrays, centres and
//   weights side by side, so a leaf is one straight, branch-free loop that the compiler
//   vectorises (no gather, no indirection) over memory read in order;
// * the walk is breadth first, fetching a few nodes ahead in its queue, and appends a node's
//   reached children to the queue and the leaf batch by one shuffle each, without a branch;
// * a grey set (every splat's components equal) keeps one weight a splat;
// * on x86-64 the traversal is compiled for AVX-512, AVX2 and the baseline SSE2 and picked at run
//   time (GCC target_clones), so the default build stays portable.
// Built at load time from the splat set: the .grd format does not change.

#include <cstdint>
#include <vector>

#include "brdfsim/splat_set.h"

namespace gonio {

class SplatTree {
  public:
    // Two AVX-512 vectors. Measured on the 300k brushed-metal case (issue 4): 16 evaluates a
    // fifth fewer splats out of reach but costs more per splat, in box tests and per-leaf work.
    static constexpr int kLeafSize = 32;
    static constexpr int kWidth = 8;  // children per node

    SplatTree() = default;
    explicit SplatTree(const SplatSet& splats);

    // Adds Σ over active images v of query q and over all splats k of splats.Accumulate(k, v, q)
    // to acc[0..ncomps). Thread-safe.
    void Accumulate(const SplatQuery& q, double* acc) const;

    std::size_t MemoryBytes() const;
    std::size_t NumNodes() const { return nodes_.size(); }

    // Public for the traversal kernels in splat_tree.cpp.
    static constexpr std::uint32_t kLeafFlag = 0x80000000u;
    struct alignas(64) Node {
        // The children's boxes of their centres, per coordinate: in x, y, z (θ_in, 0, 0 for
        // isotropic sets), out x, y, z. Unused slots hold a box far outside every query's reach.
        float lo[6][kWidth], hi[6][kWidth];
        std::uint32_t child[kWidth];  // a node index, or kLeafFlag | leaf index
    };

  private:
    // Components stored per splat: one when every splat is grey.
    int StoredComponents() const { return grey_ ? 1 : ncomps_; }
    // Floats per leaf: kLeafSize values of each coordinate and stored component.
    std::size_t LeafStride() const;

    int ncomps_ = 0;
    bool grey_ = false;  // every splat's components are equal
    bool isotropic_ = false;
    Norm norm_ = Norm::kL2;
    float radius_ = 0.0f, chordRadius2_ = 0.0f, invRadius_ = 0.0f;
    std::size_t numLeaves_ = 0;
    std::vector<Node> nodes_;  // the root first
    // Per leaf: kLeafSize values of each coordinate (6, or 4 for isotropic sets: θ_in, out x,
    // y, z), then of each weight component. Unused slots lie far outside every query's reach and
    // weigh nothing.
    std::vector<float> leaves_;
};

}  // namespace gonio
