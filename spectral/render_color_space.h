#pragma once
// The colour space of a spectral render (Option "spectral" "basis" "sampled"): n point samples
// of the spectrum, and the two matrices RISpec's ColorSamples asks for, so that the renderer
// carries n components through shading unchanged and turns them into RGB only for display.

#include <vector>

#include "spectral/spectrum.h"

namespace gonio::spectral {

struct RenderColorSpace {
    WavelengthGrid grid;
    // n rows of 3 (RISpec's nRGB): linear sRGB of one unit of sample i. XYZ = Σ cᵢ x̄ᵢ Δλ /
    // Σ ȳᵢ Δλ, so an equal-energy spectrum of value c has Y = c; Bradford-adapted from E's white
    // to D65 (the scene's white is the equal-energy one); then IEC 61966-2-1's matrix. A constant
    // spectrum c gives RGB (c, c, c) exactly (each channel scaled by at most 1e-4 for it: the
    // standard's matrix has four decimals).
    std::vector<float> toRgb;
    // 3 rows of n (RISpec's RGBn): the spectra R, G and B stand for. They are the smoothest three
    // (least squared second difference) that sum to 1 at every wavelength and whose RGB are the
    // unit primaries: RGB (c, c, c) becomes the constant spectrum c, and any RGB becomes a
    // spectrum of that same RGB. They are not bounded to [0, 1]: a saturated RGB reflectance
    // becomes a spectrum with small negative parts, as any linear uplift must.
    std::vector<float> fromRgb;
};

// Throws SpectralError if the observer's tables do not cover `grid`.
RenderColorSpace SampledColorSpace(const WavelengthGrid& grid);

}  // namespace gonio::spectral
