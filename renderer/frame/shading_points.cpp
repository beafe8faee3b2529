#include "renderer/frame/shading_points.h"

#include <algorithm>
#include <cmath>

namespace gonio {
namespace {

// Hits whose points lie further apart than this many cell widths (at their depth) are on
// different parts of the surface: a fold, a silhouette seen past, or another instance.
constexpr float kDistanceInCells = 2;
// Normals further apart than about 25 degrees: a crease, or the other face of a thin box.
constexpr float kMinNormalCosine = 0.9f;

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
        const float fx = std::floor(cx), fy = std::floor(cy);
        const float dx = cx - fx - 0.5f, dy = cy - fy - 0.5f;
        cells_[i] = {(long long)fx, (long long)fy, dx * dx + dy * dy, i};
    }
    // Hits come in sample order, pixel by pixel, so at rates up to a pixel their cells are
    // already in order; otherwise group them, keeping sample order within a cell.
    auto cellBefore = [](const CellEntry& a, const CellEntry& b) {
        return a.cellY != b.cellY ? a.cellY < b.cellY : a.cellX < b.cellX;
    };
    if (!std::is_sorted(cells_.begin(), cells_.end(), cellBefore))
        std::stable_sort(cells_.begin(), cells_.end(), cellBefore);
    // Within a cell, the hits nearest its centre come first and are the ones shaded: shading
    // the first sample instead would shift every highlight and texture by most of a stratum
    // towards the cell's corner. Ties go to the earlier sample, so the order is fixed.
    auto nearerTheCentre = [](const CellEntry& a, const CellEntry& b) {
        return a.centreDistance != b.centreDistance ? a.centreDistance < b.centreDistance
                                                    : a.hit < b.hit;
    };
    shadedBy->assign(size_t(n), -1);
    // The hits of one cell, in that order: each takes the first one before it that is shaded
    // itself and that it can share with.
    const auto share = [&](std::vector<CellEntry>::iterator first,
                           std::vector<CellEntry>::iterator last) {
        for (auto i = first; i != last; ++i) {
            const int hit = i->hit;
            (*shadedBy)[hit] = hit;
            for (auto j = first; j != i; ++j) {
                const int candidate = j->hit;
                if ((*shadedBy)[candidate] != candidate) continue;
                if (CanShare(hits[hit], hits[candidate], cell)) {
                    (*shadedBy)[hit] = candidate;
                    break;
                }
            }
        }
    };
    for (auto first = cells_.begin(); first != cells_.end();) {
        auto last = first + 1;
        while (last != cells_.end() && !cellBefore(*first, *last)) ++last;
        // Sorting the cell is not needed for the usual cell, one surface: the hit nearest the
        // centre comes first and every hit that can share with it does; only those that cannot
        // (another surface, a fold) are sorted and shared among themselves. That is the same
        // as sharing the whole sorted cell, as none of the others is shaded itself.
        std::iter_swap(first, std::min_element(first, last, nearerTheCentre));
        const int nearest = first->hit;
        (*shadedBy)[nearest] = nearest;
        auto rest = std::partition(first + 1, last, [&](const CellEntry& e) {
            return CanShare(hits[e.hit], hits[nearest], cell);
        });
        for (auto i = first + 1; i != rest; ++i) (*shadedBy)[i->hit] = nearest;
        if (rest != last) {
            std::sort(rest, last, nearerTheCentre);
            share(rest, last);
        }
        first = last;
    }
    // Number the shaded hits in sample order and point every hit at its number.
    shaded->clear();
    std::vector<int>& numberOf = scratchNumbers_;
    numberOf.assign(size_t(n), -1);
    for (int i = 0; i < n; ++i)
        if ((*shadedBy)[i] == i) {
            numberOf[i] = int(shaded->size());
            shaded->push_back(i);
        }
    for (int i = 0; i < n; ++i) (*shadedBy)[i] = numberOf[(*shadedBy)[i]];
}

}  // namespace gonio
