#pragma once
// The colour space of a spectral render (Option "spectral"): "sampled", n point samples of the
// spectrum, or "bands", k averages over bands of those samples; and the two matrices RISpec's
// ColorSamples asks for, so that the renderer carries the components through shading unchanged
// and turns them into RGB only for display.

#include <Eigen/Dense>
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
    // k rows of n: the components of a spectrum sampled on `grid`. Empty for "sampled" (the
    // components are the samples).
    std::vector<float> fromSamples;
};

// Throws SpectralError if the observer's tables do not cover `grid`.
RenderColorSpace SampledColorSpace(const WavelengthGrid& grid);

// k bands of `grid`'s samples, band b holding samples [edges[b], edges[b+1]) (k + 1 increasing
// sample indices from 0 to n), weighted by `light` (the scene's light on `grid`), as thesis
// §6.1.2's bands and spectral/representations.h's BandColours: component b of any spectrum s is
// its light-weighted mean over the band, Σ wᵢsᵢ / Σ wᵢ, and band b displays as
// (Σ wᵢ Tᵢ) Σ wᵢ / Σ wᵢ² (Tᵢ: toRgb of sample i), so the light itself, and the light reflected
// by any reflectance that is constant within each band, display exactly. Under a constant light
// a constant spectrum is grey, as in "sampled". A band the light leaves dark uses plain means.
// A spectrum's display RGB in the sampled colour space of the reference grid: what an RGB
// renderer is given for it, a light's colour and a reflectance alike.
Eigen::Vector3d DisplayRgb(const Spectrum& spectrum);

RenderColorSpace BandColorSpace(const WavelengthGrid& grid, const std::vector<int>& edges,
                                const Eigen::VectorXd& light);

}  // namespace gonio::spectral
