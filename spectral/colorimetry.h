#pragma once
// CIE colorimetry of sampled spectra: tristimulus values, chromaticity, CIELAB, CIEDE2000, and
// linear sRGB (with Bradford adaptation of the scene white to sRGB's D65).
//
// Sums, not integrals: X = Σ S(λ) x̄(λ) Δλ over the working grid (CIE 15:2004 §7.1 recommends
// summation at 5 nm or finer over 380-780 nm).

#include <Eigen/Dense>

#include "spectral/named_spectra.h"
#include "spectral/spectrum.h"

namespace gonio::spectral {

using Xyz = Eigen::Vector3d;
using Lab = Eigen::Vector3d;
using Rgb = Eigen::Vector3d;

// An observer on a working grid: row 0 x̄, row 1 ȳ, row 2 z̄, times Δλ (so XYZ = cmf · S).
struct SampledObserver {
    WavelengthGrid grid;
    Eigen::Matrix<double, 3, Eigen::Dynamic> cmf;
};
// Piecewise-linear resampling of the tables (throws SpectralError if they do not cover `grid`).
SampledObserver SampleObserver(const Observer& observer, const WavelengthGrid& grid);
Eigen::VectorXd SampleSpectrum(const Spectrum& spectrum, const WavelengthGrid& grid);

// Σ S x̄ Δλ etc., unnormalised.
Xyz Tristimulus(const Eigen::VectorXd& spd, const SampledObserver& observer);
// The colour of a light, scaled so Y = 100.
Xyz EmissiveXyz(const Spectrum& light, const SampledObserver& observer);
// The colour of a reflectance under an illuminant, the perfect white having Y = 100
// (CIE 15:2004 eq. 7.1-7.3: k = 100 / Σ S ȳ Δλ).
Xyz ReflectanceXyz(const Spectrum& reflectance, const Spectrum& illuminant,
                   const SampledObserver& observer);

// CIE 15:2004 eq. 7.4: x = X / (X + Y + Z), y = Y / (X + Y + Z).
Eigen::Vector2d Chromaticity(const Xyz& xyz);

// IEC 61966-2-1: sRGB's D65 white (x 0.3127, y 0.3290) with Y = 1, and its XYZ→linear RGB
// matrix; RgbToXyz is that matrix's exact inverse so a round trip is the identity.
Xyz SrgbWhite();
Rgb XyzToLinearSrgb(const Xyz& xyz);
Xyz LinearSrgbToXyz(const Rgb& rgb);
// Bradford chromatic adaptation (Lam 1985; Süsstrunk et al. 2000): M⁻¹ diag(ρ_d / ρ_s) M.
Xyz BradfordAdapt(const Xyz& xyz, const Xyz& sourceWhite, const Xyz& destinationWhite);
// For display: adapts `xyz` from `sceneWhite` to D65 (Bradford), then the sRGB matrix. The
// scene white maps to RGB (1, 1, 1) times its Y relative to `sceneWhite`'s Y.
Rgb XyzToDisplaySrgb(const Xyz& xyz, const Xyz& sceneWhite);

// CIE 15:2004 eq. 8.1-8.3 (CIELAB relative to the white `white`).
Lab XyzToLab(const Xyz& xyz, const Xyz& white);
// CIEDE2000 (Sharma, Wu, Dalal 2005, eq. 1-22), parametric factors kL = kC = kH = 1 default.
double Ciede2000(const Lab& lab1, const Lab& lab2, double kL = 1, double kC = 1, double kH = 1);

}  // namespace gonio::spectral
