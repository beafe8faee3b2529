#pragma once
// The renderer's answers to the shading language for one batch of surface points: coordinate
// spaces, lights (run once per batch, with traced shadows), traced rays, textures, attributes
// and options. One per thread; Begin() points it at the next batch.

#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "renderer/raytrace/ray_scene.h"
#include "renderer/shading/ambient_light_globals.h"
#include "renderer/shading/area_light_samples.h"
#include "renderer/shading/frame_shaders.h"
#include "renderer/shading/named_textures.h"
#include "renderer/shading/surface_shading.h"
#include "shaderlang/message_passing.h"
#include "shaderlang/shading_context.h"

namespace gonio {

struct ShadingFiles;
class PointCloudStore;

// The rays that trace() follows from one batch, all of one depth, in world space.
struct TracedRays {
    std::vector<V3f> org, dir;  // dir unit length
    std::vector<float> tnear;   // past the surface the ray leaves
    std::vector<float>
        tfar;  // empty, or per ray where it ends (the ray-traced built-ins' "maxdist")
    // Empty, or per ray the rays that the shader traced at the point's neighbour points: the
    // ray differentials of the traced ray.
    std::vector<NeighbourRays> neighbours;
    // Empty, or per ray a seed for the random() streams of the points it hits.
    std::vector<uint64_t> randomSeeds;
    float time = 0;
};

// Follows traced rays one level deeper: finds what they hit and shades it (shader_shading.cpp).
class RayTracer {
  public:
    virtual ~RayTracer() = default;
    // Writes ncomps floats per ray, ray-major: the colour arriving along each ray (black where
    // it escapes).
    virtual void TraceRays(int depth, const TracedRays& rays, float* colours) = 0;
};

// The neighbour points of a batch shaded with derivatives: the batch's first `mainCount`
// points are its own, then come their neighbours one pixel along x, then those along y; the
// tables are what UNeighbours, VNeighbours and NeighbourSteps return (shading_context.h).
struct BatchNeighbours {
    int mainCount = 0;
    std::vector<int> u, v;
    std::vector<float> steps;  // 4 × n
};

class RenderContext : public sl::ShadingContext {
  public:
    // `depth`: the depth of the rays whose hits this context shades (0: camera rays).
    RenderContext(const FrameShaders& shaders, const RayScene& scene, const Camera& camera,
                  ShadingFiles& textures, sl::ShaderExecutor& lightExecutor, RayTracer& tracer,
                  int depth, RayCounts& rays);

    // The batch about to be shaded: its points, their current-space positions (3 × n, for the
    // light shaders' Ps) and the shader whose "shader" space applies. With `neighbours`, the
    // lights and traced rays are computed for the main points only and shared with their
    // neighbour points.
    void Begin(const ShadingBatch& batch, const float* currentP, const ShaderInstance* shader,
               const BatchNeighbours* neighbours = nullptr);

    // Message passing: `executor` runs `instance`, the batch's shader of kind `source`, from
    // now on (Begin forgets them). With `captureLights`, Lights() keeps each light's
    // parameters for lightsource().
    void SetMessageShader(sl::MessageSource source, const sl::ShaderInstance* instance,
                          const sl::ShaderExecutor* executor) {
        messageShaders_.Set(source, instance, executor);
    }
    void CaptureLightParameters(bool captureLights) { captureLights_ = captureLights; }

    bool CurrentFromSpace(const std::string& space, int point, Imath::M44f* m) const override;
    bool ShaderParameter(sl::MessageSource source, const std::string& name,
                         sl::MessageValue* value) const override {
        return messageShaders_.Find(source, name, value);
    }
    bool TextureInfo(const std::string& name, const std::string& dataname,
                     std::vector<float>* floats, std::string* text) override;
    const std::vector<sl::LightResult>& Lights() override;
    const std::vector<sl::LightResult>& LightsAt(const float* P, const uint8_t* active) override;
    bool Texture(const std::string& name, int firstChannel, int channels,
                 const TextureWrapModes& wrap, const float* s, const float* t, const float* dsdx,
                 const float* dtdx, const float* dsdy, const float* dtdy, const uint8_t* active,
                 float* out) override;
    bool Environment(const std::string& name, int firstChannel, int channels,
                     const float* directions, const uint8_t* active, float* out) override;
    bool Shadow(const std::string& name, const float* points, const uint8_t* active,
                const sl::ShadowOptions& options, float* out) override;
    std::string FindTexture(const std::string& name) const override;
    bool MeasuredBrdf(const std::string& name, int count, const float* wIn, const float* wOut,
                      const uint8_t* active, float* out) override {
        return textures_.MeasuredBrdf(*this, count, name, wIn, wOut, active, out);
    }
    void Trace(const float* P, const float* R, const uint8_t* active, float* out) override;
    // bake3d(), texture3d(), bake(): point_cloud_lookups.cpp (clouds in world space).
    bool BakePoints(const std::string& file, const float* P, const float* N, const uint8_t* active,
                    const std::vector<sl::PointChannel>& channels) override;
    bool LookupPoints(const std::string& file, const float* P, const float* N,
                      const uint8_t* active,
                      const std::vector<sl::PointChannel>& channels) override;
    // occlusion(), indirectdiffuse(), gather(), transmission(), visibility(): sampled_rays.cpp.
    bool TraceSampledRays(const std::string& what, const sl::SampledRays& rays,
                          sl::SampledHits* hits) override;
    int MainPointCount() const override { return MainCount(); }
    float PixelWidth(const Imath::V3f& P) const override;
    bool ShadesSampledRays() const override;
    bool Attribute(const std::string& name, const sl::TypeSpec& type, int point,
                   std::vector<float>* floats, std::string* text) const override;
    bool Option(const std::string& name, const sl::TypeSpec& type, std::vector<float>* floats,
                std::string* text) const override;
    bool RendererInfo(const std::string& name, const sl::TypeSpec& type, std::vector<float>* floats,
                      std::string* text) const override;
    void RuntimeWarning(const std::string& key, const std::string& message) override;
    void RuntimeError(const std::string& key, const std::string& message) override;
    double ShaderTimeout() const override { return shaders_.ShaderTimeout(); }
    void ShaderTimedOut(double budget) override;
    // Once a run has timed out the frame fails: the later runs stop at their first check.
    bool ShadersStopped() const override { return shaders_.TimedOut(); }
    void Print(const std::string& text) override;
    const int* UNeighbours() const override {
        return neighbours_ ? neighbours_->u.data() : noNeighbours_.data();
    }
    const int* VNeighbours() const override {
        return neighbours_ ? neighbours_->v.data() : noNeighbours_.data();
    }
    const float* NeighbourSteps() const override {
        return neighbours_ ? neighbours_->steps.data() : nullptr;
    }

  private:
    void ReportRuntime(Severity severity, const std::string& key, const std::string& message);
    // Runs the lights for the main points at positions P (3 × n, current space) into
    // `results`, sharing them with the neighbour points; `active` (may be null) limits them.
    void EvaluateLights(const float* P, const uint8_t* active,
                        std::vector<sl::LightResult>* results);
    const float* MainPoints(const float* P, const uint8_t* active);
    // One run of light `index` for the main points, with its area weight and shadows.
    sl::LightResult RunLight(int index, const FrameLight& light, const sl::ShaderGlobals& globals,
                             const uint8_t* active);
    void ShareLightWithNeighbours(sl::LightResult* result) const;
    void TraceShadows(sl::LightResult* light);
    // The seed of point i's shadow-map jitter: its random() stream's, else its position's.
    uint64_t ShadowSeed(int i, const V3f& P) const;
    // The points whose lights and traced rays are computed (the rest share them).
    int MainCount() const { return neighbours_ ? neighbours_->mainCount : n_; }
    // Copies the main points' values to their neighbour points in `planes` planes of n floats.
    template <typename T>
    void ShareWithNeighbours(std::vector<T>* values, int planes) const;
    // The world-space ray from current-space P and R at point i; false if R is zero.
    bool WorldRay(const float* P, const float* R, int i, V3f* org, V3f* dir) const;

    const FrameShaders& shaders_;
    const RayScene& scene_;
    const Camera& camera_;
    NamedTextures textures_;
    ShadowMapCache& shadowMaps_;  // the render's, shared by all threads
    PointCloudStore& pointClouds_;
    sl::ShaderExecutor& lightExecutor_;
    RayTracer& tracer_;
    int depth_;
    RayCounts& rays_;  // the worker's: shadow and sampled rays are counted here
    const ShadingBatch* batch_ = nullptr;
    const float* currentP_ = nullptr;
    const float* lightP_ = nullptr;  // P of the points the lights run for (3 × MainCount())
    std::vector<float> mainP_;
    const BatchNeighbours* neighbours_ = nullptr;
    const ShaderInstance* shader_ = nullptr;
    std::vector<sl::LightResult> lights_;       // at the surface's P, cached per batch
    std::vector<sl::LightResult> movedLights_;  // LightsAt's, per call
    std::vector<uint8_t> mainActive_;
    bool lightsValid_ = false;
    AreaLightPoints areaPoints_;     // the running area light's sample points
    bool runningLight_ = false;      // a light shader is running (Shadow's fallback)
    bool shadowMapMissing_ = false;  // ... and asked for a shadow map that cannot be read
    std::vector<int> noNeighbours_;
    M44f worldFromCurrent_;
    sl::MessageShaders messageShaders_;
    bool captureLights_ = false;
    AmbientLightGlobals ambientGlobals_;  // an ambient light's P, N, I (the surface's)
};

}  // namespace gonio
