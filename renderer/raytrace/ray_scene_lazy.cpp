// The DelayedReadArchives a frame has not read (renderer/scene/lazy_procedurals.h) as seen by
// the ray tracer: their bounds in an Embree scene of their own, one user primitive each, which
// every ray crosses on its way to its hit (RayScene::Intersect, Occluded) and which marks the
// bounds it passes through and reports no hit, so that a ray meets every one on its way.
#include <algorithm>
#include <utility>

#include "renderer/raytrace/ray_scene_impl.h"

namespace gonio {

namespace {

// Whether org + t·dir meets `box` for some t in [t0, t1] (the slab test, Kay and Kajiya 1986).
bool SegmentMeetsBox(const Box3f& box, const V3f& org, const V3f& dir, float t0, float t1) {
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0) {
            if (org[a] < box.min[a] || org[a] > box.max[a]) return false;
            continue;
        }
        float near = (box.min[a] - org[a]) / dir[a], far = (box.max[a] - org[a]) / dir[a];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    return true;
}

void LazyBounds(const RTCBoundsFunctionArguments* args) {
    const auto* lazy = static_cast<const LazyProcedurals*>(args->geometryUserPtr);
    const Box3f& box = lazy->All()[args->primID].worldBound;
    RTCBounds* b = args->bounds_o;
    b->lower_x = box.min.x, b->lower_y = box.min.y, b->lower_z = box.min.z;
    b->upper_x = box.max.x, b->upper_y = box.max.y, b->upper_z = box.max.z;
}

void LazyReached(const RTCOccludedFunctionNArguments* args) {
    const auto* lazy = static_cast<const LazyProcedurals*>(args->geometryUserPtr);
    const Box3f& box = lazy->All()[args->primID].worldBound;
    RTCRayN* rays = args->ray;
    const unsigned N = args->N;
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i]) continue;
        const V3f org(RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i),
                      RTCRayN_org_z(rays, N, i));
        const V3f dir(RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i),
                      RTCRayN_dir_z(rays, N, i));
        if (SegmentMeetsBox(box, org, dir, RTCRayN_tnear(rays, N, i), RTCRayN_tfar(rays, N, i)))
            lazy->MarkReached(args->primID);
    }
}

}  // namespace

void RayScene::Impl::WatchLazyProcedurals(const LazyProcedurals& lazy) {
    lazyScene = rtcNewScene(device);
    // Robust traversal: a ray grazing a bound must mark it whatever the BVH's shape.
    rtcSetSceneFlags(lazyScene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, unsigned(lazy.All().size()));
    rtcSetGeometryUserData(g, const_cast<LazyProcedurals*>(&lazy));
    rtcSetGeometryBoundsFunction(g, LazyBounds, nullptr);
    rtcSetGeometryOccludedFunction(g, LazyReached);
    rtcCommitGeometry(g);
    rtcAttachGeometry(lazyScene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(lazyScene);
}

void RayScene::Impl::MarkLazyProcedurals(const V3f& org, const V3f& dir, float tnear, float tfar,
                                         float time) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = MakeRay(org, dir, tnear, tfar, time);
    rtcOccluded1(lazyScene, &context, &ray);
}

}  // namespace gonio
