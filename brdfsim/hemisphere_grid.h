#pragma once
// The subdivision of a hemisphere of thesis §4.3.1: bands of equal width in θ, the b-th band
// (1-based, from the pole) cut into n_rect = max(round(sin(π/2 · b/n_bands) · n_max), 1) cells
// (thesis eq. 4.14), and the exact test of which cells a splat's cap reaches.

#include <Imath/ImathVec.h>

#include <cstdint>
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
    // The cells of a grid of these bands and rects, without building it (which costs a bounding
    // cap per cell): what a reader checks a file against.
    static std::uint64_t CellCount(int bands, int maxRects);
    int RectsInBand(int band) const { return firstCell_[band + 1] - firstCell_[band]; }

    // The cell holding unit direction w (z >= 0).
    int CellOf(const Imath::V3f& w) const;
    // Minimum great-circle distance from the point (θc, φc) to the cell.
    double DistanceToCell(int cell, double thetaC, double phiC) const;

  private:
    friend class CellFinder;
    void ComputeBoundingCap(int cell);
    double DistanceToCell(int cell, double thetaC, double phiC, double sinC, double cosC) const;

    int bands_ = 0, maxRects_ = 0;
    double bandWidth_ = 0.0;
    std::vector<int> firstCell_;  // bands_ + 1 entries
    std::vector<int> bandOfCell_;
    // A cap around each cell (centre, cos of its radius) rejects far cells with one dot product.
    std::vector<Imath::V3d> cellCentre_;
    std::vector<double> cellRadius_;
    std::vector<double> bandCos_, bandSin_;  // of the band boundaries
};

// Finds the cells a splat of a given radius reaches.
class CellFinder {
  public:
    CellFinder(const HemisphereGrid& grid, double radius);
    // Appends (cell, minimum great-circle distance) for every cell closer than the radius to the
    // point `centre` (unit; may lie below the horizon, as mirror images do).
    void Near(const Imath::V3d& centre, std::vector<std::pair<int, double>>& cells) const;

  private:
    const HemisphereGrid& grid_;
    double radius_;
    std::vector<double> cosReach_;  // per cell: cos(radius + bounding radius), or -2
};

}  // namespace gonio
