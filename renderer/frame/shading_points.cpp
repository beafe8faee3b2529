#include "renderer/frame/shading_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace gonio {
namespace {

// Hits whose points lie further apart than this many cell widths (at their depth) are on
// different parts of the surface: a fold, a silhouette seen past, or another instance.
constexpr float kDistanceInCells = 2;
// Normals further apart than about 25 degrees: a crease, or the other face of a thin box.
constexpr float kMinNormalCosine = 0.9f;

// floor(v) for |v| < 2^31, without the library call that x86-64's baseline makes of std::floor.
int FloorToInt(float v) {
    const int i = int(v);  // towards zero
    return i - int(v < float(i));
}

// A raster cell as one integer: cells compare in row order (by y, then x, for cells at
// non-negative positions; any order groups a cell's hits together).
uint64_t CellKey(int x, int y) { return uint64_t(uint32_t(y)) << 32 | uint32_t(x); }

// A hit's squared distance from its cell's centre, then its index, as one integer: a
// non-negative float's bits order as the float does.
uint64_t NearnessKey(float centreDistance2, int hit) {
    uint32_t bits;
    std::memcpy(&bits, &centreDistance2, sizeof bits);
    return uint64_t(bits) << 32 | uint32_t(hit);
}

}  // namespace

inline bool ShadingPointSharing::CanShare(const ShadingPointHit& hit, const ShadingPointHit& shaded,
                                          float cell) const {
    const SurfacePoint& a = *hit.point;
    const SurfacePoint& b = *shaded.point;
    if (a.shape != b.shape || a.record != b.record) return false;
    // Uniform primitive variables (a face's Cs, a patch's id) change from face to face; REYES
    // dices every face on its own grid too.
    if (a.stencils.uniform != b.stencils.uniform) return false;
    // Both sides of a two-sided sheet can show in one cell; they shade differently.
    if ((a.Ng.dot(hit.dir) < 0) != (b.Ng.dot(shaded.dir) < 0)) return false;
    if (a.N.dot(b.N) < kMinNormalCosine) return false;
    const float reach =
        kDistanceInCells * cell * (footprintAt0_ + footprintPerDistance_ * shaded.t);
    return (a.P - b.P).length2() <= reach * reach;
}

void ShadingPointSharing::Cluster(const std::vector<ShadingPointHit>& hits, float shadingRate,
                                  std::vector<int>* shaded, std::vector<int>* shadedBy) {
    const int n = int(hits.size());
    const float cell = std::sqrt(shadingRate), cellsPerPixel = 1 / cell;
    cells_.resize(size_t(n));
    for (int i = 0; i < n; ++i) {
        const float cx = hits[i].x * cellsPerPixel, cy = hits[i].y * cellsPerPixel;
        const int ix = FloorToInt(cx), iy = FloorToInt(cy);
        const float dx = cx - float(ix) - 0.5f, dy = cy - float(iy) - 0.5f;
        cells_[i] = {CellKey(ix, iy), NearnessKey(dx * dx + dy * dy, i)};
    }
    // Hits come in sample order, pixel by pixel, so at rates up to a pixel their cells are
    // already in order; otherwise group them, keeping sample order within a cell.
    auto cellBefore = [](const CellEntry& a, const CellEntry& b) { return a.cell < b.cell; };
    const bool inSampleOrder = std::is_sorted(cells_.begin(), cells_.end(), cellBefore);
    if (!inSampleOrder) std::stable_sort(cells_.begin(), cells_.end(), cellBefore);
    // Within a cell, the hits nearest its centre come first and are the ones shaded: shading
    // the first sample instead would shift every highlight and texture by most of a stratum
    // towards the cell's corner. Ties go to the earlier sample, so the order is fixed.
    auto nearerTheCentre = [](const CellEntry& a, const CellEntry& b) {
        return a.nearness < b.nearness;
    };
    shadedBy->assign(size_t(n), -1);
    shaded->clear();
    std::vector<int>& numberOf = scratchNumbers_;  // of each shaded hit, in `shaded`
    numberOf.resize(size_t(n));
    // The hits of one cell, in that order: each takes the first one before it that is shaded
    // itself and that it can share with.
    const auto share = [&](std::vector<CellEntry>::iterator first,
                           std::vector<CellEntry>::iterator last) {
        for (auto i = first; i != last; ++i) {
            const int hit = i->Hit();
            (*shadedBy)[hit] = hit;
            for (auto j = first; j != i; ++j) {
                const int candidate = j->Hit();
                if ((*shadedBy)[candidate] != candidate) continue;
                if (CanShare(hits[hit], hits[candidate], cell)) {
                    (*shadedBy)[hit] = candidate;
                    break;
                }
            }
        }
    };
    // Numbers the shaded hits of [first, last) in sample order and points the hits there at
    // their numbers (shadedBy holds the shaded hit itself until then).
    const auto number = [&](std::vector<CellEntry>::iterator first,
                            std::vector<CellEntry>::iterator last) {
        std::vector<int>& cellShaded = scratchShaded_;
        cellShaded.clear();
        for (auto i = first; i != last; ++i)
            if ((*shadedBy)[i->Hit()] == i->Hit()) cellShaded.push_back(i->Hit());
        std::sort(cellShaded.begin(), cellShaded.end());
        for (const int hit : cellShaded) {
            numberOf[hit] = int(shaded->size());
            shaded->push_back(hit);
        }
        for (auto i = first; i != last; ++i)
            (*shadedBy)[i->Hit()] = numberOf[(*shadedBy)[i->Hit()]];
    };
    for (auto first = cells_.begin(); first != cells_.end();) {
        auto last = first + 1;
        while (last != cells_.end() && !cellBefore(*first, *last)) ++last;
        // Sorting the cell is not needed for the usual cell, one surface: the hit nearest the
        // centre comes first and every hit that can share with it does; only those that cannot
        // (another surface, a fold) are sorted and shared among themselves. That is the same
        // as sharing the whole sorted cell, as none of the others is shaded itself.
        std::iter_swap(first, std::min_element(first, last, nearerTheCentre));
        const int nearest = first->Hit();
        auto rest = std::partition(first + 1, last, [&](const CellEntry& e) {
            return CanShare(hits[e.Hit()], hits[nearest], cell);
        });
        if (inSampleOrder && rest == last) {
            // One shaded hit, and cells in sample order: its number is the next.
            const int shadedNumber = int(shaded->size());
            shaded->push_back(nearest);
            for (auto i = first; i != last; ++i) (*shadedBy)[i->Hit()] = shadedNumber;
        } else {
            for (auto i = first; i != rest; ++i) (*shadedBy)[i->Hit()] = nearest;
            if (rest != last) {
                std::sort(rest, last, nearerTheCentre);
                share(rest, last);
            }
            if (inSampleOrder) number(first, last);
        }
        first = last;
    }
    // Cells out of sample order: number the shaded hits of all of them at once.
    if (!inSampleOrder) number(cells_.begin(), cells_.end());
}

}  // namespace gonio
