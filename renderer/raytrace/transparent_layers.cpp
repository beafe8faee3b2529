#include "renderer/raytrace/transparent_layers.h"

#include <algorithm>

namespace gonio {

bool NextVisibleHit(const RayScene& scene, const Imath::V3f& org, const Imath::V3f& dir, float time,
                    float tfar, float* tnear, SurfacePoint* sp, float* t, uint64_t* rays,
                    HitEvaluation evaluation) {
    RayHit hit;
    ++*rays;
    if (!scene.Intersect(org, dir, *tnear, tfar, time, &hit)) return false;
    return NextVisibleHitFrom(&hit, scene, org, dir, time, tfar, tnear, sp, t, rays, evaluation);
}

size_t TransparentLayers::GroupHits() {
    groupIndex_.clear();
    size_t used = 0;
    // Neighbouring hits mostly share their attributes: the last group is tried before the map.
    const Attributes* last = nullptr;
    size_t lastGroup = 0;
    for (int k = 0; k < int(hits_.size()); ++k) {
        const Attributes* attributes = points_[size_t(k)].attributes;
        if (k == 0 || attributes != last) {
            auto [it, isNew] = groupIndex_.try_emplace(attributes, used);
            if (isNew) {
                if (used == groups_.size()) groups_.emplace_back();
                groups_[used].attributes = attributes;
                groups_[used].members.clear();
                ++used;
            }
            last = attributes;
            lastGroup = it->second;
        }
        groups_[lastGroup].members.push_back(k);
    }
    return used;
}

}  // namespace gonio
