#pragma once
// Message passing for ShadingContext implementations (RISpec §15.8): which shaders of a batch
// surface(), displacement() and atmosphere() read, and the copies of light parameters that
// lightsource() reads after the light executor has moved on to the next light.

#include <string>

#include "shaderlang/shading_context.h"
#include "shaderlang/shading_system.h"

namespace gonio::sl {

// The displacement, surface and atmosphere shaders of one batch, each readable from the moment
// it starts to run (a shader reads itself and those that ran before it at the same points).
class MessageShaders {
  public:
    void Clear() { *this = MessageShaders(); }
    // `executor` runs `instance` over the batch now (or has run it).
    void Set(MessageSource source, const ShaderInstance* instance, const ShaderExecutor* executor);
    bool Find(MessageSource source, const std::string& name, MessageValue* value) const;

  private:
    struct Entry {
        const ShaderInstance* instance = nullptr;
        const ShaderExecutor* executor = nullptr;
    };
    Entry entries_[3];  // Surface, Displacement, Atmosphere
};

// Copies the parameters of the light `instance`, as `executor` left them over n points, into
// result->parameters.
void CaptureLightParameters(const ShaderInstance& instance, const ShaderExecutor& executor, int n,
                            LightResult* result);

// Whether the (specialised) code of `instance` calls the built-in `name`.
bool CallsBuiltin(const ShaderInstance& instance, const std::string& name);

}  // namespace gonio::sl
