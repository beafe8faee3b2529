#pragma once
// Limits every stage agrees on, so that what one writes the next can read.

namespace gonio {

// The most colour components a scene, photon map, .grd file or command takes (ColorSamples,
// Option "spectral"): room for 1 nm samples over 380-780 nm (401).
constexpr int kMaxColorComponents = 512;

}  // namespace gonio
