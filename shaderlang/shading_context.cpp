#include "shaderlang/shading_context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <mutex>

#include "base/diagnostics.h"

namespace gonio::sl {

bool ShadingContext::Unavailable(const std::string& what, int channels, float* out) {
    std::fill_n(out, size_t(channels) * size_t(n_), 0.0f);
    RuntimeWarning(what, what + " is not available here; it gives 0");
    return false;
}

const std::vector<LightResult>& ShadingContext::Lights() {
    static const std::vector<LightResult> kNone;
    return kNone;
}

bool ShadingContext::Texture(const std::string& name, int, int channels, const TextureWrapModes&,
                             const float*, const float*, const float*, const float*, const float*,
                             const float*, const uint8_t*, float* out) {
    return Unavailable("texture(\"" + name + "\")", channels, out);
}

bool ShadingContext::Environment(const std::string& name, int, int channels, const float*,
                                 const uint8_t*, float* out) {
    return Unavailable("environment(\"" + name + "\")", channels, out);
}

bool ShadingContext::Shadow(const std::string& name, const float*, const uint8_t*,
                            const ShadowOptions&, float* out) {
    return Unavailable("shadow(\"" + name + "\")", 1, out);
}

bool ShadingContext::BakePoints(const std::string& file, const float*, const float*, const uint8_t*,
                                const std::vector<PointChannel>&) {
    RuntimeWarning("bake " + file,
                   "bake3d(\"" + file + "\"): point clouds are baked by the renderer only");
    return false;
}

bool ShadingContext::LookupPoints(const std::string& file, const float*, const float*,
                                  const uint8_t*, const std::vector<PointChannel>& channels) {
    for (const PointChannel& c : channels)
        for (int k = 0; k < c.width; ++k) std::fill_n(c.values.data + size_t(k) * n_, n_, 0.0f);
    RuntimeWarning("texture3d " + file,
                   "texture3d(\"" + file + "\"): point clouds are read by the renderer only");
    return false;
}

void ShadingContext::Trace(const float*, const float*, const uint8_t*, float* out) {
    Unavailable("trace()", colorComponents_, out);
}

bool ShadingContext::TraceSampledRays(const std::string& what, const SampledRays&, SampledHits*) {
    RuntimeWarning(what, what + " traces rays, and there is no scene to trace here; it gives 0");
    return false;
}

bool ShadingContext::MeasuredBrdf(const std::string& name, int count, const float*, const float*,
                                  const uint8_t*, float* out) {
    std::fill_n(out, size_t(colorComponents_) * size_t(count), 0.0f);
    RuntimeWarning("brdf " + name,
                   "brdf(\"" + name + "\"): measured BRDFs are read by the renderer only");
    return false;
}

bool ShadingContext::Attribute(const std::string&, const TypeSpec&, int, std::vector<float>*,
                               std::string*) const {
    return false;
}

bool ShadingContext::Option(const std::string&, const TypeSpec&, std::vector<float>*,
                            std::string*) const {
    return false;
}

bool ShadingContext::RendererInfo(const std::string& name, const TypeSpec& type,
                                  std::vector<float>*, std::string* text) const {
    if (name != "renderer" || type.base != BaseType::String) return false;
    *text = "gonio";
    return true;
}

void ShadingContext::Print(const std::string& text) {
    static std::mutex printMutex;
    std::lock_guard<std::mutex> lock(printMutex);
    std::fputs(text.c_str(), stdout);
}

FileLoc StatementLoc(const std::string& statement, const std::string& fallbackFile) {
    FileLoc loc;
    const size_t colon = statement.rfind(':');
    if (colon != std::string::npos && colon + 1 < statement.size() &&
        std::isdigit(static_cast<unsigned char>(statement[colon + 1]))) {
        loc.file = std::make_shared<const std::string>(statement.substr(0, colon));
        loc.line = std::atoi(statement.c_str() + colon + 1);
    } else {
        loc.file = std::make_shared<const std::string>(fallbackFile);
    }
    return loc;
}

void ShadingContext::ShaderTimedOut(double budget) {
    RuntimeError("shader time budget",
                 "the shader ran longer than its time budget of " + FormatNumber(budget) +
                     " s (Option \"limits\" \"shadertimeout\"; an endless loop?) and was stopped");
}

}  // namespace gonio::sl
