#include "spectral/render_color_space.h"

#include <cmath>
#include <string>

#include "spectral/colorimetry.h"
#include "spectral/spectral_error.h"

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

// The space's matrices in ColorSamples' float layouts: toRgb 3 × k as k rows of 3, fromRgb as
// 3 rows of k, fromSamples (when given) as k rows of n.
RenderColorSpace MakeSpace(const WavelengthGrid& grid, const Eigen::MatrixXd& toRgb,
                           const Eigen::MatrixXd& fromRgb, const Eigen::MatrixXd& fromSamples) {
    RenderColorSpace space;
    space.grid = grid;
    const Eigen::Index k = toRgb.cols();
    for (Eigen::Index i = 0; i < k; ++i)
        for (int c = 0; c < 3; ++c) space.toRgb.push_back(float(toRgb(c, i)));
    for (int c = 0; c < 3; ++c)
        for (Eigen::Index i = 0; i < k; ++i) space.fromRgb.push_back(float(fromRgb(c, i)));
    for (Eigen::Index b = 0; b < fromSamples.rows(); ++b)
        for (Eigen::Index i = 0; i < fromSamples.cols(); ++i)
            space.fromSamples.push_back(float(fromSamples(b, i)));
    return space;
}

void CheckBandEdges(const std::vector<int>& edges, int n) {
    bool valid = edges.size() >= 2 && edges.front() == 0 && edges.back() == n;
    for (size_t b = 1; valid && b < edges.size(); ++b) valid = edges[b] > edges[b - 1];
    if (!valid)
        throw SpectralError("band edges must rise from sample 0 to sample " + std::to_string(n));
}

}  // namespace

RenderColorSpace SampledColorSpace(const WavelengthGrid& grid) {
    const Eigen::MatrixXd toRgb = RgbOfSamples(grid);
    return MakeSpace(grid, toRgb, UpliftSpectra(toRgb), Eigen::MatrixXd());
}

Eigen::Vector3d DisplayRgb(const Spectrum& spectrum) {
    static const RenderColorSpace space = SampledColorSpace(ReferenceGrid());
    const std::vector<double> samples = spectrum.Sample(space.grid);
    Eigen::Vector3d rgb = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < samples.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[c] += samples[i] * space.toRgb[3 * i + c];
    return rgb;
}

RenderColorSpace BandColorSpace(const WavelengthGrid& grid, const std::vector<int>& edges,
                                const Eigen::VectorXd& light) {
    const int n = grid.Count(), k = int(edges.size()) - 1;
    CheckBandEdges(edges, n);
    if (light.size() != n) throw SpectralError("the band weights must have one value per sample");
    const Eigen::MatrixXd samplesToRgb = RgbOfSamples(grid);
    Eigen::MatrixXd fromSamples = Eigen::MatrixXd::Zero(k, n);
    Eigen::MatrixXd toRgb(3, k);
    for (int b = 0; b < k; ++b) {
        const int first = edges[b], count = edges[b + 1] - edges[b];
        Eigen::VectorXd w = light.segment(first, count).cwiseMax(0.0);
        if (!(w.sum() > 0)) w.setOnes();
        fromSamples.block(b, first, 1, count) = w.transpose() / w.sum();
        toRgb.col(b) = samplesToRgb.middleCols(first, count) * w * (w.sum() / w.squaredNorm());
    }
    const Eigen::MatrixXd fromRgb = UpliftSpectra(samplesToRgb) * fromSamples.transpose();
    return MakeSpace(grid, toRgb, fromRgb, fromSamples);
}

namespace {

// A rotation taking the unit vector `from` to the unit vector `to`: the Householder reflection
// across their bisector, or I when they coincide.
Eigen::MatrixXd Reflection(const Eigen::VectorXd& from, const Eigen::VectorXd& to) {
    const Eigen::VectorXd v = from - to;
    Eigen::MatrixXd h = Eigen::MatrixXd::Identity(from.size(), from.size());
    if (v.squaredNorm() > 1e-24) h -= 2 * v * v.transpose() / v.squaredNorm();
    return h;
}

}  // namespace

Eigen::MatrixXd LightSvdBasis(const Eigen::VectorXd& light,
                              const std::vector<Eigen::VectorXd>& surfaces, int k) {
    const Eigen::Index n = light.size();
    if (k < 1 || k > n)
        throw SpectralError("svd: " + std::to_string(k) + " vectors, expected 1 to the " +
                            std::to_string(n) + " samples");
    Eigen::MatrixXd once(n, Eigen::Index(surfaces.size()) + 1);
    once.col(0) = light;
    for (size_t j = 0; j < surfaces.size(); ++j) {
        if (surfaces[j].size() != n)
            throw SpectralError("svd: a surface must have one value per sample");
        once.col(Eigen::Index(j) + 1) = light.cwiseProduct(surfaces[j]);
    }
    // Thesis §6.1.2: [U, S, V] = svd(O); the first k columns of U are the optimal basis.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(once, Eigen::ComputeFullU);
    const Eigen::MatrixXd u = svd.matrixU().leftCols(k);
    // R = (|a| / √k) H with H a rotation taking 1/√k to a/|a|, a = U_kᵀ l: then white's
    // coordinates R⁻¹ U_kᵀ l are all 1 (U_k R 1 = U_k a, the light's projection), and R is a
    // rotation times a scale, as well conditioned as U_k.
    const Eigen::VectorXd a = u.transpose() * light;
    if (!(a.norm() > 0)) return u;
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(k) / std::sqrt(double(k));
    return u * (a.norm() / std::sqrt(double(k))) * Reflection(ones, a.normalized());
}

RenderColorSpace SvdColorSpace(const WavelengthGrid& grid, const std::vector<SvdBlock>& blocks) {
    const int n = grid.Count();
    Eigen::Index components = 0;
    for (const SvdBlock& block : blocks) {
        if (block.light.size() != n || block.basis.rows() != n)
            throw SpectralError("svd: a light and its basis must have one value per sample");
        components += block.basis.cols();
    }
    const Eigen::MatrixXd samplesToRgb = RgbOfSamples(grid);
    Eigen::MatrixXd fromSamples(components, n), toRgb(3, components);
    Eigen::Index first = 0;
    for (const SvdBlock& block : blocks) {
        const Eigen::Index k = block.basis.cols();
        // The coordinates of l_b∘r: the basis's pseudo-inverse after the light.
        fromSamples.middleRows(first, k) =
            block.basis.completeOrthogonalDecomposition().pseudoInverse() *
            block.light.asDiagonal();
        toRgb.middleCols(first, k) = samplesToRgb * block.basis;
        first += k;
    }
    const Eigen::MatrixXd fromRgb = UpliftSpectra(samplesToRgb) * fromSamples.transpose();
    return MakeSpace(grid, toRgb, fromRgb, fromSamples);
}

}  // namespace gonio::spectral
