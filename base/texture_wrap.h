#pragma once
// Texture wrap modes (RISpec §7.1 MakeTexture's swrap and twrap; the "swrap", "twrap" and
// "wrap" parameters of texture() as PRMan spells them): what a lookup at s or t outside [0, 1]
// reads. Shared by the RIB requests that make textures, the shading language's lookups and the
// OpenImageIO plugin that does both; header only, so that the plugin links nothing of gonio's.

#include <optional>
#include <string_view>

namespace gonio {

enum class TextureWrap {
    Default,   // a lookup: the mode the texture file records (OpenImageIO's "wrapmodes")
    Black,     // zero outside [0, 1]
    Clamp,     // the edge texel extended
    Periodic,  // the texture repeated: s and s + 1 read the same texel
};

struct TextureWrapModes {
    TextureWrap s = TextureWrap::Default;
    TextureWrap t = TextureWrap::Default;
};

// The mode RISpec names "black", "clamp" or "periodic" (and "default"); none for another name.
inline std::optional<TextureWrap> TextureWrapFromName(std::string_view name) {
    if (name == "black") return TextureWrap::Black;
    if (name == "clamp") return TextureWrap::Clamp;
    if (name == "periodic") return TextureWrap::Periodic;
    if (name == "default") return TextureWrap::Default;
    return std::nullopt;
}

// RISpec's (and OpenImageIO's) name of a mode.
inline const char* TextureWrapName(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Black:
            return "black";
        case TextureWrap::Clamp:
            return "clamp";
        case TextureWrap::Periodic:
            return "periodic";
        default:
            return "default";
    }
}

}  // namespace gonio
