#pragma once
// How many rays a render traced, by what traced them (`gonio render --stats`). Each worker
// (one per thread) keeps its own counts and the frame sums them at the end: a shared atomic
// bumped per ray would cost more than many of the rays it counts. A ray is one query of the
// scene, so a ray continued past a transparent surface counts once per surface crossed.

#include <cstdint>

namespace gonio {

struct RayCounts {
    uint64_t camera = 0;   // camera rays, with their continuations through transparent surfaces
    uint64_t trace = 0;    // rays followed to shade what they hit: trace(), and the shaded
                           // hits of indirectdiffuse() and gather()
    uint64_t shadow = 0;   // shadow rays towards lights (point and area lights alike)
    uint64_t sampled = 0;  // the rays of occlusion(), indirectdiffuse(), gather(),
                           // transmission() and visibility()
    uint64_t differential = 0;  // rays to the neighbour points of shaders taking derivatives
    uint64_t path = 0;          // the path tracer's rays, its camera rays among them

    uint64_t Total() const { return camera + trace + shadow + sampled + differential + path; }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera, trace += o.trace, shadow += o.shadow, sampled += o.sampled;
        differential += o.differential, path += o.path;
        return *this;
    }
};

}  // namespace gonio
