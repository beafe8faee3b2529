#pragma once
// The spectral viewer's "Match RGB" (thesis §6.2.2): change a light's spectrum s as little as
// possible (in L2) so that it has a wanted RGB t and stays non-negative:
//
//   min ½ |s̄ − s|²  subject to  M s̄ = t,  s̄ ≥ 0          (M: 3 × n, spectrum to RGB)
//
// The thesis states it for Lawson & Hanson's LSEI with two sign slips: the unknown is Δs = s − s̄
// (not Δc), and s̄ = s − Δs ≥ 0 is −I Δs ≥ −s, i.e. G = −I, h = −s (not G = I, h = −c). The
// problem is strictly convex with 3 equality constraints, so its solution has the closed form
// s̄ = max(0, s + Mᵀλ) for the 3 multipliers λ, found by a semismooth Newton solve of
// F(λ) = M max(0, s + Mᵀλ) − t = 0 (the gradient of the dual), damped by a line search on the
// dual. A target outside the cone of colours non-negative spectra reach (cone_projection.h) is
// reported with a Farkas certificate instead of a wrong curve. See docs/spectral.md, "Match RGB".

#include <Eigen/Dense>
#include <string>

#include "spectral/spectrum.h"

namespace gonio::spectral {

struct LightMatch {
    bool reachable = false;    // false: no non-negative spectrum maps to the target
    Eigen::VectorXd spectrum;  // the matched light s̄ ≥ 0 (reachable), else the input light
    Eigen::Vector3d lambda;    // the multipliers: s̄ = max(0, s + Mᵀλ)
    int newtonSteps = 0;
    double rgbResidual = 0;  // |M s̄ − t| / |t| (|M s̄| when t = 0)
    double complementarity = 0;  // max_i |s̄_i μ_i| / (|s̄|∞ (|s|∞ + |Mᵀλ|∞)), μ = s̄ − s − Mᵀλ
    Eigen::Vector3d certificate;  // unreachable: y with Mᵀy ≥ 0 and yᵀt < 0 (Farkas), else 0
    std::string message;          // one line for a person
    double relativeChange = 0;    // |s̄ − s| / |s| (|s̄| for the all-zero light)
};

// The smallest L2 change of `light` (n samples) whose image under `toRgb` (3 × n) is `target`,
// staying non-negative (thesis §6.2.2, constraints corrected: s − Δs ≥ 0, G = −I, h = −s).
// Of the KKT conditions (s̄ ≥ 0, μ ≥ 0, s̄ − s − Mᵀλ = μ, s̄ᵢ μᵢ = 0, M s̄ = t) the form of s̄
// satisfies all but M s̄ = t by construction; `rgbResidual` and `complementarity` report the
// two that rounding can touch. Never NaN: t = 0 gives the black light (samples M does not see
// keep their value); on the very edge of the cone (a single wavelength's colour, say) Newton's
// multipliers diverge, and the match is then the cone projection's light, which has the RGB and
// is the closest when the edge holds one light only (`message` says so). Throws SpectralError if
// the sizes disagree or an input is not finite.
LightMatch MatchLightToRgb(const Eigen::VectorXd& light, const Eigen::Matrix3Xd& toRgb,
                           const Eigen::Vector3d& target);

// How NormalisedTarget measures brightness. The thesis's text (§6.2.2) uses the Euclidean norm
// of RGB; the viewer's colour patch, and the RGB values of the thesis's fig. 6.2, are scaled so
// the largest component is 1.
enum class Brightness { Euclidean, Largest };

// The thesis's brightness normalisation (§6.2.2): the match should follow the target's hue and
// saturation, not its brightness, which depends on the reflectance image. The thesis normalises
// the target to |c̄| = 1 and scales the light by "s' = ‖c'‖ s" (c' = M s); that factor is a slip
// (it gives |M s'| = |c'|², not 1): the intent is s / |M s|. Since the problem is homogeneous
// (k s, k t) → k s̄, we leave the light as drawn and scale the target instead: this returns
// t |M s| / |t|, the target's direction at the light's RGB brightness (with Largest, the largest
// components are made equal instead). A black target stays 0; a light without brightness (RGB 0,
// or no positive component) keeps the target as given.
Eigen::Vector3d NormalisedTarget(const Eigen::VectorXd& light, const Eigen::Matrix3Xd& toRgb,
                                 const Eigen::Vector3d& target,
                                 Brightness brightness = Brightness::Euclidean);

// M for the thesis's viewer (§6.2.4: M X, the CIE 1931 2° functions X on `grid` times the
// XYZ → RGB matrix; here IEC 61966-2-1's linear sRGB, without chromatic adaptation, so D65 is
// white).
Eigen::Matrix3Xd CieRgbMatrix(const WavelengthGrid& grid);
// M for a spectral render's colour space on `grid`: RenderColorSpace::toRgb (n rows of 3 floats)
// as a 3 × n matrix, so the matcher and the renderer agree on a light's RGB (the equal-energy
// light is white).
Eigen::Matrix3Xd RenderRgbMatrix(const WavelengthGrid& grid);

}  // namespace gonio::spectral
