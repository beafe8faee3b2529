#include "spectral/light_match.h"

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include "spectral/colorimetry.h"
#include "spectral/cone_projection.h"
#include "spectral/render_color_space.h"
#include "spectral/spectral_error.h"

namespace gonio::spectral {
namespace {

// A cone projection closer to t than this share of |t| is t itself, up to rounding.
constexpr double kReachTolerance = 1e-12;
// Newton stops when |F(λ)| ≤ this share of |t|: a few hundred roundings of the sums in M s̄.
constexpr double kNewtonTolerance = 1e-12;
// A Newton match whose RGB residual is above this has stopped short (the target is on the edge).
constexpr double kMatchTolerance = 1e-9;
// Far more than an interior target needs (tests/spectral: at most a handful); only targets on
// the cone's edge, whose multipliers grow without bound, use them up.
constexpr int kMaxNewtonSteps = 50;
// The Newton system's smallest eigenvalue, relative to trace(M Mᵀ).
constexpr double kRegularisation = 1e-12;

// A point of the dual of the match, θ(λ) = ½ |max(0, s + Mᵀλ)|² − tᵀλ (convex, C¹ and piecewise
// quadratic), with its gradient F(λ) = M max(0, s + Mᵀλ) − t. θ's minimiser gives the primal
// s̄ = max(0, s + Mᵀλ).
struct DualPoint {
    Eigen::Vector3d lambda;
    Eigen::VectorXd shifted;   // v = s + Mᵀλ
    Eigen::Vector3d gradient;  // F(λ)
};

struct Problem {
    const Eigen::VectorXd& light;
    const Eigen::Matrix3Xd& m;
    const Eigen::Vector3d& target;
};

DualPoint EvaluateDual(const Problem& p, const Eigen::Vector3d& lambda) {
    DualPoint point;
    point.lambda = lambda;
    point.shifted = p.light + p.m.transpose() * lambda;
    point.gradient = p.m * point.shifted.cwiseMax(0.0) - p.target;
    return point;
}

// The multipliers without s̄ ≥ 0: s̄ = s + Mᵀλ with M Mᵀ λ = t − M s (least-norm if M is
// rank-deficient). Exact when that s̄ is already non-negative, a close start otherwise.
Eigen::Vector3d UnconstrainedMultipliers(const Problem& p) {
    const Eigen::Matrix3d mmt = p.m * p.m.transpose();
    return mmt.completeOrthogonalDecomposition().solve(p.target - p.m * p.light);
}

// The semismooth Newton direction (Qi & Sun 1993): the generalised Jacobian of F is
// M D Mᵀ, D = diag(vᵢ > 0). Fewer than three independent samples above 0 make it singular, so
// its eigenvalues are raised to a floor far below its scale: d then grows along the missing
// direction (the exact step length scales it back), and a regular Jacobian is used as it is.
Eigen::Vector3d NewtonDirection(const Problem& p, const DualPoint& point) {
    const Eigen::Array<bool, Eigen::Dynamic, 1> active = point.shifted.array() > 0;
    const Eigen::Matrix3Xd activeColumns = p.m * active.cast<double>().matrix().asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> jacobian(activeColumns * p.m.transpose());
    const double floor = kRegularisation * p.m.squaredNorm();
    const Eigen::Vector3d raised = jacobian.eigenvalues().cwiseMax(floor);
    const Eigen::Matrix3d& u = jacobian.eigenvectors();
    return -u * (u.transpose() * point.gradient).cwiseQuotient(raised);
}

// The exact minimiser along λ + α d, α > 0. φ(α) = θ(λ + α d) is convex and piecewise quadratic,
// so φ'(α) = Σ max(0, vᵢ + α wᵢ) wᵢ − tᵀd (w = Mᵀd) is piecewise linear and non-decreasing, with
// a kink where a sample crosses 0; walking the kinks in order finds its root. Near the solution
// no sample crosses and this is the full Newton step α = 1; far from it, or when a singular
// Jacobian makes d huge, it finds the right length. 0 if φ does not fall along d.
double ExactStepLength(const Problem& p, const DualPoint& point, const Eigen::Vector3d& direction) {
    const Eigen::VectorXd w = p.m.transpose() * direction;
    const Eigen::VectorXd& v = point.shifted;
    double slope = -p.target.dot(direction);  // φ' = slope + curvature α on the current piece
    double curvature = 0;
    std::vector<std::pair<double, Eigen::Index>> kinks;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
        if (v(i) > 0 || (v(i) == 0 && w(i) > 0)) slope += v(i) * w(i), curvature += w(i) * w(i);
        if (w(i) != 0 && -v(i) / w(i) > 0) kinks.emplace_back(-v(i) / w(i), i);
    }
    if (slope >= 0) return 0;
    std::sort(kinks.begin(), kinks.end());
    double alpha = 0;
    for (const auto& [at, i] : kinks) {
        if (curvature > 0 && -slope / curvature <= at) return -slope / curvature;
        const double sign = w(i) > 0 ? 1 : -1;  // sample i turns on, or off
        slope += sign * v(i) * w(i);
        curvature += sign * w(i) * w(i);
        alpha = at;
    }
    // θ is bounded below for a reachable t, so the last piece rises, or is flat by rounding.
    return curvature > 0 ? std::max(alpha, -slope / curvature) : alpha;
}

// Newton on F(λ) = 0 from the unconstrained multipliers; returns the last point and the steps.
DualPoint SolveDual(const Problem& p, int* steps) {
    DualPoint point = EvaluateDual(p, UnconstrainedMultipliers(p));
    const double tolerance = kNewtonTolerance * p.target.norm();
    for (*steps = 0; *steps < kMaxNewtonSteps; ++*steps) {
        if (point.gradient.norm() <= tolerance) break;
        const Eigen::Vector3d direction = NewtonDirection(p, point);
        const double alpha = ExactStepLength(p, point, direction);
        if (!(alpha > 0)) break;
        point = EvaluateDual(p, point.lambda + alpha * direction);
    }
    return point;
}

// max |s̄ᵢ μᵢ| over the samples, μ = s̄ − s − Mᵀλ the multiplier of s̄ ≥ 0, relative to the sizes
// of s̄ and of the two terms μ is the difference of (so rounding alone gives ~1e-16).
double Complementarity(const Eigen::VectorXd& matched, const Eigen::VectorXd& light,
                       const Eigen::VectorXd& shift) {
    const Eigen::VectorXd mu = matched - light - shift;
    const double scale = matched.lpNorm<Eigen::Infinity>() *
                         (light.lpNorm<Eigen::Infinity>() + shift.lpNorm<Eigen::Infinity>());
    if (scale == 0) return 0;
    return matched.cwiseProduct(mu).lpNorm<Eigen::Infinity>() / scale;
}

void MeasureMatch(const Problem& p, LightMatch* match) {
    const double targetNorm = p.target.norm();
    const double offBy = (p.m * match->spectrum - p.target).norm();
    match->rgbResidual = targetNorm > 0 ? offBy / targetNorm : offBy;
    const double change = (match->spectrum - p.light).norm();
    match->relativeChange = p.light.norm() > 0 ? change / p.light.norm() : change;
    match->complementarity =
        Complementarity(match->spectrum, p.light, p.m.transpose() * match->lambda);
}

template <typename... Numbers>
std::string Format(const char* format, Numbers... numbers) {
    char text[256];
    std::snprintf(text, sizeof text, format, numbers...);
    return text;
}

LightMatch Unreachable(const Problem& p, const ConeProjection& projection) {
    LightMatch match;
    match.spectrum = p.light;
    match.lambda.setZero();
    match.rgbResidual = projection.residual.norm() / p.target.norm();
    match.certificate = -projection.residual.normalized();
    match.message = Format(
        "no non-negative light has this RGB: the nearest colour a spectrum reaches is %.3g "
        "of |t| away (certificate y = (%.4g, %.4g, %.4g): Mᵀy ≥ 0 but yᵀt < 0)",
        match.rgbResidual, match.certificate(0), match.certificate(1), match.certificate(2));
    return match;
}

// t = 0: every sample M sees must be 0 (its colours span a pointed cone, as any observer's do:
// ȳ ≥ 0); a sample M does not see is free, so it keeps its value, clamped at 0.
LightMatch BlackTarget(const Problem& p) {
    LightMatch match;
    match.reachable = true;
    match.spectrum = p.light.cwiseMax(0.0);
    for (Eigen::Index i = 0; i < p.m.cols(); ++i)
        if (!p.m.col(i).isZero(0)) match.spectrum(i) = 0;
    match.lambda.setZero();
    match.certificate.setZero();
    MeasureMatch(p, &match);
    match.complementarity = 0;  // μ is unbounded here (λ → −∞); s̄ᵢ μᵢ = 0 holds in the limit
    match.message = "the target is black: the matched light is 0 wherever M sees it";
    return match;
}

std::string Summary(const LightMatch& match) {
    return Format(" in %d Newton steps: RGB residual %.2g, complementarity %.2g, change %.1f%%",
                  match.newtonSteps, match.rgbResidual, match.complementarity,
                  100 * match.relativeChange);
}

// On the cone's edge (a single wavelength's colour, a point of the purple line) the multipliers
// diverge and Newton stops short. There the feasible lights are few (often one: the edge's own
// wavelengths), so the cone projection's light, which has the RGB, is returned instead.
void UseConeProjection(const Problem& p, const ConeProjection& projection, LightMatch* match) {
    match->spectrum = projection.weights;
    MeasureMatch(p, match);
    match->message =
        "the target is on the edge of the colours non-negative spectra reach, where Newton's "
        "multipliers diverge: returned the non-negative least-squares light, which has the RGB "
        "but is the closest only when the edge holds a single light" +
        Summary(*match);
}

LightMatch NewtonMatch(const Problem& p, const ConeProjection& projection) {
    LightMatch match;
    match.reachable = true;
    const DualPoint point = SolveDual(p, &match.newtonSteps);
    match.lambda = point.lambda;
    match.spectrum = point.shifted.cwiseMax(0.0);
    match.certificate.setZero();
    MeasureMatch(p, &match);
    if (match.rgbResidual > kMatchTolerance) return UseConeProjection(p, projection, &match), match;
    match.message = "matched" + Summary(match);
    return match;
}

void CheckInputs(const Problem& p) {
    if (p.light.size() != p.m.cols())
        throw SpectralError("light match: the light has " + std::to_string(p.light.size()) +
                            " samples but the RGB matrix " + std::to_string(p.m.cols()) +
                            " columns");
    if (!p.light.allFinite() || !p.m.allFinite() || !p.target.allFinite())
        throw SpectralError("light match: the light, the RGB matrix or the target is not finite");
}

}  // namespace

LightMatch MatchLightToRgb(const Eigen::VectorXd& light, const Eigen::Matrix3Xd& toRgb,
                           const Eigen::Vector3d& target) {
    const Problem p{light, toRgb, target};
    CheckInputs(p);
    if (target.isZero(0)) return BlackTarget(p);
    const ConeProjection projection = ProjectOntoCone(toRgb, target);
    if (projection.residual.norm() > kReachTolerance * target.norm())
        return Unreachable(p, projection);
    return NewtonMatch(p, projection);
}

Eigen::Vector3d NormalisedTarget(const Eigen::VectorXd& light, const Eigen::Matrix3Xd& toRgb,
                                 const Eigen::Vector3d& target, Brightness brightness) {
    const Eigen::Vector3d rgb = toRgb * light;
    const bool euclidean = brightness == Brightness::Euclidean;
    const double of = euclidean ? rgb.norm() : rgb.maxCoeff();
    const double wanted = euclidean ? target.norm() : target.maxCoeff();
    if (!(of > 0) || !(wanted > 0)) return target;
    return target * (of / wanted);
}

Eigen::Matrix3Xd CieRgbMatrix(const WavelengthGrid& grid) {
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), grid);
    // Scaled so that a constant spectrum of 1 has Y = 1, as in the render colour space.
    const double yOfOne = observer.cmf.row(1).sum();
    Eigen::Matrix3Xd m(3, grid.Count());
    for (Eigen::Index i = 0; i < m.cols(); ++i)
        m.col(i) = XyzToLinearSrgb(observer.cmf.col(i) / yOfOne);
    return m;
}

Eigen::Matrix3Xd RenderRgbMatrix(const WavelengthGrid& grid) {
    const RenderColorSpace space = SampledColorSpace(grid);
    Eigen::Matrix3Xd m(3, grid.Count());
    for (Eigen::Index i = 0; i < m.cols(); ++i)
        for (int c = 0; c < 3; ++c) m(c, i) = space.toRgb[size_t(3 * i + c)];
    return m;
}

}  // namespace gonio::spectral
