#pragma once
// The exact single-scattering BRDF of parallel cylinders with a Lambertian surface (Poulin &
// Fournier 1990, "A model for anisotropic reflection"), computed from the 2D profile alone and
// independently of the photon tracer: cylinders of radius r along y with axes in z = 0, one
// radius apart (50% overlap), so the visible profile is arcs of ±30° meeting in cusps.
//
// With a collimated beam of irradiance E⊥ from ω′, a profile element ds (per unit length of
// cylinder) with normal n receives E⊥ (n·ω′) ds and sends radiance (kd/π) E⊥ (n·ω′) towards ω;
// dividing the intensity of one period (width L = r) by L cos θ · E⊥ cos θ′ gives
//   f(ω′, ω) = kd / (π L cos θ′ cos θ) ∫ V(ψ) (n·ω′)(n·ω) r dψ,
// V = 1 where the point is both lit and seen. As the cylinders are infinite along y, a point is
// hidden from a direction exactly when the direction projected onto the xz plane is blocked.

#include <Imath/ImathVec.h>

#include <cmath>

namespace gonio::test {

// Whether the 2D ray from p (unit radius units, on circle 0) along d (x, z) meets another
// circle of the row (centres (k, 0), radius 1, k ≠ 0).
inline bool ProfileBlocked(double px, double pz, double dx, double dz) {
    const double len = std::hypot(dx, dz);
    if (len < 1e-12) return false;  // along the axes: nothing in the way
    dx /= len, dz /= len;
    if (dz <= 0) return true;
    // Past the tops of the circles (z = 1) nothing can block: check the circles below that.
    const double reach = (1 - pz) / dz * std::abs(dx) + 1;
    const int kMax = static_cast<int>(std::ceil(reach)) + 1;
    for (int k = -kMax; k <= kMax; ++k) {
        if (k == 0) continue;
        const double ox = px - k, oz = pz;
        const double b = ox * dx + oz * dz, c = ox * ox + oz * oz - 1;
        const double disc = b * b - c;
        if (disc <= 0) continue;
        // p lies outside circle k (on it at a cusp): blocked if the ray leaves it ahead of p.
        if (-b + std::sqrt(disc) > 1e-9) return true;
    }
    return false;
}

inline double CylinderRowBrdf(const Imath::V3d& wIn, const Imath::V3d& wOut, double kd,
                              int steps = 600) {
    const double arc = 3.14159265358979323846 / 6;  // ±30°
    double sum = 0;
    for (int i = 0; i < steps; ++i) {
        const double psi = -arc + (i + 0.5) * 2 * arc / steps;
        const double nx = std::sin(psi), nz = std::cos(psi);
        const double cosIn = nx * wIn.x + nz * wIn.z, cosOut = nx * wOut.x + nz * wOut.z;
        if (cosIn <= 0 || cosOut <= 0) continue;
        if (ProfileBlocked(nx, nz, wIn.x, wIn.z) || ProfileBlocked(nx, nz, wOut.x, wOut.z))
            continue;
        sum += cosIn * cosOut;
    }
    const double integral = sum * 2 * arc / steps;  // r dψ / L with L = r
    return kd / 3.14159265358979323846 * integral / (wIn.z * wOut.z);
}

}  // namespace gonio::test
