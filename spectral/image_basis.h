#pragma once
// A basis computed from an image's own pixel spectra, so that a reflectance image can be stored
// as k coefficients per pixel instead of n samples (thesis §6.2.4: pixel = M X diag(l) Bᵀ r, one
// 3×k matrix per light). The basis is the first k principal directions of the pixel spectra:
// the left singular vectors of the n × P matrix R = [r_1 … r_P] of all pixels, uncentred (black
// stays 0, and a pixel's coefficients scale with its spectrum) and unweighted. Unweighted because
// the light applied later is not known when the image is written and may put its energy anywhere
// (a lamp peaking at 700 nm makes the long-wave tail matter), and because an eye-weighted basis
// (the singular vectors U of W R, B = W⁻¹U) is not orthonormal and grows without bound where the
// weight vanishes. The error measure is the fraction of the pixels' energy Σ‖r‖² the first k
// directions miss, so a caller can pick the smallest k that meets its own (ΔE) target.

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace gonio::spectral {

struct ImageSpectraBasis {
    // n × n, orthonormal columns by decreasing energy, each signed so its samples sum to ≥ 0
    // (singular vectors have arbitrary signs; this makes the basis a function of the image).
    Eigen::MatrixXd directions;
    // Σ_p (d_iᵀ r_p)² for each direction d_i (the squared singular values), decreasing, ≥ 0;
    // they sum to Σ_p ‖r_p‖².
    Eigen::VectorXd energies;

    int SampleCount() const { return int(directions.rows()); }
    // The first k directions, n × k. 1 ≤ k ≤ n.
    Eigen::MatrixXd Basis(int k) const;
    // Σ_p ‖r_p − B Bᵀ r_p‖² / Σ_p ‖r_p‖² for B = Basis(k), 0 ≤ k ≤ n; 0 for a black image.
    double LostEnergyFraction(int k) const;
};

// The principal directions of `pixelCount` spectra of n samples each, pixel-major (sample i of
// pixel p at p·n + i). Through the n × n matrix R Rᵀ accumulated in double: its eigenvectors are
// R's left singular vectors, at a cost of P n² instead of an SVD of the n × P matrix.
ImageSpectraBasis PrincipalSpectra(const float* spectra, size_t pixelCount, int n);

// Each pixel's k coefficients Bᵀ r (B orthonormal: the closest point of its span), pixel-major.
std::vector<float> ProjectSpectra(const float* spectra, size_t pixelCount,
                                  const Eigen::MatrixXd& basis);

}  // namespace gonio::spectral
