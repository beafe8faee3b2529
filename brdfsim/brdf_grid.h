#pragma once
// The 4D splat grid of thesis §4.3.1-4.3.2 (GPBRDFGrid): the incoming and the outgoing
// hemisphere are each subdivided (HemisphereGrid); every pair of cells keeps the list of splat
// images that reach it (Table 4.1, the .grd file). BrdfIsoGrid is the 3D variant (§4.3.3).
// A lookup sums the same splat images, but finds them through a SplatTree built at load time:
// a cell's list holds about ten times the splats that reach a given point of it (issue 4).

#include <memory>

#include "brdfsim/brdf.h"
#include "brdfsim/cell_lists.h"
#include "brdfsim/hemisphere_grid.h"
#include "brdfsim/splat_set.h"
#include "brdfsim/splat_tree.h"

namespace gonio {

// Thesis Table 4.1: how many splats a lookup visits.
struct GridStats {
    std::size_t cells = 0;
    double averageSplats = 0.0;  // entries per cell
    std::size_t maxSplats = 0;
    double ratio = 0.0;  // average / photons: the inverse of the speed-up over BrdfSimple
};

GridStats ComputeGridStats(const CellLists& lists, std::size_t photons);

class BrdfGrid : public Brdf {
  public:
    BrdfGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects,
             const ProgressFn& progress = {});
    // From stored lists (.grd).
    BrdfGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects, CellLists lists);

    int NumComponents() const override { return splats_->NumComponents(); }
    bool IsIsotropic() const override { return false; }
    void Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const override;
    std::size_t MemoryBytes() const override;

    const SplatSet& Splats() const { return *splats_; }
    const CellLists& Lists() const { return lists_; }
    int Rings() const { return grid_.NumBands(); }
    int Rects() const { return grid_.MaxRects(); }
    GridStats Stats() const { return ComputeGridStats(lists_, splats_->Size()); }

  private:
    std::shared_ptr<const SplatSet> splats_;
    HemisphereGrid grid_;  // the same subdivision on both hemispheres (thesis C.3.2)
    CellLists lists_;
    SplatTree tree_;  // finds the splats a lookup sums (the cells' lists give the same sum)
};

// Isotropic: θ_in split into `rings` ranges, each holding an outgoing hemisphere (θ_out, Δφ)
// subdivided as in BrdfGrid (GPIBRDFOpt: rects does not apply to the incoming side).
class BrdfIsoGrid : public Brdf {
  public:
    BrdfIsoGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects,
                const ProgressFn& progress = {});
    BrdfIsoGrid(std::shared_ptr<const SplatSet> splats, int rings, int rects, CellLists lists);

    int NumComponents() const override { return splats_->NumComponents(); }
    bool IsIsotropic() const override { return true; }
    void Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const override;
    std::size_t MemoryBytes() const override;

    const SplatSet& Splats() const { return *splats_; }
    const CellLists& Lists() const { return lists_; }
    int Rings() const { return rings_; }
    int Rects() const { return grid_.MaxRects(); }
    GridStats Stats() const { return ComputeGridStats(lists_, splats_->Size()); }

  private:
    std::shared_ptr<const SplatSet> splats_;
    int rings_;
    HemisphereGrid grid_;
    CellLists lists_;
    SplatTree tree_;
};

}  // namespace gonio
