#pragma once
// The points on an area light at which its shader runs for one batch of shaded points
// (docs/shading-language.md, Area lights). Sample k of `count` is the k-th point of a
// Hammersley set, (k + ½)/count and the radical inverses of k in bases 2 and 3, toroidally
// shifted per shaded point by its random seed (Cranley & Patterson 1976): each point sees a
// stratified set of its own, the same whatever the thread count, and neighbouring points'
// sets differ so that their error is noise rather than banding.

#include <Imath/ImathMatrix.h>

#include <cstdint>
#include <vector>

#include "renderer/raytrace/area_light_geometry.h"

namespace gonio {

struct AreaLightPoints {
    std::vector<float> P, N;    // 3 × n each, current space, component-major
    std::vector<float> weight;  // per point: 1 / (pdfArea · count), the Monte Carlo weight
};

// seeds: one per point (null: none, the unshifted set for every point).
void AreaLightSamplePoints(const AreaLightGeometry& geometry, int k, int count,
                           const uint64_t* seeds, int n, const Imath::M44f& currentFromWorld,
                           AreaLightPoints* out);

}  // namespace gonio
