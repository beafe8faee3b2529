#pragma once
// The colour space of a spectral render (Option "spectral"): "sampled", n point samples of the
// spectrum, "bands", k averages over bands of those samples, or "svd", k coordinates per light
// in a basis of that light's one-bounce spectra; and the two matrices RISpec's ColorSamples asks
// for, so that the renderer carries the components through shading unchanged and turns them
// into RGB only for display.

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
    // k rows of n: the components of a spectrum sampled on `grid` (under "svd", of a reflectance).
    // Empty for "sampled" (the components are the samples).
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

// One light's part of an "svd" colour space: the light on the grid's samples, and n × k basis
// vectors whose span holds the spectra that light makes its surfaces reflect.
struct SvdBlock {
    Eigen::VectorXd light;
    Eigen::MatrixXd basis;
};

// Thesis §6.1.2's basis for one light l: the first k left singular vectors U_k of the matrix of
// one-bounce spectra l∘r_j of `surfaces` and of white (l itself among them), turned
// by a scaled rotation R (basis U_k R) so that white under l has every coordinate 1: then a
// shader's `color 1` is white there, as it is in "sampled". With k above the matrix's rank the
// further vectors complete U_k to an orthonormal set. 1 <= k <= n.
Eigen::MatrixXd LightSvdBasis(const Eigen::VectorXd& light,
                              const std::vector<Eigen::VectorXd>& surfaces, int k);

// Option "spectral" "basis" "svd", done exactly for direct light: one block of components per
// light spectrum, the per-light images of thesis §6.1.3 carried side by side and added at
// display. A reflectance r has, in block b, the coordinates of l_b∘r in that block's basis
// (fromSamples); a light of spectrum l_b is given the components 1 in its block and 0 elsewhere,
// so the component-wise product a shader computes, light times reflectance, is the projection of
// l_b∘r exactly; the block displays through its basis (toRgb). Light reflected a second time
// multiplies two such coordinates component by component, which is not the spectral product.
RenderColorSpace SvdColorSpace(const WavelengthGrid& grid, const std::vector<SvdBlock>& blocks);

}  // namespace gonio::spectral
