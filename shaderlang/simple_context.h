#pragma once
// A ShadingContext for shading without a scene (`gonio shade`, tests): every coordinate system
// is the identity, textures are missing (black, with a warning), attributes and options are
// absent, and lights are light-shader instances evaluated at the batch's P on demand (with
// their parameters kept for lightsource()). random() draws from streams seeded by the point's
// index in the grid.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "shaderlang/shading_context.h"
#include "shaderlang/shading_system.h"

namespace gonio::sl {

class SimpleShadingContext : public ShadingContext {
  public:
    SimpleShadingContext(Diagnostics& diagnostics, std::FILE* printSink = stdout)
        : diagnostics_(diagnostics), printSink_(printSink) {}

    void AddLight(std::shared_ptr<ShaderInstance> light) { lights_.push_back(std::move(light)); }
    // Starts a batch: n points whose globals (P, N, ...) the lights see as Ps.
    void BeginBatch(const ShaderGlobals& globals, int colorComponents);

    bool CurrentFromSpace(const std::string& space, int point, Imath::M44f* m) const override;
    const std::vector<LightResult>& Lights() override;
    const std::vector<LightResult>& LightsAt(const float* P, const uint8_t* active) override;
    bool Shadow(const std::string& name, const float* points, const uint8_t* active,
                const ShadowOptions& options, float* out) override;
    void Trace(const float* P, const float* R, const uint8_t* active, float* out) override;
    void RuntimeWarning(const std::string& key, const std::string& message) override;
    void Print(const std::string& text) override;
    const int* UNeighbours() const override { return uNeighbours_.data(); }
    const int* VNeighbours() const override { return vNeighbours_.data(); }

    // Neighbour indices for derivatives (-1: none); sized n by BeginBatch (all -1).
    std::vector<int>& UNeighbourTable() { return uNeighbours_; }
    std::vector<int>& VNeighbourTable() { return vNeighbours_; }

  private:
    void RunLights(const float* P, std::vector<LightResult>* results);

    Diagnostics& diagnostics_;
    std::FILE* printSink_;
    std::vector<std::shared_ptr<ShaderInstance>> lights_;
    ShaderGlobals globals_;
    bool lightsValid_ = false;
    std::vector<LightResult> lightResults_;       // at the batch's P
    std::vector<LightResult> movedLightResults_;  // LightsAt's
    std::vector<int> uNeighbours_, vNeighbours_;
    ShaderExecutor lightExecutor_;
};

}  // namespace gonio::sl
