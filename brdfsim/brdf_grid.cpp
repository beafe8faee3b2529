#include "brdfsim/brdf_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/math.h"

namespace gonio {

namespace {

// f(ω'→ω): the splats the tree finds for the pair, summed in double (on the stack for up to 16
// components), 0 below the horizon.
void SumSplats(const SplatSet& splats, const SplatTree& tree, const Imath::V3f& wIn,
               const Imath::V3f& wOut, float* f) {
    const int n = splats.NumComponents();
    double acc[16] = {0};
    std::vector<double> wide(n > 16 ? n : 0, 0.0);
    double* sum = n > 16 ? wide.data() : acc;
    if (wIn.z > 0 && wOut.z > 0) tree.Accumulate(splats.MakeQuery(wIn, wOut), sum);
    for (int c = 0; c < n; ++c) f[c] = static_cast<float>(sum[c]);
}

// Cell tests get a little slack so that float rounding in a lookup never misses a splat.
double SlackRadius(double radius) { return radius * (1 + 1e-5) + 1e-6; }

std::uint32_t Entry(std::size_t k, int image) {
    return static_cast<std::uint32_t>(k) | (static_cast<std::uint32_t>(image) << kImageShift);
}

void CheckSize(const SplatSet& splats, std::size_t cells) {
    if (splats.Size() > kSplatMask) throw std::invalid_argument("too many photons for a grid");
    // Offsets and build counters cost about 20 bytes a cell.
    if (cells > (std::size_t(1) << 24)) {
        throw std::invalid_argument("grid too fine: " + std::to_string(cells) +
                                    " cells (at most 16.7M); use fewer rings or rects");
    }
}

}  // namespace

GridStats ComputeGridStats(const CellLists& lists, std::size_t photons) {
    GridStats stats;
    stats.cells = lists.NumCells();
    for (std::size_t c = 0; c < stats.cells; ++c) {
        stats.maxSplats =
            std::max<std::size_t>(stats.maxSplats, lists.offsets[c + 1] - lists.offsets[c]);
    }
    stats.averageSplats = stats.cells ? static_cast<double>(lists.entries.size()) / stats.cells : 0;
    stats.ratio = photons ? stats.averageSplats / photons : 0.0;
    return stats;
}

BrdfGrid::BrdfGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects,
                   const ProgressFn& progress)
    : splats_(std::move(splats)), grid_(rings, rects) {
    if (splats_->Params().isotropic) throw std::invalid_argument("BrdfGrid needs a 4D splat set");
    CheckSize(*splats_, static_cast<std::size_t>(grid_.NumCells()) * grid_.NumCells());
    const SplatSet& s = *splats_;
    const double radius = SlackRadius(s.Params().radius);
    const std::size_t numOut = grid_.NumCells();
    const CellFinder finder(grid_, radius);
    auto emit = [&](std::size_t k, const auto& add) {
        std::vector<std::pair<int, double>> inCells, outCells;
        for (int v = 0; v < s.NumImages(); ++v) {
            Imath::V3d in, out;
            double theta;
            s.ImageCentre(k, v, &in, &theta, &out);
            inCells.clear();
            outCells.clear();
            finder.Near(in, inCells);
            if (inCells.empty()) continue;
            finder.Near(out, outCells);
            // Exact in the product domain: the nearest point of a pair of cells is at
            // norm(d_in, d_out), tighter than the thesis's norm-independent assignment.
            for (const auto& [ci, di] : inCells) {
                for (const auto& [co, dout] : outCells) {
                    if (CombineDistances(s.Params().norm, di, dout) < radius) {
                        add(ci * numOut + co, Entry(k, v));
                    }
                }
            }
        }
    };
    lists_ = CellLists::Build(numOut * numOut, s.Size(), emit, progress);
    tree_ = SplatTree(s);
}

BrdfGrid::BrdfGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects, CellLists lists)
    : splats_(std::move(splats)), grid_(rings, rects), lists_(std::move(lists)), tree_(*splats_) {}

void BrdfGrid::Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const {
    SumSplats(*splats_, tree_, wIn, wOut, f);
}

std::size_t BrdfGrid::MemoryBytes() const {
    return SplatSetBytes(*splats_) + lists_.Bytes() + tree_.MemoryBytes();
}

BrdfIsoGrid::BrdfIsoGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects,
                         const ProgressFn& progress)
    : splats_(std::move(splats)), rings_(rings), grid_(rings, rects) {
    if (!splats_->Params().isotropic) {
        throw std::invalid_argument("BrdfIsoGrid needs an isotropic splat set");
    }
    CheckSize(*splats_, static_cast<std::size_t>(rings) * grid_.NumCells());
    const SplatSet& s = *splats_;
    const double radius = SlackRadius(s.Params().radius);
    const double width = 0.5 * kPi / rings;
    const std::size_t numOut = grid_.NumCells();
    const CellFinder finder(grid_, radius);
    auto emit = [&](std::size_t k, const auto& add) {
        std::vector<std::pair<int, double>> outCells;
        for (int v = 0; v < s.NumImages(); ++v) {
            Imath::V3d in, out;
            double theta;
            s.ImageCentre(k, v, &in, &theta, &out);
            if (theta < -radius || theta > 0.5 * kPi + radius) continue;
            outCells.clear();
            finder.Near(out, outCells);
            for (int r = 0; r < rings_; ++r) {
                const double di = std::max({0.0, r * width - theta, theta - (r + 1) * width});
                if (di >= radius) continue;
                for (const auto& [co, dout] : outCells) {
                    if (CombineDistances(s.Params().norm, di, dout) < radius) {
                        add(r * numOut + co, Entry(k, v));
                    }
                }
            }
        }
    };
    lists_ = CellLists::Build(rings_ * numOut, s.Size(), emit, progress);
    tree_ = SplatTree(s);
}

BrdfIsoGrid::BrdfIsoGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects,
                         CellLists lists)
    : splats_(std::move(splats)),
      rings_(rings),
      grid_(rings, rects),
      lists_(std::move(lists)),
      tree_(*splats_) {}

void BrdfIsoGrid::Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const {
    SumSplats(*splats_, tree_, wIn, wOut, f);
}

std::size_t BrdfIsoGrid::MemoryBytes() const {
    return SplatSetBytes(*splats_) + lists_.Bytes() + tree_.MemoryBytes();
}

}  // namespace gonio
