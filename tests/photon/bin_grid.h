#pragma once
// A grid of outgoing-direction bins (θ bands × φ sectors) and the χ² comparison of a tracer's
// binned energies with the expectation of an analytic BRDF, ∫ p(θ′) ∫_bin f cos θ dω dθ′, for
// isotropic runs (φ′ = 0, θ′ uniform on a band).

#include <tbb/parallel_for.h>

#include <functional>
#include <numeric>

#include "photon_test_util.h"

namespace gonio::test {

struct BinGrid {
    int thetaBands = 9, phiSectors = 12;
    double thetaMax = kPi / 2;

    int Size() const { return thetaBands * phiSectors; }
    // Sectors are centred on φ = 0 (backwards, towards the light of an isotropic run).
    int BinOf(double theta, double phi) const {
        const int t = std::min(thetaBands - 1, static_cast<int>(theta / thetaMax * thetaBands));
        double shifted = phi / (2 * kPi) * phiSectors + 0.5;
        shifted -= phiSectors * std::floor(shifted / phiSectors);
        return t * phiSectors + std::min(phiSectors - 1, static_cast<int>(shifted));
    }
    // Midpoint quadrature of g(ω) dω over bin b with m × m points.
    double Integrate(int b, const std::function<double(const Imath::V3d&)>& g, int m) const {
        const int t = b / phiSectors, p = b % phiSectors;
        const double dTheta = thetaMax / thetaBands, dPhi = 2 * kPi / phiSectors;
        const double theta0 = t * dTheta, phi0 = (p - 0.5) * dPhi;
        double sum = 0;
        for (int i = 0; i < m; ++i) {
            const double theta = theta0 + (i + 0.5) * dTheta / m;
            for (int j = 0; j < m; ++j) {
                const double phi = phi0 + (j + 0.5) * dPhi / m;
                sum += g(Direction(theta, phi)) * std::sin(theta);
            }
        }
        return sum * dTheta * dPhi / (m * m);
    }
};

// Gauss-Legendre nodes on [-1, 1] (8 points).
constexpr double kGaussX[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                               -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                               0.7966664774136267,  0.9602898564975363};
constexpr double kGaussW[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                               0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                               0.2223810344533745, 0.1012285362903763};

// E[β 1_bin] per path for f(ω′, ω) with φ′ = 0 and θ′ uniform on [θmin, θmax] (isotropic runs).
inline std::vector<double> ExpectedBinEnergy(
    const BinGrid& grid, double thetaMin, double thetaMax,
    const std::function<double(const Imath::V3d&, const Imath::V3d&)>& f, int m) {
    std::vector<double> expected(grid.Size(), 0.0);
    for (int g = 0; g < 8; ++g) {
        const double thetaIn =
            0.5 * (thetaMin + thetaMax) + 0.5 * (thetaMax - thetaMin) * kGaussX[g];
        const Imath::V3d wIn = Direction(thetaIn, 0);
        tbb::parallel_for(0, grid.Size(), [&](int b) {
            expected[b] += 0.5 * kGaussW[g] *
                           grid.Integrate(
                               b, [&](const Imath::V3d& w) { return f(wIn, w) * w.z; }, m);
        });
    }
    return expected;
}

struct ChiSquare {
    double value = 0;
    int dof = 0;
    double worstZ = 0;  // the largest |z| of a bin
};

// Σ (x̄_b − E_b)² / σ_b² over the bins that hold at least `minPhotons` photons' worth of energy.
inline ChiSquare Compare(const BinnedEstimate& measured, const std::vector<double>& expected,
                         double minMean) {
    ChiSquare c;
    for (size_t b = 0; b < expected.size(); ++b) {
        if (expected[b] < minMean || measured.sigma[b] <= 0) continue;
        const double z = (measured.mean[b] - expected[b]) / measured.sigma[b];
        c.value += z * z;
        c.worstZ = std::max(c.worstZ, std::abs(z));
        ++c.dof;
    }
    return c;
}

}  // namespace gonio::test
