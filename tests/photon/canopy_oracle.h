#pragma once
// The once-scattered BRDF of a turbid-medium canopy over a black ground (issue 18 item 3): a
// plane-parallel layer of leaf area index L made of infinitely small, randomly placed
// bi-Lambertian leaves (reflectance ρ, transmittance τ) whose normals are uniform over the
// sphere (the spherical leaf-angle distribution, G = 1/2).
//
// Radiative transfer (Ross 1981, "The radiation regime and architecture of plant stands";
// Myneni, Ross & Asrar 1989, "A review on the theory of photon transport in leaf canopies",
// Agric. For. Meteorol. 45, 1-153): the direct beam
// at cumulative leaf area l below the top is F₀ e^{−G l/μ₀}; a unit leaf area scatters into Ω
// the intensity F₀ Γ(Ω′→Ω)/π, where Γ is the area scattering phase function; the light it sends
// out through the top is attenuated by e^{−G l/μ}. Integrating l over [0, L]:
//
//   f₁(ω₀, ω) = BRF₁/π,   BRF₁ = Γ(Ω′→Ω) (1 − e^{−G L (1/μ₀ + 1/μ)}) / (G (μ₀ + μ)),
//
// μ₀, μ the cosines of the light and view directions. For bi-Lambertian leaves with the
// spherical distribution Γ depends only on the phase angle β between the propagation
// directions Ω′ = −ω₀ and Ω = ω (Shultis & Myneni 1988, "Radiative transfer in vegetation
// canopies with anisotropic scattering", JQSRT 39, 115-129; canopy_test.cpp checks it against
// the integral over leaf normals it stands for):
//
//   Γ(β) = ω_L/(3π) (sin β − β cos β) + τ/3 cos β,   ω_L = ρ + τ,   cos β = −ω₀·ω,
//
// normalised so that ∫_{4π} Γ/π dΩ = ω_L G. The turbid medium has no hotspot: finite leaves
// make the paths in and out correlated near backscatter (β = π), which raises the real canopy
// there (Kuusk 1985); the oracle holds away from it.

#include <Imath/ImathVec.h>

#include <algorithm>
#include <cmath>

#include "base/math.h"

namespace gonio::test {

// Γ(β) of bi-Lambertian leaves with uniform spherical leaf angles.
inline double SphericalGamma(double cosBeta, double rho, double tau) {
    const double c = std::clamp(cosBeta, -1.0, 1.0);
    const double beta = std::acos(c);
    return (rho + tau) / (3 * kPi) * (std::sin(beta) - beta * c) + tau / 3 * c;
}

// f₁(ω₀ → ω) (1/sr) of the canopy of leaf area index `lai`; both directions above the ground.
inline double CanopySingleScatterBrdf(const Imath::V3d& toLight, const Imath::V3d& toViewer,
                                      double lai, double rho, double tau) {
    constexpr double kG = 0.5;  // the spherical distribution's projection of unit leaf area
    const double mu0 = toLight.z, mu = toViewer.z;
    if (mu0 <= 0 || mu <= 0) return 0;
    const double gamma = SphericalGamma(-toLight.dot(toViewer), rho, tau);
    const double brf = gamma * (1 - std::exp(-kG * lai * (1 / mu0 + 1 / mu))) / (kG * (mu0 + mu));
    return brf / kPi;
}

}  // namespace gonio::test
