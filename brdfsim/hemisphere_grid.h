#pragma once
// The subdivision of a hemisphere of thesis §4.3.1: bands of equal width in θ, the b-th band
// (1-based, from the pole) cut into n_rect = max(round(sin(π/2 · b/n_bands) · n_max), 1) cells
// (thesis eq. 4.14), and the exact test of which cells a splat's cap reaches.

#include <Imath/ImathVec.h>

#include <utility>
#include <vector>

namespace gonio {

class HemisphereGrid {
public:
    HemisphereGrid() = default;
    HemisphereGrid(int bands, int maxRects);

    int NumBands() const { return bands_; }
    int MaxRects() const { return maxRects_; }
    int NumCells() const { return firstCell_.back(); }
    int RectsInBand(int band) const { return firstCell_[band + 1] - firstCell_[band]; }

    // The cell holding unit direction w (z >= 0).
    int CellOf(const Imath::V3f& w) const;
    // Appends (cell, minimum great-circle distance) for every cell closer than `radius` to the
    // point `centre` (unit; may lie below the horizon, as mirror images do).
    void CellsNear(const Imath::V3d& centre, double radius,
                   std::vector<std::pair<int, double>>& cells) const;
    // Minimum great-circle distance from `centre` to the cell.
    double DistanceToCell(int cell, double thetaC, double phiC) const;

private:
    int bands_ = 0, maxRects_ = 0;
    double bandWidth_ = 0.0;
    std::vector<int> firstCell_;  // bands_ + 1 entries
    std::vector<int> bandOfCell_;
};

}  // namespace gonio
