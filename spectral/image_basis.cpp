#include "spectral/image_basis.h"

#include <algorithm>

#include "spectral/spectral_error.h"

namespace gonio::spectral {

namespace {

Eigen::MatrixXd GramMatrix(const float* spectra, size_t pixelCount, int n) {
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n, n);
    for (size_t p = 0; p < pixelCount; ++p) {
        const Eigen::VectorXd r =
            Eigen::Map<const Eigen::VectorXf>(spectra + p * size_t(n), n).cast<double>();
        gram.selfadjointView<Eigen::Lower>().rankUpdate(r);
    }
    return gram.selfadjointView<Eigen::Lower>();
}

}  // namespace

Eigen::MatrixXd ImageSpectraBasis::Basis(int k) const {
    if (k < 1 || k > SampleCount())
        throw SpectralError("a basis of " + std::to_string(k) + " vectors for spectra of " +
                            std::to_string(SampleCount()) + " samples");
    return directions.leftCols(k);
}

double ImageSpectraBasis::LostEnergyFraction(int k) const {
    const double total = energies.sum();
    if (!(total > 0)) return 0;
    return std::max(0.0, energies.tail(SampleCount() - k).sum() / total);
}

ImageSpectraBasis PrincipalSpectra(const float* spectra, size_t pixelCount, int n) {
    if (n < 1) throw SpectralError("spectra of no samples have no basis");
    // Eigen's solver returns increasing eigenvalues: reverse them, largest energy first.
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(GramMatrix(spectra, pixelCount, n));
    ImageSpectraBasis basis;
    basis.directions = eigen.eigenvectors().rowwise().reverse();
    basis.energies = eigen.eigenvalues().reverse().cwiseMax(0.0);
    for (int i = 0; i < n; ++i)
        if (basis.directions.col(i).sum() < 0) basis.directions.col(i) *= -1;
    return basis;
}

std::vector<float> ProjectSpectra(const float* spectra, size_t pixelCount,
                                  const Eigen::MatrixXd& basis) {
    const int n = int(basis.rows()), k = int(basis.cols());
    const Eigen::MatrixXd transposed = basis.transpose();
    std::vector<float> coefficients(pixelCount * size_t(k));
    for (size_t p = 0; p < pixelCount; ++p) {
        const Eigen::VectorXd r =
            Eigen::Map<const Eigen::VectorXf>(spectra + p * size_t(n), n).cast<double>();
        Eigen::Map<Eigen::VectorXf>(&coefficients[p * size_t(k)], k) =
            (transposed * r).cast<float>();
    }
    return coefficients;
}

}  // namespace gonio::spectral
