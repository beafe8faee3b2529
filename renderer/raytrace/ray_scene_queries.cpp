// Rays through a RayScene: the nearest hit and occlusion, with solids (SolidBegin) combined
// from the crossings a ray collects with their surfaces.

#include <algorithm>
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
    MakeHit(level, rh.ray.tfar, time, rh.hit.geomID, rh.hit.primID, rh.hit.instID[0], rh.hit.u,
            rh.hit.v, V3f(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z), hit);
    return true;
}

void RayScene::Impl::MakeHit(const SceneLevel& level, float tfar, float time, unsigned geomID,
                             unsigned primID, unsigned instID, float u, float v, const V3f& ng,
                             RayHit* hit) const {
    hit->t = tfar;
    hit->time = time;
    hit->geomID = geomID;
    hit->primID = primID;
    hit->instID = &level == &solids ? kSolidLevel : instID;
    hit->u = u;
    hit->v = v;
    hit->flipNormal = false;
    const bool quadric = RecordOf(*hit).quadric != nullptr;
    hit->Ng = quadric ? V3f(0) : ng;
    hit->objectP = quadric ? ng : V3f(0);  // QuadricIntersect's point
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

void RayScene::IntersectCoherent(int count, const CoherentRay* rays, RayHit* hits,
                                 uint8_t* found) const {
    const Impl& s = *impl_;
    if (!s.top.scene || s.trees || s.lazyScene) {
        for (int i = 0; i < count; ++i) {
            const CoherentRay& r = rays[i];
            found[i] = Intersect(r.org, r.dir, r.tnear, r.tfar, r.time, &hits[i]);
        }
        return;
    }
    // AVX2's width: Embree's 8-wide packet traversal on the CPUs it targets.
    constexpr int kPacket = 8;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (int first = 0; first < count; first += kPacket) {
        const int n = std::min(kPacket, count - first);
        alignas(32) int valid[kPacket];
        alignas(32) RTCRayHit8 packet;
        for (int k = 0; k < kPacket; ++k) {
            valid[k] = k < n ? -1 : 0;
            const CoherentRay& r = rays[first + std::min(k, n - 1)];
            packet.ray.org_x[k] = r.org.x, packet.ray.org_y[k] = r.org.y;
            packet.ray.org_z[k] = r.org.z;
            packet.ray.dir_x[k] = r.dir.x, packet.ray.dir_y[k] = r.dir.y;
            packet.ray.dir_z[k] = r.dir.z;
            packet.ray.tnear[k] = r.tnear, packet.ray.tfar[k] = r.tfar;
            packet.ray.time[k] = s.EmbreeTime(r.time);
            packet.ray.mask[k] = ~0u, packet.ray.id[k] = 0, packet.ray.flags[k] = 0;
            packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect8(valid, s.top.scene, &context, &packet);
        for (int k = 0; k < n; ++k) {
            const int i = first + k;
            found[i] = packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
            if (!found[i]) continue;
            s.MakeHit(s.top, packet.ray.tfar[k], rays[i].time, packet.hit.geomID[k],
                      packet.hit.primID[k], packet.hit.instID[0][k], packet.hit.u[k],
                      packet.hit.v[k],
                      V3f(packet.hit.Ng_x[k], packet.hit.Ng_y[k], packet.hit.Ng_z[k]), &hits[i]);
        }
    }
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
