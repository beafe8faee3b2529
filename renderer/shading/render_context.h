#pragma once
// The renderer's answers to the shading language for one batch of surface points: coordinate
// spaces, lights (run once per batch, with traced shadows), traced rays, textures, attributes
// and options. One per thread; Begin() points it at the next batch.

#include <mutex>
#include <vector>

#include "render/ray_scene.h"
#include "shaderlang/shading_context.h"
#include "shading/frame_shaders.h"
#include "shading/surface_shading.h"

namespace gonio {

class TextureLookup;

class RenderContext : public sl::ShadingContext {
  public:
    RenderContext(const FrameShaders& shaders, const RayScene& scene, const Camera& camera,
                  TextureLookup& textures, sl::ShaderExecutor& lightExecutor);

    // The batch about to be shaded: its points, their current-space positions (3 × n, for the
    // light shaders' Ps) and the shader whose "shader" space applies.
    void Begin(const ShadingBatch& batch, const float* currentP, const ShaderInstance* shader);

    bool CurrentFromSpace(const std::string& space, int point, Imath::M44f* m) const override;
    const std::vector<sl::LightResult>& Lights() override;
    bool Texture(const std::string& name, int firstChannel, int channels, const float* s,
                 const float* t, const float* dsdx, const float* dtdx, const float* dsdy,
                 const float* dtdy, const uint8_t* active, float* out) override;
    bool Environment(const std::string& name, int firstChannel, int channels,
                     const float* directions, const uint8_t* active, float* out) override;
    bool Shadow(const std::string& name, const float* points, const uint8_t* active,
                float* out) override;
    void Trace(const float* P, const float* R, const uint8_t* active, float* out) override;
    bool Attribute(const std::string& name, const sl::TypeSpec& type, int point,
                   std::vector<float>* floats, std::string* text) const override;
    bool Option(const std::string& name, const sl::TypeSpec& type, std::vector<float>* floats,
                std::string* text) const override;
    bool RendererInfo(const std::string& name, const sl::TypeSpec& type, std::vector<float>* floats,
                      std::string* text) const override;
    void RuntimeWarning(const std::string& key, const std::string& message) override;
    void Print(const std::string& text) override;
    const int* UNeighbours() const override { return noNeighbours_.data(); }
    const int* VNeighbours() const override { return noNeighbours_.data(); }

  private:
    void TraceShadows(sl::LightResult* light) const;

    const FrameShaders& shaders_;
    const RayScene& scene_;
    const Camera& camera_;
    TextureLookup& textures_;
    sl::ShaderExecutor& lightExecutor_;
    const ShadingBatch* batch_ = nullptr;
    const float* currentP_ = nullptr;
    const ShaderInstance* shader_ = nullptr;
    std::vector<sl::LightResult> lights_;
    bool lightsValid_ = false;
    std::vector<int> noNeighbours_;
    M44f worldFromCurrent_;
};

}  // namespace gonio
