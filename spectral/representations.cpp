#include "spectral/representations.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "spectral/render_color_space.h"
#include "spectral/spectral_error.h"

namespace gonio::spectral {

namespace {

int SurfaceCount(const PatchScene& scene) { return int(scene.reflectances.cols()); }

// Fills the two-bounce columns from a per-surface "reflect this" operation.
template <typename Reflect>
Eigen::Matrix3Xd TwoBounce(int m, const Reflect& reflect) {
    Eigen::Matrix3Xd result(3, m * m);
    for (int j1 = 0; j1 < m; ++j1)
        for (int j2 = 0; j2 < m; ++j2) result.col(j1 * m + j2) = reflect(j1, j2);
    return result;
}

void CheckK(int k, int most, const char* what) {
    if (k < 1 || k > most)
        throw SpectralError(std::string(what) + " needs 1 ≤ k ≤ " + std::to_string(most) +
                            ", got " + std::to_string(k));
}

}  // namespace

BounceColours ReferenceColours(const PatchScene& scene) {
    const int m = SurfaceCount(scene);
    const auto& cmf = scene.observer.cmf;
    const Eigen::MatrixXd once = scene.reflectances.array().colwise() * scene.light.array();
    BounceColours colours{cmf * once, {}};
    colours.twoBounce = TwoBounce(m, [&](int j1, int j2) -> Eigen::Vector3d {
        return cmf * once.col(j1).cwiseProduct(scene.reflectances.col(j2));
    });
    return colours;
}

BounceColours RgbColours(const PatchScene& scene) {
    const int m = SurfaceCount(scene);
    const auto& cmf = scene.observer.cmf;
    // The light's RGB is its colour; a reflectance's is its colour under D65, sRGB's white,
    // scaled per channel so the perfect reflector is exactly (1, 1, 1), as an RGB renderer's
    // white surface is.
    const Rgb light = XyzToLinearSrgb(cmf * scene.light);
    const Rgb white = XyzToLinearSrgb(cmf * scene.rgbIlluminant);
    Eigen::Matrix3Xd surfaces(3, m);
    for (int j = 0; j < m; ++j)
        surfaces.col(j) =
            XyzToLinearSrgb(cmf * scene.rgbIlluminant.cwiseProduct(scene.reflectances.col(j)))
                .cwiseQuotient(white);
    BounceColours colours;
    colours.oneBounce.resize(3, m);
    for (int j = 0; j < m; ++j)
        colours.oneBounce.col(j) = LinearSrgbToXyz(light.cwiseProduct(surfaces.col(j)));
    colours.twoBounce = TwoBounce(m, [&](int j1, int j2) -> Eigen::Vector3d {
        return LinearSrgbToXyz(light.cwiseProduct(surfaces.col(j1)).cwiseProduct(surfaces.col(j2)));
    });
    return colours;
}

namespace {

// The Jacobian of CIELAB (CIE 15:2004 eq. 8.1-8.3) at `xyz` relative to `white`: how an error
// in XYZ shows in L*a*b* near this colour.
Eigen::Matrix3d LabJacobian(const Xyz& xyz, const Xyz& white) {
    auto slope = [](double t) {  // f'(t)
        constexpr double delta = 6.0 / 29.0;
        return t > delta * delta * delta ? 1 / (3 * std::cbrt(t * t)) : 1 / (3 * delta * delta);
    };
    const double fx = slope(xyz.x() / white.x()) / white.x();
    const double fy = slope(xyz.y() / white.y()) / white.y();
    const double fz = slope(xyz.z() / white.z()) / white.z();
    Eigen::Matrix3d j;
    j << 0, 116 * fy, 0, 500 * fx, -500 * fy, 0, 0, 200 * fy, -200 * fz;
    return j;
}

}  // namespace

std::vector<int> BandEdges(const PatchScene& scene, int k) {
    const int n = int(scene.light.size());
    CheckK(k, n, "bands-k");
    const int m = SurfaceCount(scene);
    const auto& cmf = scene.observer.cmf;
    const Eigen::VectorXd& l = scene.light;
    const Eigen::MatrixXd& r = scene.reflectances;
    // The paths whose colours the bands must keep: each surface once, each unordered pair.
    std::vector<std::pair<int, int>> pairs;
    for (int j1 = 0; j1 < m; ++j1)
        for (int j2 = j1; j2 < m; ++j2) pairs.emplace_back(j1, j2);
    const int paths = m + int(pairs.size());
    Eigen::MatrixXd rho(n, paths);  // the reflectance product of each path
    rho.leftCols(m) = r;
    for (size_t p = 0; p < pairs.size(); ++p)
        rho.col(m + Eigen::Index(p)) = r.col(pairs[p].first).cwiseProduct(r.col(pairs[p].second));
    // Each path's error is weighed as CIELAB sees it near its true colour.
    const Xyz lightXyz = cmf * l;
    const double scale = 100 / lightXyz.y();
    std::vector<Eigen::Matrix3d> jacobian(paths);
    for (int p = 0; p < paths; ++p)
        jacobian[p] =
            LabJacobian(scale * cmf * l.cwiseProduct(rho.col(p)), scale * lightXyz) * scale;
    // Prefix sums over samples: Σ l, Σ l·r_j, Σ l·cmf, Σ l·cmf·ρ_p.
    Eigen::VectorXd sumL = Eigen::VectorXd::Zero(n + 1);
    Eigen::MatrixXd sumLr = Eigen::MatrixXd::Zero(n + 1, m);
    Eigen::MatrixXd sumLcmf = Eigen::MatrixXd::Zero(n + 1, 3);
    Eigen::MatrixXd sumExact = Eigen::MatrixXd::Zero(n + 1, 3 * paths);
    for (int i = 0; i < n; ++i) {
        sumL[i + 1] = sumL[i] + l[i];
        sumLr.row(i + 1) = sumLr.row(i) + l[i] * r.row(i);
        sumLcmf.row(i + 1) = sumLcmf.row(i) + l[i] * cmf.col(i).transpose();
        for (int p = 0; p < paths; ++p)
            sumExact.block(i + 1, 3 * p, 1, 3) =
                sumExact.block(i, 3 * p, 1, 3) + l[i] * rho(i, p) * cmf.col(i).transpose();
    }
    // cost(s, e): the squared, linearised CIELAB error that band [s, e) alone adds to every path,
    // the band computing L_b · W_b · Π r̄_j as BandColours does.
    Eigen::MatrixXd cost = Eigen::MatrixXd::Zero(n + 1, n + 1);
    for (int s = 0; s < n; ++s)
        for (int e = s + 1; e <= n; ++e) {
            const double energy = sumL[e] - sumL[s];
            if (!(energy > 0)) continue;  // a dark band adds nothing
            const Eigen::RowVectorXd mean = (sumLr.row(e) - sumLr.row(s)) / energy;
            const Eigen::Vector3d lightColour = (sumLcmf.row(e) - sumLcmf.row(s)).transpose();
            double total = 0;
            for (int p = 0; p < paths; ++p) {
                const double product =
                    p < m ? mean[p] : mean[pairs[p - m].first] * mean[pairs[p - m].second];
                const Eigen::Vector3d exact =
                    (sumExact.block(e, 3 * p, 1, 3) - sumExact.block(s, 3 * p, 1, 3)).transpose();
                total += (jacobian[p] * (exact - product * lightColour)).squaredNorm();
            }
            cost(s, e) = total;
        }
    // Dynamic programming: best[b][e] = the least cost of samples [0, e) in b bands.
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<std::vector<double>> best(k + 1, std::vector<double>(n + 1, inf));
    std::vector<std::vector<int>> from(k + 1, std::vector<int>(n + 1, 0));
    best[0][0] = 0;
    for (int b = 1; b <= k; ++b)
        for (int e = b; e <= n - (k - b); ++e)
            for (int s = b - 1; s < e; ++s) {
                if (best[b - 1][s] == inf) continue;
                const double c = best[b - 1][s] + cost(s, e);
                if (c < best[b][e]) best[b][e] = c, from[b][e] = s;
            }
    std::vector<int> edges(k + 1);
    edges[k] = n;
    for (int b = k; b > 0; --b) edges[b - 1] = from[b][edges[b]];
    return edges;
}

BounceColours BandColours(const PatchScene& scene, int k) {
    const int m = SurfaceCount(scene);
    const std::vector<int> edges = BandEdges(scene, k);
    // Band b of the light: its energy L_b. Of a surface: its reflectance averaged with the
    // light's weight over the band. Band b's colour: the observer averaged the same way, so the
    // light itself (a white surface) is reproduced exactly.
    Eigen::VectorXd light(k);
    Eigen::MatrixXd surfaces(k, m);
    Eigen::Matrix3Xd response(3, k);
    for (int b = 0; b < k; ++b) {
        const int first = edges[b], count = edges[b + 1] - edges[b];
        Eigen::VectorXd weight = scene.light.segment(first, count);
        light[b] = weight.sum();
        if (!(light[b] > 0)) weight.setConstant(1);  // a dark band: plain averages
        const double sum = weight.sum();
        surfaces.row(b) = weight.transpose() * scene.reflectances.middleRows(first, count) / sum;
        response.col(b) = scene.observer.cmf.middleCols(first, count) * weight / sum;
    }
    BounceColours colours;
    colours.oneBounce = response * (surfaces.array().colwise() * light.array()).matrix();
    colours.twoBounce = TwoBounce(m, [&](int j1, int j2) -> Eigen::Vector3d {
        return response * light.cwiseProduct(surfaces.col(j1)).cwiseProduct(surfaces.col(j2));
    });
    return colours;
}

Eigen::MatrixXd SvdBasis(const PatchScene& scene, int k) {
    const Eigen::MatrixXd once = scene.reflectances.array().colwise() * scene.light.array();
    CheckK(k, int(std::min(once.rows(), once.cols())), "svd-k");
    // Thesis §6.1.2: [U, S, V] = svd(O); the first k columns of U are the optimal basis.
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(once, Eigen::ComputeThinU);
    Eigen::MatrixXd basis = svd.matrixU().leftCols(k);
    for (int c = 0; c < k; ++c)
        if (basis.col(c).sum() < 0) basis.col(c) *= -1;
    return basis;
}

BounceColours SvdExactDirectColours(const PatchScene& scene, int k) {
    const int m = SurfaceCount(scene);
    const Eigen::MatrixXd basis = SvdBasis(scene, k);
    const Eigen::Matrix3Xd response = scene.observer.cmf * basis;  // XYZ of each basis vector
    const Eigen::MatrixXd once = scene.reflectances.array().colwise() * scene.light.array();
    // Each surface stored as the coefficients of l∘r_j: the direct term is its projection.
    const Eigen::MatrixXd direct = basis.transpose() * once;
    // A second bounce off surface j2 acts on those coefficients through the k×k projected
    // operator Bᵀ diag(r_j2) B (Galerkin projection of the reflection).
    std::vector<Eigen::MatrixXd> operators(m);
    for (int j = 0; j < m; ++j)
        operators[j] = basis.transpose() * scene.reflectances.col(j).asDiagonal() * basis;
    BounceColours colours{response * direct, {}};
    colours.twoBounce = TwoBounce(m, [&](int j1, int j2) -> Eigen::Vector3d {
        return response * (operators[j2] * direct.col(j1));
    });
    return colours;
}

BounceColours SvdRenderedColours(const PatchScene& scene, int k) {
    const int m = SurfaceCount(scene);
    std::vector<Eigen::VectorXd> surfaces;
    for (int j = 0; j < m; ++j) surfaces.push_back(scene.reflectances.col(j));
    const Eigen::MatrixXd basis = LightSvdBasis(scene.light, surfaces, k);
    const Eigen::Matrix3Xd response = scene.observer.cmf * basis;
    const Eigen::MatrixXd once = scene.reflectances.array().colwise() * scene.light.array();
    // The coordinates SvdColorSpace stores for each surface: those of l∘r_j (least squares).
    const Eigen::MatrixXd stored = basis.completeOrthogonalDecomposition().solve(once);
    BounceColours colours{response * stored, {}};
    colours.twoBounce = TwoBounce(m, [&](int j1, int j2) -> Eigen::Vector3d {
        return response * stored.col(j1).cwiseProduct(stored.col(j2));
    });
    return colours;
}

BounceColours SvdEq69Colours(const PatchScene& scene, int k) {
    const int m = SurfaceCount(scene);
    const Eigen::MatrixXd basis = SvdBasis(scene, k);
    const Eigen::Matrix3Xd response = scene.observer.cmf * basis;
    // Thesis eq. 6.7: i_B = B i, r_B = B r; eq. 6.9 with BBᵀ taken as I: o_B = r_B ∘ i_B.
    const Eigen::VectorXd light = basis.transpose() * scene.light;
    const Eigen::MatrixXd surfaces = basis.transpose() * scene.reflectances;
    BounceColours colours;
    colours.oneBounce = response * (surfaces.array().colwise() * light.array()).matrix();
    colours.twoBounce = TwoBounce(m, [&](int j1, int j2) -> Eigen::Vector3d {
        return response * light.cwiseProduct(surfaces.col(j1)).cwiseProduct(surfaces.col(j2));
    });
    return colours;
}

}  // namespace gonio::spectral
