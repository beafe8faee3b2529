#pragma once
// Filtered texture and environment lookups for the shading language, through OpenImageIO's
// TextureSystem (mipmapped, cached; make tiled mipmaps with `maketx`) in the OpenImageIO
// plugin, loaded at the first lookup. Thread-safe.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/texture_wrap.h"

namespace gonio {

class TextureSystem;

class TextureLookup {
  public:
    TextureLookup();
    ~TextureLookup();

    // `channels` channels from `firstChannel` at (s, t) for each active point of n, filtered
    // over the footprint given by the derivatives (which may be null: a point lookup), s and t
    // outside [0, 1] wrapped as `wrap` says (Default: as the file records). Writes
    // channels × n floats, component-major. False if the file cannot be read (out is zeroed).
    bool Texture(const std::string& file, int firstChannel, int channels,
                 const TextureWrapModes& wrap, int n, const float* s, const float* t,
                 const float* dsdx, const float* dtdx, const float* dsdy, const float* dtdy,
                 const uint8_t* active, float* out);
    // A lat-long or cube environment map in direction D (3 × n, in the space the map was made
    // in: the shader transforms it there).
    bool Environment(const std::string& file, int firstChannel, int channels, int n,
                     const float* directions, const uint8_t* active, float* out);
    // textureinfo() (RISpec Table 15.3): "resolution" (2 floats), "channels" (1), "type"
    // ("texture", "shadow" or "environment"), "viewingmatrix" and "projectionmatrix" (16 floats,
    // row-major: world to the texture's camera and screen, where the file records them). False
    // if the file cannot be read or lacks the fact.
    bool Info(const std::string& file, const std::string& dataname, std::vector<float>* floats,
              std::string* text);
    // Why the last failed lookup failed (also when the plugin could not be loaded).
    std::string LastError() const;

  private:
    // The plugin's texture system, made at the first lookup; null if the plugin is missing.
    TextureSystem* System(const std::string& file);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace gonio
