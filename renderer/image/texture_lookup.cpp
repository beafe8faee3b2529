// Texture reads go through OpenImageIO's TextureSystem, which does mipmapping, filtering and
// caching better than we would; it lives in the OpenImageIO plugin, opened at the first lookup
// so that renders without textures never load it.

#include "renderer/image/texture_lookup.h"

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include "imageio/oiio_plugin.h"

namespace gonio {

struct TextureLookup::Impl {
    std::once_flag once;
    std::unique_ptr<TextureSystem> system;
    std::string loadError;  // why the plugin could not be loaded
};

TextureLookup::TextureLookup() : impl_(std::make_unique<Impl>()) {}
TextureLookup::~TextureLookup() = default;

TextureSystem* TextureLookup::System(const std::string& file) {
    std::call_once(impl_->once, [&] {
        try {
            impl_->system = LoadOiioPlugin("the texture \"" + file + "\"").NewTextureSystem();
        } catch (const std::runtime_error& e) {
            impl_->loadError = e.what();
        }
    });
    return impl_->system.get();
}

std::string TextureLookup::LastError() const {
    return impl_->system ? impl_->system->LastError() : impl_->loadError;
}

bool TextureLookup::Info(const std::string& file, const std::string& dataname,
                         std::vector<float>* floats, std::string* text) {
    TextureSystem* system = System(file);
    return system && system->Info(file, dataname, floats, text);
}

bool TextureLookup::Texture(const std::string& file, int firstChannel, int channels,
                            const TextureWrapModes& wrap, int n, const float* s, const float* t,
                            const float* dsdx, const float* dtdx, const float* dsdy,
                            const float* dtdy, const uint8_t* active, float* out) {
    TextureSystem* system = System(file);
    if (!system) std::fill(out, out + size_t(channels) * n, 0.f);
    return system && system->Texture(file, firstChannel, channels, wrap, n, s, t, dsdx, dtdx, dsdy,
                                     dtdy, active, out);
}

bool TextureLookup::Environment(const std::string& file, int firstChannel, int channels, int n,
                                const float* directions, const uint8_t* active, float* out) {
    TextureSystem* system = System(file);
    if (!system) std::fill(out, out + size_t(channels) * n, 0.f);
    return system && system->Environment(file, firstChannel, channels, n, directions, active, out);
}

}  // namespace gonio
