#include "spectral/render_color_space.h"

#include <Eigen/Dense>

#include "spectral/colorimetry.h"

namespace gonio::spectral {
namespace {

// Linear sRGB per unit of each sample: 3 × n.
Eigen::MatrixXd RgbOfSamples(const WavelengthGrid& grid) {
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), grid);
    const int n = grid.Count();
    const double yOfOne = observer.cmf.row(1).sum();
    const Xyz equalEnergyWhite = observer.cmf.rowwise().sum() / yOfOne;
    Eigen::MatrixXd rgb(3, n);
    for (int i = 0; i < n; ++i) {
        const Xyz xyz = observer.cmf.col(i) / yOfOne;
        rgb.col(i) = XyzToLinearSrgb(BradfordAdapt(xyz, equalEnergyWhite, SrgbWhite()));
    }
    // IEC 61966-2-1 gives its matrix to four decimals, so D65 comes out as RGB (1, 1, 1) only to
    // within 1e-4; each channel is scaled so that the scene's white is exactly grey.
    for (int c = 0; c < 3; ++c) rgb.row(c) /= rgb.row(c).sum();
    return rgb;
}

// The uplift: spectra s₀, s₁ and s₂ = 1 − s₀ − s₁ minimising Σₖ |D sₖ|² (D the second
// difference; D·1 = 0, so |D s₂|² = |D (s₀ + s₁)|²) subject to T sₖ = eₖ for k = 0, 1 (T s₂ = e₂
// follows from T·1 = (1, 1, 1)). Solved through its KKT system.
Eigen::MatrixXd UpliftSpectra(const Eigen::MatrixXd& toRgb) {
    const int n = int(toRgb.cols());
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(std::max(0, n - 2), n);
    for (int i = 0; i + 2 < n; ++i) d(i, i) = 1, d(i, i + 1) = -2, d(i, i + 2) = 1;
    const Eigen::MatrixXd q = d.transpose() * d;
    // Objective ½ xᵀ H x with x = (s₀, s₁): |D s₀|² + |D s₁|² + |D (s₀ + s₁)|².
    Eigen::MatrixXd h(2 * n, 2 * n);
    h << 4 * q, 2 * q, 2 * q, 4 * q;
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(2 * n + 6, 2 * n + 6);
    kkt.topLeftCorner(2 * n, 2 * n) = h;
    kkt.block(2 * n, 0, 3, n) = toRgb;
    kkt.block(2 * n + 3, n, 3, n) = toRgb;
    kkt.block(0, 2 * n, n, 3) = toRgb.transpose();
    kkt.block(n, 2 * n + 3, n, 3) = toRgb.transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n + 6);
    rhs(2 * n + 0) = 1;  // T s₀ = (1, 0, 0)
    rhs(2 * n + 4) = 1;  // T s₁ = (0, 1, 0)
    const Eigen::VectorXd x = kkt.fullPivLu().solve(rhs);
    Eigen::MatrixXd spectra(3, n);
    spectra.row(0) = x.head(n).transpose();
    spectra.row(1) = x.segment(n, n).transpose();
    spectra.row(2) = (Eigen::VectorXd::Ones(n) - x.head(n) - x.segment(n, n)).transpose();
    return spectra;
}

}  // namespace

RenderColorSpace SampledColorSpace(const WavelengthGrid& grid) {
    RenderColorSpace space;
    space.grid = grid;
    const Eigen::MatrixXd toRgb = RgbOfSamples(grid);
    const Eigen::MatrixXd uplift = UpliftSpectra(toRgb);
    const int n = grid.Count();
    space.toRgb.resize(3 * size_t(n));
    space.fromRgb.resize(3 * size_t(n));
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            space.toRgb[3 * size_t(i) + c] = float(toRgb(c, i));
            space.fromRgb[size_t(c) * n + i] = float(uplift(c, i));
        }
    return space;
}

}  // namespace gonio::spectral
