#include "brdfsim/splat_tree.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <numeric>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace gonio {
namespace {

constexpr int kLeaf = SplatTree::kLeafSize;
static_assert(kLeaf % 16 == 0, "leaves are summed 16 slots at a time");
constexpr int kWidth = SplatTree::kWidth;
// Unused slots and boxes: no query comes within any radius of them.
constexpr float kFarAway = 1e4f;
// Skipping a subtree needs its lower bound clearly past R: float rounding in the bound must never
// skip a splat the exact per-splat test would keep (keeping one too many costs nothing).
constexpr double kReachSlack = 1e-4;
// Reachable leaves are gathered in batches, so that the box tests and the leaf loop run apart.
constexpr int kBatch = 64;
// The walk fetches the node this many places ahead in its queue while it tests one: far enough
// for the fetch to arrive from L2 or L3 in time (measured on brushed metal: 2 to 8 do as well).
constexpr std::size_t kPrefetchAhead = 4;

// Everything the traversal calls is forced inline: a call from the AVX2 copy into a function
// compiled for the baseline would cost more than the function.
#define GONIO_INLINE inline __attribute__((always_inline))

#if defined(GONIO_SPLAT_TREE_ONLY_AVX2)
// One copy alone, for the tests of the copies a machine would not pick (tests/brdfsim).
#define GONIO_SIMD_CLONES __attribute__((target("avx2")))
#elif defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(GONIO_SPLAT_TREE_ONLY_BASELINE)
// One copy of the traversal per instruction set, chosen once at load time (GCC ifunc).
#define GONIO_SIMD_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define GONIO_SIMD_CLONES
#endif

constexpr int NumCoordinates(bool isotropic) { return isotropic ? 4 : 6; }

// What the traversal reads, in plain pointers.
struct TreeView {
    const SplatTree::Node* nodes;
    std::size_t numNodes;
    const float* leaves;
    std::size_t leafStride;   // floats per leaf
    std::uint32_t emptyLeaf;  // far from everything, weighing nothing
    int ncomps;
    float chordRadius2, invRadius2;
    float reach, chordReach2;  // R and the squared chord of R, with slack, for skipping
};

// One image of the query (SplatQuery's index v). in[0] is θ_in for isotropic sets.
struct QueryImage {
    float in[3], out[3];
};

// Eight floats, ints or doubles, GCC's generic vectors: one AVX register, two SSE ones in the
// baseline.
typedef float Floats8 __attribute__((vector_size(32)));
typedef float Floats16 __attribute__((vector_size(64)));
typedef std::int32_t Ints8 __attribute__((vector_size(32)));
typedef double Doubles8 __attribute__((vector_size(64)));

// The helpers take and give vectors by reference only: by value, the baseline copy of a function
// would pass them differently from the AVX copies (GCC's -Wpsabi).

// sum += a[0..16) · b[0..16)
GONIO_INLINE void AddProducts(Floats16& sum, const float* a, const float* b) {
    Floats16 x, y;
    std::memcpy(&x, a, sizeof x);
    std::memcpy(&y, b, sizeof y);
    sum += x * y;
}

// sum += both halves of x, in double.
GONIO_INLINE void AddToDoubles(Doubles8& sum, const Floats16& x) {
    Floats8 low, high;
    std::memcpy(&low, &x, sizeof low);
    std::memcpy(&high, reinterpret_cast<const char*>(&x) + sizeof low, sizeof high);
    sum += __builtin_convertvector(low, Doubles8);
    sum += __builtin_convertvector(high, Doubles8);
}

// sum2 += (distance from x to [lo, hi])², per lane.
GONIO_INLINE void AddAxisDistance2(Floats8& sum2, const float* lo, const float* hi, float x) {
    Floats8 below, above;
    std::memcpy(&below, lo, sizeof below);
    std::memcpy(&above, hi, sizeof above);
    below -= x;
    above = x - above;
    Floats8 d = below > above ? below : above;
    d = d > 0.0f ? d : Floats8{};
    sum2 += d * d;
}

// Bit j set where lane j of m (all ones or zero) is set: the sign bits, read four at a time on
// x86-64 (SSE's movmskps, which every x86-64 has).
GONIO_INLINE unsigned BitMask(const Ints8& m) {
#if defined(__x86_64__)
    __m128 low, high;
    std::memcpy(&low, &m, sizeof low);
    std::memcpy(&high, reinterpret_cast<const char*>(&m) + sizeof low, sizeof high);
    return static_cast<unsigned>(_mm_movemask_ps(low) | (_mm_movemask_ps(high) << 4));
#else
    const Ints8 bits = m & Ints8{1, 2, 4, 8, 16, 32, 64, 128};
    unsigned mask = 0;
    for (int j = 0; j < 8; ++j) mask |= static_cast<unsigned>(bits[j]);
    return mask;
#endif
}

// Lower bounds of the chords from the query to the kWidth boxes of a node, squared, combined in
// the splat's norm and compared with R: bit j of the result is set when child j may be reached.
// The box distances bound the chords from below, and a great-circle distance is at least its
// chord.
template <bool kIso, Norm kNorm>
GONIO_INLINE unsigned ReachableChildren(const TreeView& t, const SplatTree::Node& n,
                                        const QueryImage& q) {
    static_assert(kWidth == 8, "one generic vector per coordinate");
    Floats8 in2 = {}, out2 = {};
    for (int dim = 0; dim < (kIso ? 1 : 3); ++dim)
        AddAxisDistance2(in2, n.lo[dim], n.hi[dim], q.in[dim]);
    for (int dim = 0; dim < 3; ++dim)
        AddAxisDistance2(out2, n.lo[3 + dim], n.hi[3 + dim], q.out[dim]);
    const float reach2 = t.reach * t.reach;
    // The isotropic θ_in offset is a distance itself, not a chord.
    Ints8 reach = (out2 <= t.chordReach2) & (in2 <= (kIso ? reach2 : t.chordReach2));
    if constexpr (kNorm == Norm::kL1) {
        // √in2 + √out2 <= R without square roots: R² - in2 - out2 >= 2 √(in2 out2).
        const Floats8 rest = reach2 - in2 - out2;
        reach &= (rest >= 0.0f) & (4.0f * in2 * out2 <= rest * rest);
    } else if constexpr (kNorm == Norm::kL2) {
        reach &= in2 + out2 <= reach2;
    }
    return BitMask(reach);
}

// What the traversal is compiled for: the domain, the norm, the polynomial for the distances and
// the number of colour components (0: any, summed through memory).
template <bool kIsotropic, Norm kNormUsed, ChordRange kRangeUsed, int kComponents>
struct Kind {
    static constexpr bool kIso = kIsotropic;
    static constexpr Norm kNorm = kNormUsed;
    static constexpr ChordRange kRange = kRangeUsed;
    static constexpr int kComps = kComponents;
};

// Leaves summed together: each leaf is a long chain of dependent operations (two polynomials in
// a row), and several chains side by side keep the vector units busy.
constexpr int kTogether = 2;

// SplatKernelFromChords for the kLeaf splats of one leaf: a straight loop the compiler vectorises.
template <typename K>
GONIO_INLINE void LeafKernel(const TreeView& t, const float* __restrict leaf, const QueryImage& q,
                             float* __restrict kern) {
    constexpr int kOut = K::kIso ? 1 : 3;  // first outgoing coordinate
    const float* __restrict out = leaf + kOut * kLeaf;
    for (int j = 0; j < kLeaf; ++j) {
        const float chordOut2 =
            Chord2(q.out[0] - out[j], q.out[1] - out[kLeaf + j], q.out[2] - out[2 * kLeaf + j]);
        float in2;
        if constexpr (K::kIso) {
            const float d = q.in[0] - leaf[j];
            in2 = d * d;
        } else {
            in2 =
                Chord2(q.in[0] - leaf[j], q.in[1] - leaf[kLeaf + j], q.in[2] - leaf[2 * kLeaf + j]);
        }
        kern[j] = SplatKernelFromChords<K::kRange, K::kNorm, K::kIso>(in2, chordOut2,
                                                                      t.chordRadius2, t.invRadius2);
    }
}

// Adds the terms of kTogether leaves, each kernel · weight in float as Accumulate computes it, to
// double sums per component and lane (sums[c]): the kTogether · kLeaf / 16 terms that share one
// of 16 float lanes are added in float first (positive, so within that many float roundings),
// then in double.
template <typename K>
GONIO_INLINE void SumLeaves(const TreeView& t, const float* const* leaves, const QueryImage& q,
                            Doubles8* __restrict sums) {
    alignas(64) float values[kTogether * kLeaf];
    for (int n = 0; n < kTogether; ++n) LeafKernel<K>(t, leaves[n], q, values + n * kLeaf);
    const int ncomps = K::kComps > 0 ? K::kComps : t.ncomps;
    for (int c = 0; c < ncomps; ++c) {
        Floats16 partial = {};
        for (int n = 0; n < kTogether; ++n) {
            const float* __restrict weights = leaves[n] + (NumCoordinates(K::kIso) + c) * kLeaf;
            for (int h = 0; h < kLeaf / 16; ++h) {
                AddProducts(partial, values + n * kLeaf + 16 * h, weights + 16 * h);
            }
        }
        AddToDoubles(sums[c], partial);
    }
}

GONIO_INLINE void PrefetchNode(const TreeView& t, std::uint32_t node) {
    const char* data = reinterpret_cast<const char*>(t.nodes + node);
    for (std::size_t line = 0; line < sizeof(SplatTree::Node); line += 64) {
        __builtin_prefetch(data + line);
    }
}

// Fetches a leaf's cache lines; with a known number of components their count is a constant, and
// the loop unrolls.
template <typename K>
GONIO_INLINE void PrefetchLeaf(const TreeView& t, const float* leaf) {
    constexpr std::size_t kStride = (NumCoordinates(K::kIso) + K::kComps) * kLeaf;
    const std::size_t stride = K::kComps > 0 ? kStride : t.leafStride;
    for (std::size_t line = 0; line < stride; line += 16) __builtin_prefetch(leaf + line);
}

// Sums the leaves of a batch, kTogether at a time, the last group filled up with the empty leaf
// (weights 0) after the real ones; the next group is fetched while one is summed.
template <typename K>
GONIO_INLINE void SumBatch(const TreeView& t, std::uint32_t* batch, int size, const QueryImage& q,
                           Doubles8* sums) {
    const std::uint32_t empty = t.emptyLeaf;
    while (size % kTogether) batch[size++] = empty;
    for (int i = 0; i < size; i += kTogether) {
        const float* leaves[kTogether];
        for (int n = 0; n < kTogether; ++n) leaves[n] = t.leaves + batch[i + n] * t.leafStride;
        if (i + kTogether < size) {
            for (int n = 0; n < kTogether; ++n) {
                PrefetchLeaf<K>(t, t.leaves + batch[i + kTogether + n] * t.leafStride);
            }
        }
        SumLeaves<K>(t, leaves, q, sums);
    }
}

// For each 8-bit mask, the lanes set in it, lowest first (then zeros): the shuffle that moves
// those lanes to the front.
struct LanePacking {
    std::int32_t lanes[256][8];
};

constexpr LanePacking MakeLanePacking() {
    LanePacking packing{};
    for (int mask = 0; mask < 256; ++mask) {
        int packed = 0;
        for (int lane = 0; lane < 8; ++lane) {
            if ((mask >> lane) & 1) packing.lanes[mask][packed++] = lane;
        }
    }
    return packing;
}

constexpr LanePacking kLanePacking = MakeLanePacking();
// The walk tells leaves from inner nodes by the sign of the child entry.
static_assert(SplatTree::kLeafFlag == 0x80000000u, "the leaf flag is the sign bit");
constexpr std::int32_t kLeafIndexBits = static_cast<std::int32_t>(~SplatTree::kLeafFlag);

// Writes the lanes of v set in mask to dst[0, popcount(mask)), in order, with one shuffle and one
// store: no branch and no loop over the lanes. dst needs room for eight.
GONIO_INLINE void AppendLanes(std::uint32_t* dst, const Ints8& v, unsigned mask) {
    Ints8 lanes;
    std::memcpy(&lanes, kLanePacking.lanes[mask], sizeof lanes);
#if defined(__GNUC__) && !defined(__clang__)
    const Ints8 packed = __builtin_shuffle(v, lanes);
#else
    Ints8 packed;  // Clang shuffles by constant lanes only
    for (int j = 0; j < 8; ++j) packed[j] = v[lanes[j]];
#endif
    std::memcpy(dst, &packed, sizeof packed);
}

// The nodes a walk has queued, one list per thread, kept from query to query: a node is queued
// at most once, so it never needs more room than the tree has nodes (and kWidth slots past the
// last, written but not counted).
GONIO_INLINE std::uint32_t* NodeQueue(std::size_t numNodes) {
    thread_local std::vector<std::uint32_t> queue;
    if (queue.size() < numNodes) queue.resize(numNodes);
    return queue.data();
}

// Breadth first through the nodes whose boxes the query reaches, the node kPrefetchAhead places on
// in the queue fetched while one is tested, so fetches overlap instead of waiting one after
// another. A node's reached children are appended to the queue (inner nodes) or the batch
// (leaves) by one shuffle each, with no branch or store per child: on brushed metal the walk
// alone takes 1.0 us a query, against 1.9 with a store per child and 2.3 with a branch per child
// (which mispredicts often). The leaves are summed in batches of about kBatch. With a known number
// of components the sums stay in registers.
template <typename K>
GONIO_INLINE void Traverse(const TreeView& t, const QueryImage& q, Doubles8* sums) {
    Doubles8 local[K::kComps > 0 ? K::kComps : 1] = {};
    Doubles8* into = K::kComps > 0 ? local : sums;
    std::uint32_t* queue = NodeQueue(t.numNodes + kWidth);
    // Under kBatch leaves, then a whole node's appended, then the padding of SumBatch.
    std::uint32_t batch[kBatch + kWidth + kTogether];
    std::size_t queued = 0;
    int batched = 0;
    queue[queued++] = 0;
    for (std::size_t next = 0; next < queued; ++next) {
        const std::size_t ahead = next + kPrefetchAhead;
        PrefetchNode(t, queue[ahead < queued ? ahead : next]);
        const SplatTree::Node& n = t.nodes[queue[next]];
        const unsigned reached = ReachableChildren<K::kIso, K::kNorm>(t, n, q);
        Ints8 children;
        std::memcpy(&children, n.child, sizeof children);
        const unsigned leaves = reached & BitMask(children < 0);
        const unsigned inner = reached & ~leaves;
        AppendLanes(queue + queued, children, inner);
        queued += static_cast<std::size_t>(__builtin_popcount(inner));
        AppendLanes(batch + batched, children & kLeafIndexBits, leaves);
        batched += __builtin_popcount(leaves);
        if (batched >= kBatch) {
            SumBatch<K>(t, batch, batched, q, into);
            batched = 0;
        }
    }
    SumBatch<K>(t, batch, batched, q, into);
    if constexpr (K::kComps > 0) {
        for (int c = 0; c < K::kComps; ++c) sums[c] += local[c];
    }
}

template <bool kIso, Norm kNorm, ChordRange kRange>
GONIO_INLINE void TraverseComps(const TreeView& t, const QueryImage& q, Doubles8* sums) {
    // Grey (one stored component) and colour (3) are the common cases; anything else sums
    // through memory.
    switch (t.ncomps) {
        case 1:
            return Traverse<Kind<kIso, kNorm, kRange, 1>>(t, q, sums);
        case 3:
            return Traverse<Kind<kIso, kNorm, kRange, 3>>(t, q, sums);
        default:
            return Traverse<Kind<kIso, kNorm, kRange, 0>>(t, q, sums);
    }
}

template <bool kIso, ChordRange kRange>
GONIO_INLINE void TraverseNorm(Norm norm, const TreeView& t, const QueryImage& q, Doubles8* sums) {
    switch (norm) {
        case Norm::kL1:
            return TraverseComps<kIso, Norm::kL1, kRange>(t, q, sums);
        case Norm::kL2:
            return TraverseComps<kIso, Norm::kL2, kRange>(t, q, sums);
        case Norm::kLinf:
            return TraverseComps<kIso, Norm::kLinf, kRange>(t, q, sums);
    }
}

template <bool kIso>
GONIO_INLINE void TraverseRange(Norm norm, const TreeView& t, const QueryImage& q, Doubles8* sums) {
    switch (ChordRangeFor(t.chordRadius2)) {
        case ChordRange::kSmall:
            return TraverseNorm<kIso, ChordRange::kSmall>(norm, t, q, sums);
        case ChordRange::kMedium:
            return TraverseNorm<kIso, ChordRange::kMedium>(norm, t, q, sums);
        case ChordRange::kLarge:
            return TraverseNorm<kIso, ChordRange::kLarge>(norm, t, q, sums);
    }
}

GONIO_SIMD_CLONES
void SumImage(bool isotropic, Norm norm, const TreeView& t, const QueryImage& q, Doubles8* sums) {
    isotropic ? TraverseRange<true>(norm, t, q, sums) : TraverseRange<false>(norm, t, q, sums);
}

// Splats per child of a node over `count` splats: kLeaf · 8^k, the least that needs no more than
// kWidth children. Every node but those on the path to the last splat is then full.
std::size_t ChildCapacity(std::size_t count) {
    std::size_t capacity = kLeaf;
    while (capacity * kWidth < count) capacity *= kWidth;
    return capacity;
}

// Where a node over `count` splats (more than `capacity`) splits in two: half its whole
// capacities below, the rest above. Sorting and laying out split at the same places.
std::size_t LowerPieceSize(std::size_t count, std::size_t capacity) {
    return (count + capacity - 1) / capacity / 2 * capacity;
}

struct Box {
    float lo[6], hi[6];
};

// Orders the splats (median splits on the widest side) and lays out the nodes.
class Builder {
  public:
    Builder(const SplatSet& splats, std::vector<std::uint32_t>& order)
        : splats_(splats), order_(order), isotropic_(splats.Params().isotropic) {}

    // Sorts order[begin, begin + count) into its leaves, parallel over large ranges.
    void Sort(std::size_t begin, std::size_t count) const {
        if (count > static_cast<std::size_t>(kLeaf)) SortPieces(begin, count, ChildCapacity(count));
    }

    // Boxes of the leaves, once sorted: a node's child box is the union of its leaves' boxes.
    void BoxLeaves() {
        leafBoxes_.resize((order_.size() + kLeaf - 1) / kLeaf);
        for (std::size_t leaf = 0; leaf < leafBoxes_.size(); ++leaf) {
            const std::size_t begin = leaf * kLeaf;
            leafBoxes_[leaf] = Bounds(begin, std::min<std::size_t>(kLeaf, order_.size() - begin));
        }
    }

    // Creates the node over order[begin, begin + count) and its subtree, once sorted and boxed;
    // returns its index.
    std::uint32_t Emit(std::size_t begin, std::size_t count, std::vector<SplatTree::Node>& nodes) {
        const auto index = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        int slot = 0;
        SplitIntoPieces(begin, count, ChildCapacity(count), [&](std::size_t b, std::size_t c) {
            Box box = leafBoxes_[b / kLeaf];
            for (std::size_t leaf = b / kLeaf + 1; leaf < (b + c + kLeaf - 1) / kLeaf; ++leaf) {
                for (int dim = 0; dim < 6; ++dim) {
                    box.lo[dim] = std::min(box.lo[dim], leafBoxes_[leaf].lo[dim]);
                    box.hi[dim] = std::max(box.hi[dim], leafBoxes_[leaf].hi[dim]);
                }
            }
            const std::uint32_t child =
                c <= static_cast<std::size_t>(kLeaf)
                    ? SplatTree::kLeafFlag | static_cast<std::uint32_t>(b / kLeaf)
                    : Emit(b, c, nodes);
            SplatTree::Node& n = nodes[index];
            for (int dim = 0; dim < 6; ++dim) {
                n.lo[dim][slot] = box.lo[dim];
                n.hi[dim][slot] = box.hi[dim];
            }
            n.child[slot++] = child;
        });
        SplatTree::Node& n = nodes[index];
        for (; slot < kWidth; ++slot) {
            for (int dim = 0; dim < 6; ++dim) n.lo[dim][slot] = n.hi[dim][slot] = kFarAway;
            n.child[slot] = SplatTree::kLeafFlag;
        }
        return index;
    }

    float Coordinate(std::uint32_t k, int dim) const {
        const SplatGeometry& g = splats_.geometry[k];
        switch (dim) {
            case 0:
                return isotropic_ ? g.thetaIn : g.inX;
            case 1:
                return isotropic_ ? 0.0f : g.inY;
            case 2:
                return isotropic_ ? 0.0f : g.inZ;
            case 3:
                return g.outX;
            case 4:
                return g.outY;
            default:
                return g.outZ;
        }
    }

  private:
    Box Bounds(std::size_t begin, std::size_t count) const {
        Box box;
        for (int dim = 0; dim < 6; ++dim) {
            float lo = Coordinate(order_[begin], dim), hi = lo;
            for (std::size_t i = begin + 1; i < begin + count; ++i) {
                const float x = Coordinate(order_[i], dim);
                lo = std::min(lo, x);
                hi = std::max(hi, x);
            }
            box.lo[dim] = lo;
            box.hi[dim] = hi;
        }
        return box;
    }

    // Calls piece(begin, count) for the children of a node over order[begin, begin + count):
    // halves of whole capacities, split again until each holds at most `capacity` splats.
    template <typename Piece>
    static void SplitIntoPieces(std::size_t begin, std::size_t count, std::size_t capacity,
                                const Piece& piece) {
        if (count <= capacity) return piece(begin, count);
        const std::size_t left = LowerPieceSize(count, capacity);
        SplitIntoPieces(begin, left, capacity, piece);
        SplitIntoPieces(begin + left, count - left, capacity, piece);
    }

    // The splits of SplitIntoPieces, done: at the median of the widest side, then each piece
    // sorted into its own children.
    void SortPieces(std::size_t begin, std::size_t count, std::size_t capacity) const {
        if (count <= capacity) return Sort(begin, count);
        const std::size_t left = LowerPieceSize(count, capacity);
        const Box box = Bounds(begin, count);
        int widest = 0;
        for (int dim = 1; dim < 6; ++dim) {
            if (box.hi[dim] - box.lo[dim] > box.hi[widest] - box.lo[widest]) widest = dim;
        }
        auto first = order_.begin() + static_cast<std::ptrdiff_t>(begin);
        std::nth_element(first, first + static_cast<std::ptrdiff_t>(left),
                         first + static_cast<std::ptrdiff_t>(count),
                         [&](std::uint32_t a, std::uint32_t b) {
                             const float ca = Coordinate(a, widest), cb = Coordinate(b, widest);
                             return ca < cb || (ca == cb && a < b);
                         });
        const auto lower = [&] { SortPieces(begin, left, capacity); };
        const auto upper = [&] { SortPieces(begin + left, count - left, capacity); };
        if (count > 65536) {
            tbb::parallel_invoke(lower, upper);
        } else {
            lower();
            upper();
        }
    }

    const SplatSet& splats_;
    std::vector<std::uint32_t>& order_;
    bool isotropic_;
    std::vector<Box> leafBoxes_;
};

// Whether every splat weighs the same in every component (a grey material, and every synthetic
// map): the tree then keeps and sums one weight a splat instead of one per component, so an RGB
// lookup reads a fifth less memory and does a third of the products.
bool AllGrey(const SplatSet& splats) {
    const int n = splats.NumComponents();
    for (std::size_t k = 0; k < splats.Size(); ++k) {
        const float* w = &splats.weights[k * n];
        if (!std::all_of(w + 1, w + n, [&](float x) { return x == w[0]; })) return false;
    }
    return true;
}

// The first 64-byte boundary in the leaf array: each row of kLeaf floats fills a cache line.
const float* Aligned(const std::vector<float>& v) {
    const auto address = reinterpret_cast<std::uintptr_t>(v.data());
    return v.data() + ((64 - address % 64) % 64) / sizeof(float);
}

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
    grey_ = ncomps_ > 1 && AllGrey(splats);
    std::vector<std::uint32_t> order(size);
    std::iota(order.begin(), order.end(), 0u);
    Builder builder(splats, order);
    builder.Sort(0, size);
    builder.BoxLeaves();
    builder.Emit(0, size, nodes_);
    numLeaves_ = (size + kLeaf - 1) / kLeaf;

    const int coordinates = NumCoordinates(isotropic_);
    const std::size_t stride = LeafStride();
    leaves_.assign((numLeaves_ + 1) * stride + 64 / sizeof(float), 0.0f);
    float* data = const_cast<float*>(Aligned(leaves_));
    for (std::size_t leaf = 0; leaf <= numLeaves_; ++leaf) {  // the last one stays empty
        float* block = data + leaf * stride;
        std::fill(block, block + coordinates * kLeaf, kFarAway);
        for (int slot = 0; slot < kLeaf && leaf * kLeaf + slot < size; ++slot) {
            const std::uint32_t k = order[leaf * kLeaf + slot];
            for (int c = 0; c < coordinates; ++c) {
                const int dim = isotropic_ && c > 0 ? c + 2 : c;  // isotropic: θ_in, out x, y, z
                block[c * kLeaf + slot] = builder.Coordinate(k, dim);
            }
            for (int c = 0; c < StoredComponents(); ++c) {
                block[(coordinates + c) * kLeaf + slot] = splats.weights[k * ncomps_ + c];
            }
        }
    }
}

void SplatTree::Accumulate(const SplatQuery& q, double* acc) const {
    if (nodes_.empty()) return;
    const double reach = radius_ * (1 + kReachSlack) + 1e-6;
    const double chordReach =
        std::sqrt(static_cast<double>(chordRadius2_)) * (1 + kReachSlack) + 1e-6;
    const TreeView view{nodes_.data(),
                        nodes_.size(),
                        Aligned(leaves_),
                        LeafStride(),
                        static_cast<std::uint32_t>(numLeaves_),
                        StoredComponents(),
                        chordRadius2_,
                        invRadius_ * invRadius_,
                        static_cast<float>(reach),
                        static_cast<float>(chordReach * chordReach)};
    // Per stored component, in double (lane j: the float lanes j and j + 8 of SumLeaves).
    Doubles8 fixed[4];
    // new[] keeps the vectors' alignment (a std::vector would drop it with the type's attribute).
    const int stored = StoredComponents();
    std::unique_ptr<Doubles8[]> more(stored > 4 ? new Doubles8[stored] : nullptr);
    Doubles8* sums = stored > 4 ? more.get() : fixed;
    std::fill(sums, sums + stored, Doubles8{});
    for (int v = 0; v < 6; ++v) {
        if (!(q.activeMask & (1u << v))) continue;
        const QueryImage image{{isotropic_ ? q.thetaIn[v] : q.inX[v], isotropic_ ? 0.0f : q.inY[v],
                                isotropic_ ? 0.0f : q.inZ[v]},
                               {q.outX[v], q.outY[v], q.outZ[v]}};
        SumImage(isotropic_, norm_, view, image, sums);
    }
    for (int c = 0; c < ncomps_; ++c) {
        double sum = 0.0;
        for (int j = 0; j < 8; ++j) sum += sums[grey_ ? 0 : c][j];
        acc[c] += sum;
    }
}

std::size_t SplatTree::LeafStride() const {
    return static_cast<std::size_t>(NumCoordinates(isotropic_) + StoredComponents()) * kLeaf;
}

std::size_t SplatTree::MemoryBytes() const {
    return nodes_.size() * sizeof(Node) + sizeof(float) * leaves_.size();
}

}  // namespace gonio
