#include "renderer/shading/named_textures.h"

#include <algorithm>
#include <memory>

#include "base/search_path.h"

namespace gonio {

const std::string& NamedTextures::Find(const std::string& name) const {
    auto known = found_.find(name);
    if (known != found_.end()) return known->second;
    const std::string found = FindOnSearchPath(name, searchPath_);
    return found_.emplace(name, found.empty() ? name : found).first->second;
}

// OpenImageIO says why a file cannot be read only on the first failed lookup; the warning is
// given once, but another thread's failure may be the one to give it.
std::string NamedTextures::Why() const {
    const std::string error = lookup_.LastError();
    return error.empty() ? "cannot read it" : error;
}

bool NamedTextures::Texture(sl::ShadingContext& asker, int n, const std::string& name,
                            int firstChannel, int channels, const TextureWrapModes& wrap,
                            const float* s, const float* t, const float* dsdx, const float* dtdx,
                            const float* dsdy, const float* dtdy, const uint8_t* active,
                            float* out) {
    const bool ok = lookup_.Texture(Find(name), firstChannel, channels, wrap, n, s, t, dsdx, dtdx,
                                    dsdy, dtdy, active, out);
    if (!ok) asker.RuntimeWarning("texture " + name, "texture \"" + name + "\": " + Why());
    return ok;
}

bool NamedTextures::Environment(sl::ShadingContext& asker, int n, const std::string& name,
                                int firstChannel, int channels, const float* directions,
                                const uint8_t* active, float* out) {
    const bool ok =
        lookup_.Environment(Find(name), firstChannel, channels, n, directions, active, out);
    if (!ok) asker.RuntimeWarning("environment " + name, "environment \"" + name + "\": " + Why());
    return ok;
}

bool NamedTextures::MeasuredBrdf(sl::ShadingContext& asker, int count, const std::string& name,
                                 const float* wIn, const float* wOut, const uint8_t* active,
                                 float* out) {
    const int ncomps = asker.ColorComponents();
    std::fill_n(out, size_t(ncomps) * size_t(count), 0.0f);
    std::string error;
    const std::shared_ptr<const GrdFile> file = brdfs_.Get(Find(name), &error);
    if (!file) {
        asker.RuntimeError("brdf " + name, "brdf(\"" + name + "\"): " + error);
        return false;
    }
    const Brdf& brdf = file->Fastest();
    if (brdf.NumComponents() != 1 && brdf.NumComponents() != ncomps) {
        asker.RuntimeWarning("brdf components " + name,
                             "brdf(\"" + name + "\") has " + std::to_string(brdf.NumComponents()) +
                                 " colour components, the scene " + std::to_string(ncomps) +
                                 "; shading with their mean");
    }
    EvalPlanes(brdf, ncomps, count, wIn, wOut, active, out);
    return true;
}

}  // namespace gonio
