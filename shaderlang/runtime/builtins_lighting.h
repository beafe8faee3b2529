#pragma once
// The specular lobe shared by specular() and specularbrdf(), exposed so that a hand-written C++
// plastic (bench/) and the renderer's tests compute exactly what the shaders do.

#include <Imath/ImathVec.h>

namespace gonio::sl::builtins {

// specular() uses max(0, N·H)^(kSpecularExponentScale / roughness), as Aqsis 1.8 does.
constexpr float kSpecularExponentScale = 8.0f;

// max(0, N·H)^(8/roughness) with H = normalize(ln + view); ln must be normalised.
float SpecularBrdf(const Imath::V3f& ln, const Imath::V3f& normal, const Imath::V3f& view,
                   float roughness);

}  // namespace gonio::sl::builtins
