// OpenImageIO's TextureSystem behind gonio's TextureSystem: it does mipmapping, filtering and
// caching better than we would (make tiled mipmaps with `maketx`).
#include <Imath/ImathVec.h>
#include <OpenImageIO/texture.h>

#include <algorithm>

#include "imageio/oiio/oiio_parts.h"

namespace gonio {

namespace {

class OiioTextureSystem : public TextureSystem {
  public:
    OiioTextureSystem() : system_(OIIO::TextureSystem::create(/*shared=*/false)) {}
    ~OiioTextureSystem() override { OIIO::TextureSystem::destroy(system_); }

    bool Texture(const std::string& file, int firstChannel, int channels,
                 const TextureWrapModes& wrap, int n, const float* s, const float* t,
                 const float* dsdx, const float* dtdx, const float* dsdy, const float* dtdy,
                 const uint8_t* active, float* out) override;
    bool Environment(const std::string& file, int firstChannel, int channels, int n,
                     const float* directions, const uint8_t* active, float* out) override;
    bool Info(const std::string& file, const std::string& dataname, std::vector<float>* floats,
              std::string* text) override;
    std::string LastError() override { return system_->geterror(); }

  private:
    OIIO::TextureSystem* system_;
};

bool OiioTextureSystem::Info(const std::string& file, const std::string& dataname,
                             std::vector<float>* floats, std::string* text) {
    OIIO::TextureSystem* system = system_;
    // textureinfo() answers 0 for a missing file or fact; OpenImageIO's error would otherwise
    // linger and be reported later as if a lookup had failed.
    struct ClearError {
        OIIO::TextureSystem* system;
        ~ClearError() { system->geterror(); }
    } clearError{system};
    const OIIO::ustring name(file);
    if (dataname == "resolution" || dataname == "channels") {
        int values[2] = {0, 0};
        const bool resolution = dataname == "resolution";
        const OIIO::TypeDesc type = resolution ? OIIO::TypeDesc(OIIO::TypeDesc::INT, 2)
                                               : OIIO::TypeDesc(OIIO::TypeDesc::INT);
        if (!system->get_texture_info(name, 0, OIIO::ustring(dataname), type, values)) return false;
        floats->assign(values, values + (resolution ? 2 : 1));
        return true;
    }
    if (dataname == "type") {
        // OpenImageIO's "Plain Texture", "Shadow", "LatLong Environment", ... as maketx
        // records it; a plain image that can be read is a texture.
        OIIO::ustring format("Plain Texture");
        int exists = 0;
        if (!system->get_texture_info(name, 0, OIIO::ustring("exists"), OIIO::TypeInt, &exists) ||
            !exists)
            return false;
        system->get_texture_info(name, 0, OIIO::ustring("textureformat"), OIIO::TypeString,
                                 &format);
        const std::string f = format.string();
        *text = f.find("Shadow") != std::string::npos        ? "shadow"
                : f.find("Environment") != std::string::npos ? "environment"
                                                             : "texture";
        return true;
    }
    const char* matrix = dataname == "viewingmatrix"      ? "worldtocamera"
                         : dataname == "projectionmatrix" ? "worldtoscreen"
                                                          : nullptr;
    if (!matrix) return false;
    float values[16];
    if (!system->get_texture_info(name, 0, OIIO::ustring(matrix), OIIO::TypeMatrix, values))
        return false;
    floats->assign(values, values + 16);
    return true;
}

// Runs `lookup(handle, options, i, result)` for each active point and spreads its `channels`
// results component-major; texture and environment lookups differ only in that call.
template <class Lookup>
bool LookupEachPoint(OIIO::TextureSystem* system, const std::string& file, int firstChannel,
                     int channels, int n, const uint8_t* active, float* out, Lookup lookup) {
    std::fill(out, out + size_t(channels) * n, 0.f);
    OIIO::TextureOpt options;
    options.firstchannel = firstChannel;
    OIIO::TextureSystem::TextureHandle* handle = system->get_texture_handle(OIIO::ustring(file));
    if (!handle || !system->good(handle)) return false;
    std::vector<float> result(channels);
    bool ok = true;
    for (int i = 0; i < n; ++i) {
        if (active && !active[i]) continue;
        ok &= lookup(handle, options, i, result.data());
        for (int c = 0; c < channels; ++c) out[c * n + i] = result[c];
    }
    return ok;
}

OIIO::TextureOpt::Wrap OiioWrap(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Black:
            return OIIO::TextureOpt::WrapBlack;
        case TextureWrap::Clamp:
            return OIIO::TextureOpt::WrapClamp;
        case TextureWrap::Periodic:
            return OIIO::TextureOpt::WrapPeriodic;
        default:  // the file's "wrapmodes"
            return OIIO::TextureOpt::WrapDefault;
    }
}

bool OiioTextureSystem::Texture(const std::string& file, int firstChannel, int channels,
                                const TextureWrapModes& wrap, int n, const float* s, const float* t,
                                const float* dsdx, const float* dtdx, const float* dsdy,
                                const float* dtdy, const uint8_t* active, float* out) {
    OIIO::TextureSystem* system = system_;
    return LookupEachPoint(system, file, firstChannel, channels, n, active, out,
                           [&](OIIO::TextureSystem::TextureHandle* handle,
                               OIIO::TextureOpt& options, int i, float* result) {
                               options.swrap = OiioWrap(wrap.s);
                               options.twrap = OiioWrap(wrap.t);
                               const float ds = dsdx ? dsdx[i] : 0, dt = dtdx ? dtdx[i] : 0;
                               const float ds2 = dsdy ? dsdy[i] : 0, dt2 = dtdy ? dtdy[i] : 0;
                               return system->texture(handle, nullptr, options, s[i], t[i], ds, dt,
                                                      ds2, dt2, channels, result);
                           });
}

bool OiioTextureSystem::Environment(const std::string& file, int firstChannel, int channels, int n,
                                    const float* directions, const uint8_t* active, float* out) {
    OIIO::TextureSystem* system = system_;
    return LookupEachPoint(
        system, file, firstChannel, channels, n, active, out,
        [&](OIIO::TextureSystem::TextureHandle* handle, OIIO::TextureOpt& options, int i,
            float* result) {
            const Imath::V3f R(directions[i], directions[n + i], directions[2 * n + i]);
            const Imath::V3f zero(0, 0, 0);
            return system->environment(handle, nullptr, options, R, zero, zero, channels, result);
        });
}

}  // namespace

std::unique_ptr<TextureSystem> NewOiioTextureSystem() {
    return std::make_unique<OiioTextureSystem>();
}

}  // namespace gonio
