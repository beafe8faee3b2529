#pragma once
// Rays that go on through transparent surfaces. Camera rays and trace() rays are traced layer by
// layer: each ray still going finds its next visible hit, the layer's hits are grouped by their
// attributes in order of first appearance (so that results do not depend on threads) for the
// caller to shade, and the caller composites them front to back. One policy for every such ray,
// transmission and shadow rays included: where a ray continues past a hit (ContinuePast), how
// many surfaces it may cross (kMaxTransparentLayers), and when what is left behind no longer
// shows (kNegligibleTransmittance).

#include <Imath/ImathVec.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "renderer/raytrace/ray_scene.h"
#include "renderer/raytrace/surface_point.h"

namespace gonio {

// Beyond this many surfaces the light left is (1 − Os)^64: nothing for any Os worth the name.
constexpr int kMaxTransparentLayers = 64;
constexpr float kNegligibleTransmittance = 1e-4f;

// Where a ray looks for its next hit after one at distance t: just past it, relative to t so
// that it misses the surface it left at any distance.
inline float ContinuePast(float t) { return t + std::max(1e-5f, 1e-5f * t); }

// How much of a hit NextVisibleHit evaluates: all of it, or its geometry only
// (RayScene::EvaluateGeometry; FinishEvaluate completes it), for hits that may not be shaded.
enum class HitEvaluation { kFull, kGeometry };

// The ray's next hit beyond *tnear (and before tfar) that faces it or is two-sided, evaluated
// into *sp, its distance in *t; *tnear moves past every hit tried. Counts each query in *rays.
bool NextVisibleHit(const RayScene& scene, const Imath::V3f& org, const Imath::V3f& dir, float time,
                    float tfar, float* tnear, SurfacePoint* sp, float* t, uint64_t* rays,
                    HitEvaluation evaluation = HitEvaluation::kFull);
// The same for a ray whose nearest hit beyond *tnear is known already (`first`, or null where
// there is none: RayScene::IntersectCoherent), which *rays counted when it was traced. Inline:
// every camera sample comes here.
inline bool NextVisibleHitFrom(const RayHit* first, const RayScene& scene, const Imath::V3f& org,
                               const Imath::V3f& dir, float time, float tfar, float* tnear,
                               SurfacePoint* sp, float* t, uint64_t* rays,
                               HitEvaluation evaluation) {
    if (!first) return false;
    RayHit hit = *first;
    while (true) {
        *tnear = ContinuePast(hit.t);
        if (evaluation == HitEvaluation::kFull)
            scene.Evaluate(org, dir, hit, sp);
        else
            scene.EvaluateGeometry(org, dir, hit, sp);
        *t = hit.t;
        if (sp->attributes->twoSided || sp->Ng.dot(dir) <= 0) return true;
        ++*rays;
        if (!scene.Intersect(org, dir, *tnear, tfar, time, &hit)) return false;
    }
}

// One layer composited front to back over n components: colour += T·Ci (not for a matte
// surface, which hides what is behind it and adds nothing, RISpec §4.2.5), then
// T *= 1 − clamp(Oi, 0, 1). Returns the largest transmittance left. Inline: every camera
// sample's every layer comes here.
inline float CompositeLayer(int n, const float* Ci, const float* Oi, bool matte, float* colour,
                            float* transmittance) {
    float remaining = 0;
    for (int c = 0; c < n; ++c) {
        if (!matte) colour[c] += transmittance[c] * Ci[c];
        transmittance[c] *= 1 - std::clamp(Oi[c], 0.f, 1.f);
        remaining = std::max(remaining, transmittance[c]);
    }
    return remaining;
}

class TransparentLayers {
  public:
    struct Hit {
        int ray;
        float t;
        float tnear;  // where the ray started looking for this hit
    };
    struct Group {
        const Attributes* attributes;
        std::vector<int> members;  // indices of the layer's hits
    };

    // Traces rays 0 .. count-1 layer by layer, at most kMaxTransparentLayers:
    //   bool findHit(int ray, SurfacePoint* sp, Hit* hit): the ray's next visible hit (filling
    //     hit->t and hit->tnear), or false, which stops the ray;
    //   void shadeGroup(int layer, const Group& group): shades the group's hits (HitAt,
    //     PointAt) and composites them, calling Stop for rays that need go no further.
    template <class FindHit, class ShadeGroup>
    void Trace(int count, FindHit&& findHit, ShadeGroup&& shadeGroup) {
        alive_.assign(size_t(count), 1);
        if (points_.size() < size_t(count)) points_.resize(size_t(count));
        for (int layer = 0; layer < kMaxTransparentLayers; ++layer) {
            hits_.clear();
            for (int ray = 0; ray < count; ++ray) {
                if (!alive_[size_t(ray)]) continue;
                Hit hit{ray, 0, 0};
                if (!findHit(ray, &points_[hits_.size()], &hit)) {
                    alive_[size_t(ray)] = 0;
                    continue;
                }
                hits_.push_back(hit);
            }
            if (hits_.empty()) return;
            const size_t groups = GroupHits();
            for (size_t g = 0; g < groups; ++g) shadeGroup(layer, groups_[g]);
        }
    }

    const Hit& HitAt(int k) const { return hits_[size_t(k)]; }
    SurfacePoint& PointAt(int k) { return points_[size_t(k)]; }
    void Stop(int ray) { alive_[size_t(ray)] = 0; }

  private:
    // Sorts the layer's hits into groups_ by their attributes; returns how many groups.
    size_t GroupHits();

    std::vector<uint8_t> alive_;
    std::vector<Hit> hits_;
    // Reused from layer to layer and trace to trace, so that their colour storage is allocated
    // once.
    std::vector<SurfacePoint> points_;
    std::vector<Group> groups_;
    std::unordered_map<const Attributes*, size_t> groupIndex_;
};

}  // namespace gonio
