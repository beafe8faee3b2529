#pragma once
// The global-illumination path tracer (issue 17 item 4; docs/path-tracing.md): unidirectional
// paths from the camera with next-event estimation. At every vertex each light the surface sees
// is sampled through its light shader (point-like lights at the vertex; area lights at one
// point drawn uniformly on their surface, AreaLightGeometry), shadows traced; one direction is
// drawn from the BSDF (path_bsdf.h) to go on. A path that hits an area light's surface from its
// emitting side gathers its radiance, and the two ways of finding the same light (the light's
// sample, the BSDF's) are weighed by the power heuristic (Veach 1997, eq. 9.13) so that both
// count once. Russian roulette ends paths without bias: after `rrdepth` bounces a path goes on
// with probability q = min(1, max β) and its throughput β is divided by q. A path's random numbers
// come from one stream seeded by its pixel sample (the camera sample's random() seed), so an image
// is the same whatever the thread count.

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "base/diagnostics.h"
#include "renderer/pathtrace/light_shader_context.h"
#include "renderer/pathtrace/path_materials.h"
#include "renderer/pathtrace/path_options.h"
#include "renderer/raytrace/camera.h"
#include "renderer/raytrace/ray_scene.h"
#include "renderer/shading/frame_shaders.h"

namespace gonio {

class PathWorker;

class PathIntegrator {
  public:
    // Null when the frame does not ask for path tracing (Option "pathtrace" "enable").
    static std::unique_ptr<PathIntegrator> ForFrame(const Frame& frame, const RayScene& scene,
                                                    Diagnostics& diagnostics);
    PathIntegrator(const Frame& frame, const RayScene& scene, Diagnostics& diagnostics,
                   const PathTraceOptions& options);
    ~PathIntegrator();

    // One per thread.
    std::unique_ptr<PathWorker> MakeWorker() const;

  private:
    friend class PathWorker;
    const Frame& frame_;
    const RayScene& scene_;
    Diagnostics& diagnostics_;
    PathTraceOptions options_;
    FrameShaders shaders_;
    PathMaterials materials_;
    Imath::M44f worldFromCurrent_;
    float crossSign_;
    std::map<const SceneShape*, int>
        emitters_;  // area light shapes: their Frame::lights index  // +1, or -1 where camera space
                    // has the other handedness than world's
};

// The per-thread state of the path tracer: its light-shader executor and BSDF scratch.
class PathWorker {
  public:
    explicit PathWorker(const PathIntegrator& integrator);

    // The radiance arriving along a camera ray (ncomps floats into L); the distance (ray
    // parameter) of its first hit into *depth. False when the ray hits nothing.
    bool Radiance(const CameraRay& ray, uint64_t seed, float* L, float* depth);
    uint64_t RaysTraced() const { return rays_; }

  private:
    ShadingFrame MakeFrame(const SurfacePoint& sp, const Imath::V3f& wo,
                           const PathMaterial& material) const;
    // Σ over the point's lights of f · Cl · cos θ, shadowed, area lights weighed by MIS
    // (ncomps floats into Ld); `state` is the path's random stream.
    void DirectLight(const SurfacePoint& sp, const ShadingFrame& frame, float time, uint64_t* state,
                     float* Ld);
    // Runs light `index`'s shader for the surface point Ps (world) with normal Ns (world; zero
    // where there is none), with the light's own P and N (world; an area light's surface
    // point) when `area` is set.
    bool RunLight(int index, const Imath::V3f& Ps, const Imath::V3f& Ns,
                  const AreaLightSample* area, float time, uint64_t seed, sl::LightResult* result);
    // The radiance an area light's surface sends from hit sp_ towards `from` (world), into
    // Le_: what its shader's Cl is per unit area, times d² / cos θ at the light. False when the
    // hit is not on its emitting side.
    bool Emitted(int index, const Imath::V3f& from, float time, uint64_t seed);
    // The fraction of light (ncomps floats into T) that reaches P along dir over dist through
    // the surfaces in between (shadow_transmission.h); false when none does.
    bool Transmittance(const Imath::V3f& P, const Imath::V3f& Ng, const Imath::V3f& dir, float dist,
                       float time, float* T);
    // The next hit the path scatters at (into sp_, its distance into *t), among those it sees
    // (one-sided surfaces from the front: NextVisibleHit). Stochastic transparency: a surface of
    // mean opacity m < 1 is passed with probability 1 − m, β multiplied by (1 − Os)/(1 − m), else
    // kept with β·Os/m, which is unbiased; opaque surfaces draw no number. At most
    // kMaxTransparentLayers surfaces are passed.
    bool NextScatteringHit(const Imath::V3f& org, const Imath::V3f& dir, float tnear, float tfar,
                           float time, uint64_t* state, float* t);

    const PathIntegrator& c_;
    int ncomps_;
    sl::ShaderExecutor lightExecutor_;
    LightShaderContext lightContext_;
    VertexBsdf bsdf_;
    SurfacePoint sp_;
    std::vector<float> beta_, f_, Ld_, Le_, T_;
    uint64_t rays_ = 0;
};

}  // namespace gonio
