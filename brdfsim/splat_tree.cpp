#include "splat_tree.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace gonio {
namespace {

constexpr int kLeaf = SplatTree::kLeafSize;
// Float partial sums per leaf: kLeaf / kLanes terms each (positive, so within that many float
// roundings of the sum), then double.
constexpr int kLanes = 8;
// Unused leaf slots: no query comes within any radius of them.
constexpr float kFarAway = 1e4f;
// Skipping a subtree needs its lower bound clearly past R: float rounding in the bound must never
// skip a splat the exact per-splat test would keep (keeping one too many costs nothing).
constexpr double kReachSlack = 1e-4;

// Everything the traversal calls is forced inline: a call from the AVX2 copy into a function
// compiled for the baseline would cost more than the function.
#define GONIO_INLINE inline __attribute__((always_inline))

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
// One copy of the traversal per instruction set, chosen once at load time (GCC ifunc). AVX2 has
// no FMA, so both copies compute the same float terms.
#define GONIO_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define GONIO_SIMD_CLONES
#endif

// What the traversal reads, in plain pointers.
struct TreeView {
    const SplatTree::Node* nodes;
    std::uint32_t numNodes;
    const float *inX, *inY, *inZ, *outX, *outY, *outZ, *weights;
    int ncomps;
    float chordRadius2, invRadius;
    float reach, chordReach2;  // R and the squared chord of R, with slack, for skipping
};

// One image of the query (SplatQuery's index v). in[0] is θ_in for isotropic sets.
struct QueryImage {
    float in[3], out[3];
};

// condition ? a : b as a bit mask. GCC 12 will not if-convert the float select of the wide asin
// (nor the L∞ one), and then leaves the whole leaf loop scalar.
GONIO_INLINE float Select(bool condition, float a, float b) {
    std::uint32_t bitsA, bitsB;
    std::memcpy(&bitsA, &a, sizeof a);
    std::memcpy(&bitsB, &b, sizeof b);
    const std::uint32_t mask = condition ? ~0u : 0u;
    const std::uint32_t bits = (bitsA & mask) | (bitsB & ~mask);
    float result;
    std::memcpy(&result, &bits, sizeof result);
    return result;
}

// FastAsin (splat_set.h) written without branches, the same float operations in the same order,
// so both give the same bits. `kWide` false: only x <= 0.5 can occur (R <= π/3).
template <bool kWide>
GONIO_INLINE float AsinNoBranch(float x) {
    auto series = [](float z, float s) {
        return ((((4.2163199048e-2f * z + 2.4181311049e-2f) * z + 4.5470025998e-2f) * z +
                 7.4953002686e-2f) *
                    z +
                1.6666752422e-1f) *
                   z * s +
               s;
    };
    const float narrow = series(x * x, x);
    if constexpr (!kWide) {
        return narrow;
    } else {
        const float z = 0.5f * (1.0f - x);
        const float wide = 1.5707963267948966f - 2.0f * series(z, std::sqrt(z));
        return Select(x > 0.5f, wide, narrow);
    }
}

// GreatCircleFromChord2 (splat_set.h) over R.
template <bool kWide>
GONIO_INLINE float ScaledDistance(float chord2, float invRadius) {
    return 2.0f * AsinNoBranch<kWide>(0.5f * std::sqrt(chord2)) * invRadius;
}

template <Norm kNorm>
GONIO_INLINE float CombinedSquared(float dIn, float dOut) {
    if constexpr (kNorm == Norm::kL1) {
        return (dIn + dOut) * (dIn + dOut);
    } else if constexpr (kNorm == Norm::kL2) {
        return dIn * dIn + dOut * dOut;
    } else {
        const float d = std::max(dIn, dOut);  // the same square as Accumulate's choice
        return d * d;
    }
}

// SplatSet::Accumulate's kernel value for the kLeaf splats of one leaf, 0 where it skips a splat.
// A straight loop with selects only, which the compiler vectorises.
template <bool kIso, Norm kNorm, bool kWide>
GONIO_INLINE void LeafKernel(const TreeView& t, std::size_t base, const QueryImage& q,
                             float* __restrict kern) {
    const float* __restrict inX = t.inX + base;
    const float* __restrict inY = t.inY + base;
    const float* __restrict inZ = t.inZ + base;
    const float* __restrict outX = t.outX + base;
    const float* __restrict outY = t.outY + base;
    const float* __restrict outZ = t.outZ + base;
    for (int j = 0; j < kLeaf; ++j) {
        const float ox = q.out[0] - outX[j], oy = q.out[1] - outY[j], oz = q.out[2] - outZ[j];
        const float chordOut2 = ox * ox + oy * oy + oz * oz;
        bool inside = chordOut2 < t.chordRadius2;
        float dIn;
        if constexpr (kIso) {
            dIn = std::abs(q.in[0] - inX[j]) * t.invRadius;
            inside = inside & (dIn < 1.0f);
        } else {
            const float ix = q.in[0] - inX[j], iy = q.in[1] - inY[j], iz = q.in[2] - inZ[j];
            const float chordIn2 = ix * ix + iy * iy + iz * iz;
            inside = inside & (chordIn2 < t.chordRadius2);
            dIn = ScaledDistance<kWide>(chordIn2, t.invRadius);
        }
        const float dOut = ScaledDistance<kWide>(chordOut2, t.invRadius);
        const float k2 = CombinedSquared<kNorm>(dIn, dOut);
        // thesis eq. 4.4 on the squared argument (SplatKernelSquared)
        const float value = 1.0f + k2 * (-22.0f / 9.0f + k2 * (17.0f / 9.0f - k2 * (4.0f / 9.0f)));
        kern[j] = inside & (k2 < 1.0f) & (value > 0.0f) ? value : 0.0f;
    }
}

GONIO_INLINE float BoxDistance(float q, float lo, float hi) {
    return std::max(0.0f, std::max(lo - q, q - hi));
}

GONIO_INLINE float BoxDistance2(const float* q, const float* lo, const float* hi) {
    const float x = BoxDistance(q[0], lo[0], hi[0]), y = BoxDistance(q[1], lo[1], hi[1]),
                z = BoxDistance(q[2], lo[2], hi[2]);
    return x * x + y * y + z * z;
}

// True when no splat of the subtree reaches the query. The box distances bound the chords from
// below, and a great-circle distance is at least its chord, so combining the bounds in the
// splat's norm bounds the product-domain distance from below.
template <bool kIso, Norm kNorm>
GONIO_INLINE bool Unreachable(const TreeView& t, const SplatTree::Node& n, const QueryImage& q) {
    const float out2 = BoxDistance2(q.out, n.lo + 3, n.hi + 3);
    if (out2 > t.chordReach2) return true;
    float in2;
    if constexpr (kIso) {
        const float d = BoxDistance(q.in[0], n.lo[0], n.hi[0]);
        in2 = d * d;
    } else {
        in2 = BoxDistance2(q.in, n.lo, n.hi);
        if (in2 > t.chordReach2) return true;
    }
    if constexpr (kNorm == Norm::kL1) {
        return std::sqrt(in2) + std::sqrt(out2) > t.reach;
    } else if constexpr (kNorm == Norm::kL2) {
        return in2 + out2 > t.reach * t.reach;
    } else {
        return in2 > t.reach * t.reach;
    }
}

// Depth first, skipping unreachable subtrees; each leaf adds its float terms to per-slot double
// sums (lanes[c * kLeaf + j]), as Accumulate adds each term to a double.
template <bool kIso, Norm kNorm, bool kWide>
GONIO_INLINE void Traverse(const TreeView& t, const QueryImage& q, double* __restrict lanes) {
    alignas(64) float kern[kLeaf];
    for (std::uint32_t node = 0; node < t.numNodes;) {
        const SplatTree::Node& n = t.nodes[node];
        if (Unreachable<kIso, kNorm>(t, n, q)) {
            node = n.skip;
            continue;
        }
        if (n.leaf == 0) {
            ++node;
            continue;
        }
        const std::size_t block = n.leaf - 1;
        LeafKernel<kIso, kNorm, kWide>(t, block * kLeaf, q, kern);
        for (int c = 0; c < t.ncomps; ++c) {
            const float* __restrict w = t.weights + (block * t.ncomps + c) * kLeaf;
            float partial[kLanes] = {};
            for (int g = 0; g < kLeaf; g += kLanes) {
                for (int j = 0; j < kLanes; ++j) partial[j] += kern[g + j] * w[g + j];
            }
            double* __restrict lane = lanes + c * kLanes;
            for (int j = 0; j < kLanes; ++j) lane[j] += static_cast<double>(partial[j]);
        }
        node = n.skip;
    }
}

template <bool kIso, bool kWide>
GONIO_INLINE void TraverseNorm(Norm norm, const TreeView& t, const QueryImage& q, double* lanes) {
    switch (norm) {
        case Norm::kL1:
            return Traverse<kIso, Norm::kL1, kWide>(t, q, lanes);
        case Norm::kL2:
            return Traverse<kIso, Norm::kL2, kWide>(t, q, lanes);
        case Norm::kLinf:
            return Traverse<kIso, Norm::kLinf, kWide>(t, q, lanes);
    }
}

GONIO_SIMD_CLONES
void SumImage(bool isotropic, Norm norm, const TreeView& t, const QueryImage& q, double* lanes) {
    const bool wide = t.chordRadius2 > 1.0f;  // R > π/3: FastAsin's second branch is reachable
    if (isotropic) {
        wide ? TraverseNorm<true, true>(norm, t, q, lanes)
             : TraverseNorm<true, false>(norm, t, q, lanes);
    } else {
        wide ? TraverseNorm<false, true>(norm, t, q, lanes)
             : TraverseNorm<false, false>(norm, t, q, lanes);
    }
}

struct Builder {
    const SplatSet& splats;
    std::vector<SplatTree::Node>& nodes;
    std::vector<std::uint32_t>& order;  // splat indices, in leaf order once built
    bool isotropic;

    float Coordinate(std::uint32_t k, int dim) const {
        const SplatGeometry& g = splats.geometry[k];
        switch (dim) {
            case 0:
                return isotropic ? g.thetaIn : g.inX;
            case 1:
                return g.inY;
            case 2:
                return g.inZ;
            case 3:
                return g.outX;
            case 4:
                return g.outY;
            default:
                return g.outZ;
        }
    }

    bool Used(int dim) const { return !isotropic || dim == 0 || dim >= 3; }

    // Subtree of `node` over order[begin, begin + count), whose leaves start at block firstBlock.
    void Build(std::uint32_t node, std::size_t begin, std::size_t count, std::size_t firstBlock) {
        SplatTree::Node& n = nodes[node];
        n = SplatTree::Node{};
        int widest = 0;
        float extent = -1.0f;
        for (int dim = 0; dim < 6; ++dim) {
            if (!Used(dim)) continue;
            float lo = Coordinate(order[begin], dim), hi = lo;
            for (std::size_t i = begin + 1; i < begin + count; ++i) {
                const float x = Coordinate(order[i], dim);
                lo = std::min(lo, x);
                hi = std::max(hi, x);
            }
            n.lo[dim] = lo;
            n.hi[dim] = hi;
            if (hi - lo > extent) extent = hi - lo, widest = dim;
        }
        const std::size_t blocks = (count + kLeaf - 1) / kLeaf;
        n.skip = static_cast<std::uint32_t>(node + 2 * blocks - 1);
        if (blocks == 1) {
            n.leaf = static_cast<std::uint32_t>(firstBlock + 1);
            return;
        }
        // Split at the median of the widest side, rounded to whole leaves, so that only the last
        // leaf of the set is partly empty.
        const std::size_t leftBlocks = blocks / 2, leftCount = leftBlocks * kLeaf;
        auto first = order.begin() + static_cast<std::ptrdiff_t>(begin);
        std::nth_element(first, first + static_cast<std::ptrdiff_t>(leftCount),
                         first + static_cast<std::ptrdiff_t>(count),
                         [&](std::uint32_t a, std::uint32_t b) {
                             const float ca = Coordinate(a, widest), cb = Coordinate(b, widest);
                             return ca < cb || (ca == cb && a < b);
                         });
        const auto left = [&] { Build(node + 1, begin, leftCount, firstBlock); };
        const auto right = [&] {
            Build(static_cast<std::uint32_t>(node + 2 * leftBlocks), begin + leftCount,
                  count - leftCount, firstBlock + leftBlocks);
        };
        if (count > 65536) {
            tbb::parallel_invoke(left, right);
        } else {
            left();
            right();
        }
    }
};

}  // namespace

SplatTree::SplatTree(const SplatSet& splats)
    : ncomps_(splats.NumComponents()),
      isotropic_(splats.Params().isotropic),
      norm_(splats.Params().norm),
      radius_(static_cast<float>(splats.Params().radius)),
      chordRadius2_(splats.chordRadius2),
      invRadius_(splats.invRadius) {
    const std::size_t size = splats.Size();
    if (size == 0) return;
    const std::size_t blocks = (size + kLeaf - 1) / kLeaf;
    nodes_.resize(2 * blocks - 1);
    std::vector<std::uint32_t> order(size);
    std::iota(order.begin(), order.end(), 0u);
    Builder{splats, nodes_, order, isotropic_}.Build(0, 0, size, 0);

    const std::size_t slots = blocks * kLeaf;
    for (std::vector<float>* v : {&centres_.inX, &centres_.inY, &centres_.inZ, &centres_.outX,
                                  &centres_.outY, &centres_.outZ}) {
        v->assign(slots, kFarAway);
    }
    weights_.assign(slots * ncomps_, 0.0f);
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint32_t k = order[i];
        const SplatGeometry& g = splats.geometry[k];
        centres_.inX[i] = isotropic_ ? g.thetaIn : g.inX;
        centres_.inY[i] = g.inY;
        centres_.inZ[i] = g.inZ;
        centres_.outX[i] = g.outX;
        centres_.outY[i] = g.outY;
        centres_.outZ[i] = g.outZ;
        const std::size_t block = i / kLeaf, slot = i % kLeaf;
        for (int c = 0; c < ncomps_; ++c) {
            weights_[(block * ncomps_ + c) * kLeaf + slot] = splats.weights[k * ncomps_ + c];
        }
    }
}

void SplatTree::Accumulate(const SplatQuery& q, double* acc) const {
    if (nodes_.empty()) return;
    const double reach = radius_ * (1 + kReachSlack) + 1e-6;
    const double chordReach =
        std::sqrt(static_cast<double>(chordRadius2_)) * (1 + kReachSlack) + 1e-6;
    const TreeView view{nodes_.data(),
                        static_cast<std::uint32_t>(nodes_.size()),
                        centres_.inX.data(),
                        centres_.inY.data(),
                        centres_.inZ.data(),
                        centres_.outX.data(),
                        centres_.outY.data(),
                        centres_.outZ.data(),
                        weights_.data(),
                        ncomps_,
                        chordRadius2_,
                        invRadius_,
                        static_cast<float>(reach),
                        static_cast<float>(chordReach * chordReach)};
    double fixed[4 * kLanes];
    std::vector<double> wide(ncomps_ > 4 ? ncomps_ * kLanes : 0);
    double* lanes = ncomps_ > 4 ? wide.data() : fixed;
    std::fill(lanes, lanes + ncomps_ * kLanes, 0.0);
    for (int v = 0; v < 6; ++v) {
        if (!(q.activeMask & (1u << v))) continue;
        const QueryImage image{{isotropic_ ? q.thetaIn[v] : q.inX[v], q.inY[v], q.inZ[v]},
                               {q.outX[v], q.outY[v], q.outZ[v]}};
        SumImage(isotropic_, norm_, view, image, lanes);
    }
    for (int c = 0; c < ncomps_; ++c) {
        double sum = 0.0;
        for (int j = 0; j < kLanes; ++j) sum += lanes[c * kLanes + j];
        acc[c] += sum;
    }
}

std::size_t SplatTree::MemoryBytes() const {
    return nodes_.size() * sizeof(Node) +
           sizeof(float) * (centres_.inX.size() * 6 + weights_.size());
}

}  // namespace gonio
