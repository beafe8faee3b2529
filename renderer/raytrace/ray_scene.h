#pragma once
// The frame's geometry on Embree: the only interface to the ray tracing kernels. Built once per
// frame; Intersect, Occluded and Evaluate are thread-safe. Solids (SolidBegin) are resolved
// inside Intersect and Occluded, so that every kind of ray sees the same CSG.

#include <Imath/ImathVec.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "renderer/raytrace/surface_point.h"
#include "renderer/scene/frame.h"

namespace gonio {

struct RayHit {
    float t = 0;
    float time = 0;  // when the ray travelled (shutter time)
    unsigned geomID = 0, primID = 0, instID = 0;
    float u = 0, v = 0;
    // The geometric normal as Embree reports it: not normalised, in the space the hit geometry
    // was built in. Zero for a quadric, whose normal Evaluate derives from objectP.
    Imath::V3f Ng;
    // A quadric's hit point in its object space, from which Evaluate derives (u, v) and the
    // normal (u, v above are then 0). Zero for the other kinds.
    Imath::V3f objectP;
    // A CSG hit on the surface of a subtracting or intersecting solid whose outward normal is
    // the reverse of the combined solid's there (RISpec 3.2 §5.9): Evaluate turns it round.
    bool flipNormal = false;
};

// The little a particle tracer needs at a hit (RayScene::EvaluateLean): the point, the normals
// and the colour, without (u, v), derivatives, s, t or primitive-variable stencils.
struct LeanSurfacePoint {
    Imath::V3f P;  // world space
    // World space, unit length. Unlike SurfacePoint's they may face either side of the
    // surface: a caller faces them towards the ray.
    Imath::V3f N, Ng;
    std::vector<float> Cs;  // ncomps values
    const SceneShape* shape = nullptr;
    const Attributes* attributes = nullptr;
    SurfacePoint scratch;  // reused by EvaluateLean for shapes it evaluates in full
};

class RayScene {
  public:
    // Embree's robust traversal (RTC_SCENE_FLAG_ROBUST) gives up some speed so that rays
    // through the shared edges and vertices of a mesh are not missed: a camera ray slipping
    // through shows as a speck. The photon tracer counts every photon that slips below the
    // surface, and 3 M paths through the periodic grass tile gave the same counts either way
    // (docs/brdflight.md), so it takes the faster default traversal.
    enum class Traversal { kRobust, kFast };

    RayScene(const Frame& frame, Diagnostics& diagnostics,
             Traversal traversal = Traversal::kRobust);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // The nearest hit of org + t·dir with tnear <= t <= tfar, at `time` in the shutter
    // interval (moving geometry is where it is then). On a solid it is the nearest point of
    // the combined solid's surface, whether the ray starts outside or inside it.
    bool Intersect(const Imath::V3f& org, const Imath::V3f& dir, float tnear, float tfar,
                   float time, RayHit* hit) const;
    // Intersect for each of `count` rays that leave about one point in about one direction
    // (camera rays of neighbouring samples): found[i] says whether rays[i] hit, hits[i] where.
    // Embree traverses them 8 at a time, sharing the work of the nodes they all pass through;
    // frames with solids or archives not yet read take them one by one.
    struct CoherentRay {
        Imath::V3f org, dir;
        float tnear, tfar, time;
    };
    void IntersectCoherent(int count, const CoherentRay* rays, RayHit* hits, uint8_t* found) const;
    // Whether anything lies on org + t·dir for tnear <= t <= tfar at `time`.
    bool Occluded(const Imath::V3f& org, const Imath::V3f& dir, float tnear, float tfar,
                  float time) const;
    // The surface at a hit, in world space, with Cs, Os, s, t interpolated.
    SurfacePoint Evaluate(const Imath::V3f& org, const Imath::V3f& dir, const RayHit& hit) const;
    // The same into an existing point, reusing its colour storage (no allocation in loops).
    void Evaluate(const Imath::V3f& org, const Imath::V3f& dir, const RayHit& hit,
                  SurfacePoint* sp) const;
    // Evaluate in two parts, for camera hits that may take another hit's shading (ShadingRate):
    // EvaluateGeometry fills P, N, Ng, shape, record, attributes, the uniform stencil and
    // worldFromObject (what visibility and sharing look at), and u, v, dPdu and dPdv (in object
    // space) and the other stencils unless they cost more than the normals (SurfacePoint::
    // pending); FinishEvaluate then completes those, makes the tangents world space and adds
    // Cs, Os, s and t, for the hits that are shaded. The two give exactly what Evaluate gives.
    void EvaluateGeometry(const Imath::V3f& org, const Imath::V3f& dir, const RayHit& hit,
                          SurfacePoint* sp) const;
    void FinishEvaluate(SurfacePoint* sp) const;

    // The point, normals and colour at a hit, for loops that trace many paths: flat triangle
    // meshes take them from Embree's own normal and quadrics from their implicit equation
    // (either without N or Cs primitive variables), everything else from Evaluate. Reuses
    // `out`'s storage (no allocation once it has grown).
    void EvaluateLean(const Imath::V3f& org, const Imath::V3f& dir, const RayHit& hit,
                      LeanSurfacePoint* out) const;

    // The primitive variable `name` of the shape at a hit, interpolated by its class (in the
    // primitive's object space, as given). False if the shape has no such variable.
    bool InterpolatePrimVar(const SurfacePoint& sp, const std::string& name,
                            std::vector<float>* out) const;

    size_t GeometryCount() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace gonio
