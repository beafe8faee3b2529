#pragma once
// Limits every stage agrees on, so that what one writes the next can read.

namespace gonio {

// The most colour components a scene, photon map, .grd file or command takes (ColorSamples,
// Option "spectral"): room for 1 nm samples over 380-780 nm (401).
constexpr int kMaxColorComponents = 512;

// PixelSamples in each direction (1,048,576 samples a pixel, far past any use: a larger request
// is a typing mistake that would run for days).
constexpr float kMaxPixelSamples = 1024;
// Format resolution in each direction. Pixel coordinates, the filter's margin and the crop window
// are ints: past 2^24 they would overflow (2147483647 became a 1x1 image). 16,777,216 pixels is
// far beyond any image an 8-bit-per-channel format or this machine's memory can hold.
constexpr int kMaxResolution = 1 << 24;
// PixelFilter widths, in pixels: the film renders a margin of half the width around the image.
constexpr float kMaxFilterWidth = 256;  // and MakeTexture's, in pixels of each MIP level

}  // namespace gonio
