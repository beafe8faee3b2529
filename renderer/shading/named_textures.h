#pragma once
// The textures and measured BRDFs shaders ask for by name: each name is found on the texture
// search path once (Option "searchpath" "texture") and remembered, and a lookup that fails is
// reported through the shading context that asked, at its shader statement. Shared by the
// surface shading context and the imager's.

#include <string>
#include <unordered_map>
#include <vector>

#include "renderer/shading/shading_files.h"
#include "shaderlang/shading_context.h"

namespace gonio {

class NamedTextures {
  public:
    NamedTextures(ShadingFiles& files, std::vector<std::string> searchPath)
        : lookup_(files.textures), brdfs_(files.brdfs), searchPath_(std::move(searchPath)) {}

    // The file `name` stands for; the name itself when no folder of the path has it, so that
    // the reader's error names what was asked.
    const std::string& Find(const std::string& name) const;

    // TextureLookup's lookups for n points, by name; a failure warns through `asker`.
    bool Texture(sl::ShadingContext& asker, int n, const std::string& name, int firstChannel,
                 int channels, const TextureWrapModes& wrap, const float* s, const float* t,
                 const float* dsdx, const float* dtdx, const float* dsdy, const float* dtdy,
                 const uint8_t* active, float* out);
    bool Environment(sl::ShadingContext& asker, int n, const std::string& name, int firstChannel,
                     int channels, const float* directions, const uint8_t* active, float* out);
    // ShadingContext::MeasuredBrdf for `count` points; a failure warns through `asker`.
    bool MeasuredBrdf(sl::ShadingContext& asker, int count, const std::string& name,
                      const float* wIn, const float* wOut, const uint8_t* active, float* out);
    bool Info(const std::string& name, const std::string& dataname, std::vector<float>* floats,
              std::string* text) {
        return lookup_.Info(Find(name), dataname, floats, text);
    }

  private:
    std::string Why() const;

    TextureLookup& lookup_;
    GrdCache& brdfs_;
    std::vector<std::string> searchPath_;
    // Find's answers: looking a name up costs file-system calls, and texture() and brdf() ask
    // again for every batch.
    mutable std::unordered_map<std::string, std::string> found_;
};

}  // namespace gonio
