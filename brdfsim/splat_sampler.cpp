#include "brdfsim/splat_sampler.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "base/hash.h"
#include "base/math.h"

namespace gonio {

namespace {

// Cells of incoming centres (anisotropic sets): bands of equal θ' width, equal φ' sectors. A
// query visits the cells its cap of radius R can reach, about 1/20 of them at R = 0.3.
constexpr int kBands = 32;
constexpr int kSectors = 64;
constexpr double kBandWidth = kPi / 2 / kBands;

int SectorOf(double phi) {
    const int s = static_cast<int>(std::floor((phi + kPi) / (2 * kPi) * kSectors));
    return ((s % kSectors) + kSectors) % kSectors;
}

int CellOf(const SplatGeometry& g) {
    const double theta = std::acos(std::clamp<double>(g.inZ, -1.0, 1.0));
    const int band = std::min(kBands - 1, static_cast<int>(theta / kBandWidth));
    return band * kSectors + SectorOf(std::atan2(g.inY, g.inX));
}

// Two unit vectors completing c to a right-handed frame.
void Frame(const Imath::V3d& c, Imath::V3d* t, Imath::V3d* s) {
    const Imath::V3d helper = std::abs(c.x) < 0.9 ? Imath::V3d(1, 0, 0) : Imath::V3d(0, 1, 0);
    *t = helper.cross(c).normalized();
    *s = c.cross(*t);
}

}  // namespace

SplatSampler::SplatSampler(std::shared_ptr<const SplatSet> splats, const Brdf& exact)
    : splats_(std::move(splats)), exact_(exact) {
    const SplatSet& s = *splats_;
    const SplatParams& p = s.params;
    if (s.Size() >= (std::size_t{1} << 32)) {
        throw std::invalid_argument("too many splats to sample (2^32 or more)");
    }
    inLimit_ = static_cast<float>(p.isotropic ? p.radius : 2.0 * std::sin(0.5 * p.radius));
    chordLimit2_ = inLimit_ * inLimit_;
    const KernelOutMarginalTable marginal(p.radius, p.norm);
    marginal_.resize(kMarginalSteps + 1);
    for (int i = 0; i <= kMarginalSteps; ++i) {
        const double in = double(inLimit_) * i / kMarginalSteps;
        marginal_[i] = marginal(p.isotropic ? in : 2.0 * std::asin(0.5 * in));
    }
    std::vector<std::uint32_t> order(s.Size());
    std::iota(order.begin(), order.end(), 0u);
    if (p.isotropic) {
        std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return s.geometry[a].thetaIn < s.geometry[b].thetaIn;
        });
    } else {
        // A counting sort by cell: cellStart_[c] .. cellStart_[c + 1] are cell c's splats.
        cellStart_.assign(kBands * kSectors + 1, 0);
        for (const SplatGeometry& g : s.geometry) ++cellStart_[CellOf(g) + 1];
        std::partial_sum(cellStart_.begin(), cellStart_.end(), cellStart_.begin());
        std::vector<std::uint32_t> next(cellStart_.begin(), cellStart_.end() - 1);
        for (std::uint32_t k = 0; k < s.Size(); ++k) order[next[CellOf(s.geometry[k])]++] = k;
    }
    sorted_.reserve(s.Size());
    for (std::uint32_t k : order) {
        double sum = 0.0;
        for (int c = 0; c < s.ncomps; ++c) sum += s.weights[k * s.ncomps + c];
        const SplatGeometry& g = s.geometry[k];
        const float x = p.isotropic ? g.thetaIn : g.inX;
        sorted_.push_back({x, g.inY, g.inZ, static_cast<float>(sum / s.ncomps), k});
    }
    if (p.isotropic) {
        prefix_.assign(sorted_.size() + 1, 0.0);
        for (std::size_t i = 0; i < sorted_.size(); ++i)
            prefix_[i + 1] = prefix_[i] + std::max(0.0f, sorted_[i].meanWeight);
        marginalMax_ = *std::max_element(marginal_.begin(), marginal_.end());
        TabulateIsotropicWeight();
    }
}

double SplatSampler::Marginal(float in) const {
    const float u = in / inLimit_ * kMarginalSteps;
    const int i = std::min(static_cast<int>(u), kMarginalSteps - 1);
    return marginal_[i] + (u - i) * (marginal_[i + 1] - marginal_[i]);
}

double SplatSampler::IncomingDistance(const SplatMixture::Term& term) const {
    return splats_->params.isotropic ? term.in : 2.0 * std::asin(0.5 * double(term.in));
}

void SplatSampler::GatherAnisotropic(const Imath::V3f& query, std::uint32_t image,
                                     SplatMixture* mixture) const {
    const double radius = splats_->params.radius, sinR = std::sin(radius);
    const double theta = std::acos(std::clamp<double>(query.z, -1.0, 1.0));
    const double phi = std::atan2(query.y, query.x);
    if (theta - radius >= kPi / 2) return;
    const int bandLo = std::max(0, static_cast<int>((theta - radius) / kBandWidth));
    const int bandHi = std::min(kBands - 1, static_cast<int>((theta + radius) / kBandWidth));
    // A cap around a pole holds every φ'; elsewhere a centre at colatitude θ within R of the
    // query differs from it by |Δφ| <= asin(sin R / sin θ) (spherical law of sines).
    const bool aroundPole = theta < radius || theta > kPi - radius;
    double total = mixture->Total();
    auto visit = [&](int cell) {
        for (std::uint32_t i = cellStart_[cell]; i < cellStart_[cell + 1]; ++i) {
            const Sorted& e = sorted_[i];
            const float chord2 = Chord2(query.x - e.x, query.y - e.y, query.z - e.z);
            if (chord2 >= chordLimit2_) continue;
            const float chord = std::sqrt(chord2);
            const double weight = e.meanWeight * Marginal(chord);
            if (!(weight > 0.0)) continue;
            total += weight;
            mixture->terms.push_back({e.splat, image, chord, total});
        }
    };
    for (int band = bandLo; band <= bandHi; ++band) {
        const double sinLo = std::sin(band * kBandWidth);
        int first = 0, last = kSectors - 1;
        if (!aroundPole && sinLo > sinR) {
            const double dPhi = std::asin(sinR / sinLo);
            first = static_cast<int>(std::floor((phi - dPhi + kPi) / (2 * kPi) * kSectors));
            last = static_cast<int>(std::floor((phi + dPhi + kPi) / (2 * kPi) * kSectors));
            if (last - first + 1 >= kSectors) first = 0, last = kSectors - 1;
        }
        for (int sector = first; sector <= last; ++sector) {
            visit(band * kSectors + ((sector % kSectors) + kSectors) % kSectors);
        }
    }
}

std::pair<std::size_t, std::size_t> SplatSampler::IsotropicRange(float theta) const {
    const auto below = [](const Sorted& e, float value) { return e.x < value; };
    const auto lo = std::lower_bound(sorted_.begin(), sorted_.end(), theta - inLimit_, below);
    const auto hi = std::lower_bound(lo, sorted_.end(), theta + inLimit_, below);
    return {std::size_t(lo - sorted_.begin()), std::size_t(hi - sorted_.begin())};
}

// W(x) = Σ_k w̄_k M(|x − θ'_k|) at the points x_j = x₀ + jΔ, where Δ is the spacing of M's
// table: M is linear between its knots, so the splats whose θ' lie in one Δ-wide bin sit on one
// linear piece of M as seen from every x_j. With each bin's Σ w̄ and Σ w̄ (θ' − left edge),
// W(x_j) is a sum over the 2 × kMarginalSteps bins within R, exact, and the whole table costs
// about as much as a few hundred direct sums.
void SplatSampler::TabulateIsotropicWeight() {
    weightStart_ = -inLimit_;
    weightStep_ = inLimit_ / kMarginalSteps;
    const int points = static_cast<int>(std::ceil((kPi / 2 + 2 * inLimit_) / weightStep_)) + 1;
    std::vector<double> mass(points, 0.0), moment(points, 0.0);
    for (const Sorted& e : sorted_) {
        const double at = (e.x - weightStart_) / weightStep_;
        const int bin = std::clamp(static_cast<int>(at), 0, points - 1);
        const double weight = std::max(0.0f, e.meanWeight);
        mass[bin] += weight;
        moment[bin] += weight * (at - bin);  // in units of Δ
    }
    weightTable_.assign(points, 0.0);
    for (int j = 0; j < points; ++j) {
        double total = 0.0;
        for (int i = 0; i < kMarginalSteps; ++i) {
            const double slope = marginal_[i + 1] - marginal_[i];  // per Δ
            // Right of x_j, bin j + i: offset iΔ + δ. Left, bin j − 1 − i: offset (i + 1)Δ − δ.
            if (j + i < points) total += marginal_[i] * mass[j + i] + slope * moment[j + i];
            if (j - 1 - i >= 0)
                total += marginal_[i + 1] * mass[j - 1 - i] - slope * moment[j - 1 - i];
        }
        weightTable_[j] = total;
    }
}

double SplatSampler::IsotropicWeight(float theta) const {
    // Linear between the exact points: W has a kink of at most one M step per splat in each Δ,
    // which keeps the interpolation within 4e-7 of W (splat_sampler_test).
    const double at = (theta - weightStart_) / weightStep_;
    const int j = std::clamp(static_cast<int>(at), 0, static_cast<int>(weightTable_.size()) - 2);
    return weightTable_[j] + (at - j) * (weightTable_[j + 1] - weightTable_[j]);
}

SplatMixture::Term SplatSampler::PickIsotropicTerm(const SplatMixture::Image& image,
                                                   std::uint64_t* state) const {
    const auto [lo, hi] = IsotropicRange(image.theta);
    const double base = prefix_[lo], span = prefix_[hi] - prefix_[lo];
    for (;;) {
        const double target = base + ToUnitDouble(SplitMix64(*state)) * span;
        // The first position whose prefix passes the target: splats of weight 0 are never it.
        const auto at =
            std::upper_bound(prefix_.begin() + lo + 1, prefix_.begin() + hi + 1, target);
        const std::size_t i = std::min<std::size_t>(at - prefix_.begin(), hi) - 1;
        const float offset = std::abs(image.theta - sorted_[i].x);
        if (ToUnitDouble(SplitMix64(*state)) * marginalMax_ < Marginal(offset))
            return {sorted_[i].splat, image.image, offset, 0.0};
    }
}

SplatMixture::Term SplatSampler::PickTerm(const SplatMixture& mixture, float u,
                                          std::uint64_t* state) const {
    const double target = static_cast<double>(u) * mixture.Total();
    if (!mixture.images.empty()) {
        const auto pick = std::upper_bound(
            mixture.images.begin(), mixture.images.end(), target,
            [](double value, const SplatMixture::Image& i) { return value < i.cumulative; });
        return PickIsotropicTerm(*std::min(pick, mixture.images.end() - 1), state);
    }
    const auto pick = std::upper_bound(
        mixture.terms.begin(), mixture.terms.end(), target,
        [](double value, const SplatMixture::Term& t) { return value < t.cumulative; });
    return *std::min(pick, mixture.terms.end() - 1);
}

void SplatSampler::Prepare(const Imath::V3f& wIn, SplatMixture* mixture) const {
    mixture->wIn = wIn;
    mixture->terms.clear();
    mixture->images.clear();
    if (!(wIn.z > 0)) return;
    const SplatParams& p = splats_->params;
    const bool reflect = p.horizon == Horizon::kReflect;
    // The same images, under the same conditions, as SplatSet::MakeQuery.
    if (p.isotropic) {
        const double theta = std::acos(std::clamp<double>(wIn.z, -1.0, 1.0));
        double total = 0.0;
        const auto addImage = [&](std::uint32_t image, double imageTheta) {
            const float t = static_cast<float>(imageTheta);
            const double weight = IsotropicWeight(t);
            if (!(weight > 0.0)) return;
            total += weight;
            mixture->images.push_back({image, t, total});
        };
        addImage(0, theta);
        if (reflect && theta < p.radius) addImage(1, -theta);
        if (reflect && theta > kPi / 2 - p.radius) addImage(2, kPi - theta);
        return;
    }
    GatherAnisotropic(wIn, 0, mixture);
    if (reflect && wIn.z < std::sin(p.radius)) {
        GatherAnisotropic(Imath::V3f(wIn.x, wIn.y, -wIn.z), 1, mixture);
    }
}

Imath::V3d SplatSampler::OutCentre(const SplatMixture::Term& term) const {
    const SplatGeometry& g = splats_->geometry[term.splat];
    // Isotropic image 1 (through the pole) turns ω by π about the normal.
    if (splats_->params.isotropic && term.image == 1) return Imath::V3d(-g.outX, -g.outY, g.outZ);
    return Imath::V3d(g.outX, g.outY, g.outZ);
}

bool SplatSampler::Sample(const SplatMixture& mixture, float u, std::uint64_t seed,
                          Imath::V3f* wOut) const {
    if (!(mixture.Total() > 0.0)) return false;
    std::uint64_t state = seed;
    const SplatMixture::Term term = PickTerm(mixture, u, &state);
    const SplatParams& p = splats_->params;
    // ω at distance b from the centre: density ∝ K(‖a, b‖ / R) on the sphere, by rejection
    // from the uniform cap b <= bMax; K is largest, K(a / R), at b = 0.
    const double a = IncomingDistance(term);
    const double cosMax = std::cos(KernelSupportLimit(p.norm, p.radius, a));
    const double kMax = SplatKernel(a / p.radius);
    double cosB, b;
    do {
        cosB = 1.0 - ToUnitDouble(SplitMix64(state)) * (1.0 - cosMax);
        b = std::acos(std::clamp(cosB, -1.0, 1.0));
    } while (ToUnitDouble(SplitMix64(state)) * kMax >=
             SplatKernel(CombineDistances(p.norm, a, b) / p.radius));
    const double phi = 2 * kPi * ToUnitDouble(SplitMix64(state));
    const Imath::V3d c = OutCentre(term);
    Imath::V3d t, s;
    Frame(c, &t, &s);
    const double sinB = std::sqrt(std::max(0.0, 1.0 - cosB * cosB));
    Imath::V3d w = cosB * c + sinB * (std::cos(phi) * t + std::sin(phi) * s);
    if (w.z < 0) {
        if (p.horizon != Horizon::kReflect) return false;
        w.z = -w.z;  // the image b of the outgoing side
    }
    if (!(w.z > 0)) return false;
    if (p.isotropic) {  // the domain holds ω relative to φ_in: turn it back by φ_in
        const Imath::V3f& in = mixture.wIn;
        const double r = std::sqrt(double(in.x) * in.x + double(in.y) * in.y);
        if (r > 1e-7) {
            const double cp = in.x / r, sp = in.y / r;
            w = Imath::V3d(cp * w.x - sp * w.y, sp * w.x + cp * w.y, w.z);
        }
    }
    *wOut = Imath::V3f(w.normalized());
    return true;
}

double SplatSampler::Pdf(const SplatMixture& mixture, const Imath::V3f& wOut, float* f) const {
    const int n = splats_->NumComponents();
    std::vector<float> local(f ? 0 : n);
    float* value = f ? f : local.data();
    const double total = mixture.Total();
    if (!(total > 0.0) || !(wOut.z > 0)) {
        std::fill(value, value + n, 0.0f);
        return 0.0;
    }
    exact_.Eval(mixture.wIn, wOut, value);
    double mean = 0.0;
    for (int c = 0; c < n; ++c) mean += value[c];
    return mean / n / total;
}

double SplatSampler::Pdf(const Imath::V3f& wIn, const Imath::V3f& wOut) const {
    SplatMixture mixture;
    Prepare(wIn, &mixture);
    return Pdf(mixture, wOut);
}

}  // namespace gonio
