#pragma once
// ShadingRate for a ray tracer: which camera-sample hits of a batch share one shaded point.
//
// A REYES renderer shades a surface once per ShadingRate pixels of raster area and lets every
// pixel sample that lands on that piece of surface take the colour. gonio traces every sample
// and used to shade every hit (4x4 samples: sixteen shader runs, light loops and trace() rays a
// pixel). Here the hits are clustered instead: raster cells of sqrt(ShadingRate) pixels a side,
// and within a cell the hits that lie on the same shape and face, close together on it (within the
// cell's footprint at that depth), facing the same way. Each cluster shades its hit nearest
// the cell's centre; the others take its Ci, Oi and AOVs. Coverage, depth and compositing stay per
// sample, so edges keep their antialiasing. Clusters depend only on the hits, never on threads.

#include <Imath/ImathVec.h>

#include <cstdint>
#include <vector>

#include "renderer/raytrace/surface_point.h"

namespace gonio {

// What decides whether one hit may take another's shading.
struct ShadingPointHit {
    float x = 0, y = 0;  // the camera sample's raster position
    float t = 0;         // distance along the camera ray
    Imath::V3f dir;      // the camera ray's direction
    const SurfacePoint* point = nullptr;
};

class ShadingPointSharing {
  public:
    // `pixelFootprintAt0` and `pixelFootprintPerDistance`: the world-space width of one pixel at
    // distance t along a camera ray is about a + b·t (a for orthographic, b for perspective).
    ShadingPointSharing(float pixelFootprintAt0, float pixelFootprintPerDistance)
        : footprintAt0_(pixelFootprintAt0), footprintPerDistance_(pixelFootprintPerDistance) {}

    // Whether hits at this shading rate (pixels) with these pixel samples can share at all: a
    // rate no larger than one sample's share of the pixel shades every hit, as before.
    static bool Shares(float shadingRate, int xsamples, int ysamples) {
        return shadingRate * float(xsamples) * float(ysamples) > 1.f + 1e-6f;
    }

    // For each hit, the index in `shaded` of the hit whose shading it takes; `shaded` lists the
    // hits to shade, in order. All hits share one attribute state and so one shading rate.
    void Cluster(const std::vector<ShadingPointHit>& hits, float shadingRate,
                 std::vector<int>* shaded, std::vector<int>* shadedBy);

  private:
    bool CanShare(const ShadingPointHit& hit, const ShadingPointHit& shaded, float cell) const;

    float footprintAt0_, footprintPerDistance_;
    // Cluster's scratch, kept from batch to batch: each hit's raster cell, the numbers of the
    // shaded hits, and the shaded hits of a cell.
    struct CellEntry {
        uint64_t cell;      // the raster cell (CellKey)
        uint64_t nearness;  // squared distance from the cell's centre, then the hit's index
        int Hit() const { return int(uint32_t(nearness)); }  // its index into `hits`
    };
    std::vector<CellEntry> cells_;
    std::vector<int> scratchNumbers_, scratchShaded_;
};

}  // namespace gonio
