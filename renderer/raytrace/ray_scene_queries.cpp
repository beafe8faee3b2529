// Rays through a RayScene: the nearest hit and occlusion, with solids (SolidBegin) combined
// from the crossings a ray collects with their surfaces.

#include <limits>
#include <vector>

#include "renderer/raytrace/ray_scene_impl.h"
#include "renderer/raytrace/transforms.h"
#include "renderer/raytrace/transparent_layers.h"

namespace gonio {

using Imath::M44f;
using Imath::V3f;

bool RayScene::Impl::Trace(const SceneLevel& level, const V3f& org, const V3f& dir, float tnear,
                           float tfar, float time, RayHit* hit) const {
    if (!level.scene) return false;  // an empty frame's
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = MakeRay(org, dir, tnear, tfar, time);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(level.scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit->t = rh.ray.tfar;
    hit->time = time;
    hit->geomID = rh.hit.geomID;
    hit->primID = rh.hit.primID;
    hit->instID = &level == &solids ? kSolidLevel : rh.hit.instID[0];
    hit->u = rh.hit.u;
    hit->v = rh.hit.v;
    hit->flipNormal = false;
    const V3f ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    const bool quadric = RecordOf(*hit).quadric != nullptr;
    hit->Ng = quadric ? V3f(0) : ng;
    hit->objectP = quadric ? ng : V3f(0);  // QuadricIntersect's point
    return true;
}

bool RayScene::Impl::Enters(const RayHit& hit, const V3f& org, const V3f& dir) const {
    const GeometryRecord& record = RecordOf(hit);
    const ObjectHit object = EvaluateObject(record, hit, org + hit.t * dir, dir, M44f());
    const V3f worldNg = TransformNormal(record.objectFromSpace, object.geometry.Ng);
    return (worldNg.dot(dir) < 0) != record.shape->flipNormals;
}

bool RayScene::Impl::IntersectSolids(const V3f& org, const V3f& dir, float tnear, float tfar,
                                     float time, RayHit* hit) const {
    // Every crossing to the end of the ray: those beyond tfar say where the ray starts.
    thread_local std::vector<SolidCrossing> crossings;
    thread_local std::vector<RayHit> hits;
    crossings.clear();
    hits.clear();
    RayHit next;
    float from = tnear;
    while (crossings.size() < kMaxSolidCrossings &&
           Trace(solids, org, dir, from, std::numeric_limits<float>::infinity(), time, &next)) {
        crossings.push_back({next.t, RecordOf(next).shape->solid, Enters(next, org, dir)});
        hits.push_back(next);
        from = ContinuePast(next.t);
    }
    if (crossings.empty()) return false;
    bool flip = false;
    const int first = trees->FirstBoundary(crossings, tfar, &flip);
    if (first < 0) return false;
    *hit = hits[size_t(first)];
    hit->flipNormal = flip;
    return true;
}

bool RayScene::Intersect(const V3f& org, const V3f& dir, float tnear, float tfar, float time,
                         RayHit* hit) const {
    bool found = impl_->Trace(impl_->top, org, dir, tnear, tfar, time, hit);
    // Frames without solids pay this one test.
    RayHit solid;
    if (impl_->trees &&
        impl_->IntersectSolids(org, dir, tnear, found ? hit->t : tfar, time, &solid)) {
        *hit = solid;
        found = true;
    }
    // And frames without archives out of view this one: the ray reaches those its way to the
    // hit passes through.
    if (impl_->lazyScene) impl_->MarkLazyProcedurals(org, dir, tnear, found ? hit->t : tfar, time);
    return found;
}

bool RayScene::Occluded(const V3f& org, const V3f& dir, float tnear, float tfar, float time) const {
    if (!impl_->top.scene) return false;  // an empty frame's
    // The whole segment, not only up to an occluder: occlusion does not say which is first.
    if (impl_->lazyScene) impl_->MarkLazyProcedurals(org, dir, tnear, tfar, time);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = impl_->MakeRay(org, dir, tnear, tfar, time);
    rtcOccluded1(impl_->top.scene, &context, &ray);
    if (ray.tfar < 0) return true;
    RayHit solid;
    return impl_->trees && impl_->IntersectSolids(org, dir, tnear, tfar, time, &solid);
}

}  // namespace gonio
