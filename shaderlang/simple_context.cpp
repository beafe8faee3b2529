#include "shaderlang/simple_context.h"

#include <algorithm>

#include "shaderlang/message_passing.h"

namespace gonio::sl {

void SimpleShadingContext::BeginBatch(const ShaderGlobals& globals, int colorComponents) {
    globals_ = globals;
    globals_.primvars.clear();
    n_ = globals.n;
    colorComponents_ = colorComponents;
    lightsValid_ = false;
    uNeighbours_.assign(size_t(n_), -1);
    vNeighbours_.assign(size_t(n_), -1);
    SeedRandom(nullptr);
}

bool SimpleShadingContext::CurrentFromSpace(const std::string& space, int, Imath::M44f* m) const {
    static const char* const kKnown[] = {"current", "camera", "world",  "object",
                                         "shader",  "screen", "raster", "NDC"};
    m->makeIdentity();
    return std::find_if(std::begin(kKnown), std::end(kKnown),
                        [&](const char* k) { return space == k; }) != std::end(kKnown);
}

const std::vector<LightResult>& SimpleShadingContext::Lights() {
    if (lightsValid_) return lightResults_;
    RunLights(globals_.P, &lightResults_);
    lightsValid_ = true;
    return lightResults_;
}

const std::vector<LightResult>& SimpleShadingContext::LightsAt(const float* P, const uint8_t*) {
    RunLights(P, &movedLightResults_);
    return movedLightResults_;
}

void SimpleShadingContext::RunLights(const float* P, std::vector<LightResult>* results) {
    results->clear();
    // The light shaders see the given points as Ps; their own P is the origin.
    ShaderGlobals g;
    g.n = n_;
    g.Ps = P;
    g.Ns = globals_.N;
    g.E[0] = globals_.E[0], g.E[1] = globals_.E[1], g.E[2] = globals_.E[2];
    g.time = globals_.time;
    for (size_t i = 0; i < lights_.size(); ++i) {
        LightResult result;
        lightExecutor_.RunLight(*lights_[i], g, *this, &result);
        result.shaderIndex = int(i);
        CaptureLightParameters(*lights_[i], lightExecutor_, n_, &result);
        results->push_back(std::move(result));
    }
}

bool SimpleShadingContext::Shadow(const std::string&, const float*, const uint8_t*,
                                  const ShadowOptions&, float* out) {
    std::fill_n(out, size_t(n_), 0.0f);  // unshadowed
    return false;
}

void SimpleShadingContext::Trace(const float*, const float*, const uint8_t*, float* out) {
    std::fill_n(out, size_t(colorComponents_) * n_, 0.0f);  // nothing to hit
}

void SimpleShadingContext::RuntimeWarning(const std::string& key, const std::string& message) {
    // Reported as a compiler would, at the shader statement, once per key and statement.
    const std::string& where = Statement();
    diagnostics_.WarningOnce(where + key, StatementLoc(where, "gonio shade"), message);
}

void SimpleShadingContext::Print(const std::string& text) { std::fputs(text.c_str(), printSink_); }

}  // namespace gonio::sl
