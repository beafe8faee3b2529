#pragma once
// The splat kernel of thesis eq. 4.4, the norms that combine the incoming and outgoing
// great-circle distances (thesis eqs. 3.4-3.6), and the kernel's mass measured exactly on the
// sphere (DESIGN.md "Splats"): the thesis's planar integrals (eqs. 4.6-4.8) overstate it for the
// radii used in practice.

#include <cmath>
#include <string>
#include <vector>

namespace gonio {

enum class Norm { kL1, kL2, kLinf };

// How a splat that reaches below the horizon keeps its energy inside the domain.
enum class Horizon {
    kReflect,      // mirror images across the horizon (and the pole for isotropic maps)
    kRenormalize,  // thesis eqs. 4.9-4.10: divide each cut splat by its in-domain mass
};

// Parses "l1", "l2", "linf"; throws std::invalid_argument otherwise.
Norm ParseNorm(const std::string& text);
const char* NormName(Norm norm);
Horizon ParseHorizon(const std::string& text);
const char* HorizonName(Horizon horizon);

// Thesis eq. 4.4 without its constant: 1 at x = 0, 0 with zero slope at |x| = 1.
inline double SplatKernel(double x) {
    if (x >= 1.0) return 0.0;
    const double x2 = x * x;
    return 1.0 + x2 * (-22.0 / 9.0 + x2 * (17.0 / 9.0 - x2 * (4.0 / 9.0)));
}

// Thesis eq. 4.4's polynomial in x², valid for x² < 1 only (it rises again past 1). Estrin's
// scheme, for a short chain of dependent operations in vectorised loops.
inline float SplatKernelPolynomial(float x2) {
    return (1.0f - (22.0f / 9.0f) * x2) + (x2 * x2) * (17.0f / 9.0f - (4.0f / 9.0f) * x2);
}

// Same kernel on the squared argument, so the L2 norm needs no square root.
inline float SplatKernelSquared(float x2) {
    if (x2 >= 1.0f) return 0.0f;
    return SplatKernelPolynomial(x2);
}

// Thesis eqs. 3.4-3.6: the distance in the product domain from the two partial distances.
inline double CombineDistances(Norm norm, double dIn, double dOut) {
    switch (norm) {
        case Norm::kL1:
            return dIn + dOut;
        case Norm::kL2:
            return std::sqrt(dIn * dIn + dOut * dOut);
        case Norm::kLinf:
            return dIn > dOut ? dIn : dOut;
    }
    return 0.0;
}

// Mass of k(norm(d1, d2) / R) over sphere x sphere (anisotropic, 4D; measure dω' dω) or over
// line x sphere (isotropic, 3D; measure dθ' dω), computed by quadrature on the sphere and cached
// per (R, norm). With horizon reflection this is exactly the mass each photon keeps in the domain.
double SphereKernelMass4D(double radius, Norm norm);
double SphereKernelMass3D(double radius, Norm norm);

// The same integrals with flat measures (2πr dr instead of 2π sin r dr): thesis eqs. 4.7-4.8, and
// 736π/2835 R³ for the 3D L2 case. For tests and for the estimator documentation.
double FlatKernelMass4D(double radius, Norm norm);
double FlatKernelMass3D(double radius, Norm norm);

// ∫ k(norm(dIn, b) / R) dω over the outgoing sphere (b = the outgoing distance): the splat's
// weight at incoming distance dIn once the outgoing direction is integrated out. Interpolated
// from a table cached per (R, norm).
double KernelOutMarginal(double radius, Norm norm, double dIn);

// The table behind KernelOutMarginal, fetched once (one lock) for callers that look it up many
// times, such as the splat sampler at every path vertex.
class KernelOutMarginalTable {
  public:
    KernelOutMarginalTable(double radius, Norm norm);
    double operator()(double dIn) const;

  private:
    static constexpr int kSteps = 512;
    const std::vector<double>* table_;
    double radius_;
};

// Largest outgoing distance b with norm(a, b) <= R: where the kernel's support ends once the
// incoming distance is a.
double KernelSupportLimit(Norm norm, double radius, double a);

// In-domain mass of a splat centred at colatitudes (cIn, cOut) for the thesis's renormalisation
// (eqs. 4.9-4.10, done on the sphere). For isotropic maps cIn is θ_in and the in-domain part of
// the θ_in axis is [0, π/2]. Interpolated from a table cached per (R, norm, isotropic).
double InDomainKernelMass(double radius, Norm norm, bool isotropic, double cIn, double cOut);

}  // namespace gonio
