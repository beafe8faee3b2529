// The second OpenImageIO user beside image_writer.cpp: texture reads go through its
// TextureSystem, which does mipmapping, filtering and caching better than we would.

#include "image/texture_lookup.h"

#include <Imath/ImathVec.h>
#include <OpenImageIO/texture.h>

#include <algorithm>

namespace gonio {

struct TextureLookup::Impl {
    OIIO::TextureSystem* system = OIIO::TextureSystem::create(/*shared=*/false);
    ~Impl() { OIIO::TextureSystem::destroy(system); }
};

TextureLookup::TextureLookup() : impl_(std::make_unique<Impl>()) {}
TextureLookup::~TextureLookup() = default;

std::string TextureLookup::LastError() const { return impl_->system->geterror(); }

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

bool TextureLookup::Texture(const std::string& file, int firstChannel, int channels, int n,
                            const float* s, const float* t, const float* dsdx, const float* dtdx,
                            const float* dsdy, const float* dtdy, const uint8_t* active,
                            float* out) {
    OIIO::TextureSystem* system = impl_->system;
    return LookupEachPoint(system, file, firstChannel, channels, n, active, out,
                           [&](OIIO::TextureSystem::TextureHandle* handle,
                               OIIO::TextureOpt& options, int i, float* result) {
                               const float ds = dsdx ? dsdx[i] : 0, dt = dtdx ? dtdx[i] : 0;
                               const float ds2 = dsdy ? dsdy[i] : 0, dt2 = dtdy ? dtdy[i] : 0;
                               return system->texture(handle, nullptr, options, s[i], t[i], ds, dt,
                                                      ds2, dt2, channels, result);
                           });
}

bool TextureLookup::Environment(const std::string& file, int firstChannel, int channels, int n,
                                const float* directions, const uint8_t* active, float* out) {
    OIIO::TextureSystem* system = impl_->system;
    return LookupEachPoint(
        system, file, firstChannel, channels, n, active, out,
        [&](OIIO::TextureSystem::TextureHandle* handle, OIIO::TextureOpt& options, int i,
            float* result) {
            const Imath::V3f R(directions[i], directions[n + i], directions[2 * n + i]);
            const Imath::V3f zero(0, 0, 0);
            return system->environment(handle, nullptr, options, R, zero, zero, channels, result);
        });
}

}  // namespace gonio
