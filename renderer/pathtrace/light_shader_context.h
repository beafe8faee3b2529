#pragma once
// The shading context light shaders run in at a path vertex: one point at a time, in camera
// ("current") space as everywhere in shading. A light shader needs spaces (its "shader" space
// is the light's), its parameters and Ps; what a surface shader would ask for (textures, traced
// rays, other lights) is unavailable here and gives the context's defaults.

#include <Imath/ImathMatrix.h>

#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "renderer/scene/frame.h"
#include "shaderlang/shading_context.h"

namespace gonio {

class LightShaderContext : public sl::ShadingContext {
  public:
    LightShaderContext(const Frame& frame, Diagnostics& diagnostics);

    // The light whose shader runs next ("shader" space) and the point's random() seed.
    void Begin(const ShaderInstance* lightShader, uint64_t seed);

    bool CurrentFromSpace(const std::string& space, int point, Imath::M44f* m) const override;
    void RuntimeWarning(const std::string& key, const std::string& message) override;
    const int* UNeighbours() const override { return &noNeighbour_; }
    const int* VNeighbours() const override { return &noNeighbour_; }

  private:
    const Frame& frame_;
    Diagnostics& diagnostics_;
    const ShaderInstance* shader_ = nullptr;
    int noNeighbour_ = -1;
};

}  // namespace gonio
