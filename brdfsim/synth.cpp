#include "brdfsim/synth.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <array>
#include <cmath>

#include "base/hash.h"
#include "base/math.h"

namespace gonio {

namespace {

constexpr int kDims = 5;

// The numbers for photon i depend only on (seed, i): the same map whatever the thread count.
class PhotonRandom {
  public:
    explicit PhotonRandom(const SynthOptions& options) : options_(options) {
        double phi = 2.0;  // φ_d solves x^(d+1) = x + 1 (Roberts 2018)
        for (int i = 0; i < 50; ++i) phi = std::pow(1.0 + phi, 1.0 / (kDims + 1));
        std::uint64_t state = options.seed * 0x2545f4914f6cdd1dull + 7;
        for (int d = 0; d < kDims; ++d) {
            alpha_[d] = std::fmod(std::pow(1.0 / phi, d + 1), 1.0);
            shift_[d] = ToUnitDouble(SplitMix64(state));
        }
    }

    std::array<double, kDims> Draw(std::uint64_t i) const {
        std::array<double, kDims> u;
        if (options_.stratified) {
            for (int d = 0; d < kDims; ++d) {
                const double x = shift_[d] + static_cast<double>(i) * alpha_[d];
                u[d] = x - std::floor(x);
            }
        } else {
            std::uint64_t state = options_.seed ^ (i * 0xd1b54a32d192ed03ull);
            SplitMix64(state);
            for (double& x : u) x = ToUnitDouble(SplitMix64(state));
        }
        return u;
    }

  private:
    const SynthOptions& options_;
    std::array<double, kDims> alpha_, shift_;
};

// One traced path; returns false when it leaves below the horizon.
bool DrawPhoton(const AnalyticBrdf& brdf, const SynthOptions& options, const PhotonRandom& random,
                std::uint64_t i, float* row) {
    const std::array<double, kDims> u = random.Draw(i);
    double thetaIn, phiIn = 0.0, probability = 1.0 / (2 * kPi);
    if (options.isotropic) {
        // θ' uniform: density 2/π per radian, which is 2/π / (2π sin θ') per steradian of the
        // rotation-symmetric distribution (docs/formats.md).
        thetaIn = 0.5 * kPi * u[0];
        probability = (2 / kPi) / (2 * kPi * std::max(std::sin(thetaIn), 1e-12));
    } else {
        thetaIn = std::acos(1.0 - u[0]);  // cos θ' uniform: p_in = 1/2π
        phiIn = 2 * kPi * u[1];
    }
    const Imath::V3d wIn(std::sin(thetaIn) * std::cos(phiIn), std::sin(thetaIn) * std::sin(phiIn),
                         std::cos(thetaIn));
    Imath::V3d wOut;
    double pdf;
    const double uniformPdf = 1 / (2 * kPi);
    if (options.defensive && u[2] < 0.5) {
        const double cosT = u[3], sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT));
        wOut = Imath::V3d(sinT * std::cos(2 * kPi * u[4]), sinT * std::sin(2 * kPi * u[4]), cosT);
    } else {
        const double lobe = options.defensive ? 2 * (u[2] - 0.5) : u[2];
        wOut = brdf.Sample(wIn, lobe, u[3], u[4], &pdf);
    }
    if (wOut.z <= 0) return false;
    pdf = brdf.Pdf(wIn, wOut);
    if (options.defensive) pdf = 0.5 * uniformPdf + 0.5 * pdf;
    if (pdf <= 0) return false;
    const double beta = brdf.Eval(wIn, wOut) * wOut.z / pdf;
    double phiOut = std::atan2(wOut.y, wOut.x);
    if (phiOut < 0) phiOut += 2 * kPi;
    row[kThetaIn] = static_cast<float>(thetaIn);
    row[kPhiIn] = static_cast<float>(phiIn);
    row[kThetaOut] = static_cast<float>(std::acos(std::min(1.0, wOut.z)));
    row[kPhiOut] = static_cast<float>(phiOut);
    row[kProbability] = static_cast<float>(probability);
    for (int c = 0; c < options.ncomps; ++c) row[kFirstColour + c] = static_cast<float>(beta);
    return true;
}

constexpr std::uint64_t kBlock = 1 << 16;

// Fills `rows` with the escaping photons of paths [first, first + n), in path order.
void DrawBlock(const AnalyticBrdf& brdf, const SynthOptions& options, const PhotonRandom& random,
               std::uint64_t first, std::uint64_t n, std::vector<float>& rows) {
    const int stride = kFirstColour + options.ncomps;
    std::vector<float> all(n * stride);
    std::vector<char> kept(n);
    tbb::parallel_for(std::uint64_t(0), n, [&](std::uint64_t j) {
        kept[j] = DrawPhoton(brdf, options, random, first + j, &all[j * stride]);
    });
    rows.clear();
    for (std::uint64_t j = 0; j < n; ++j) {
        if (kept[j]) rows.insert(rows.end(), &all[j * stride], &all[(j + 1) * stride]);
    }
}

}  // namespace

PhotonMap SynthesizePhotonMap(const AnalyticBrdf& brdf, const SynthOptions& options) {
    PhotonRandom random(options);
    PhotonMap map;
    map.ncomps = options.ncomps;
    map.paths = options.paths;
    std::vector<float> rows;
    for (std::uint64_t first = 0; first < options.paths; first += kBlock) {
        DrawBlock(brdf, options, random, first, std::min(kBlock, options.paths - first), rows);
        map.rows.insert(map.rows.end(), rows.begin(), rows.end());
    }
    return map;
}

PhotonMapHeader WriteSyntheticPhotonMap(const AnalyticBrdf& brdf, const SynthOptions& options,
                                        const std::string& path) {
    PhotonRandom random(options);
    // A first pass counts the escaping photons, for the header, without holding the map.
    const std::uint64_t kept = tbb::parallel_reduce(
        tbb::blocked_range<std::uint64_t>(0, options.paths), std::uint64_t(0),
        [&](const tbb::blocked_range<std::uint64_t>& range, std::uint64_t count) {
            std::vector<float> row(kFirstColour + options.ncomps);
            for (std::uint64_t i = range.begin(); i != range.end(); ++i) {
                count += DrawPhoton(brdf, options, random, i, row.data());
            }
            return count;
        },
        [](std::uint64_t a, std::uint64_t b) { return a + b; });
    const PhotonMapHeader header{kept, options.paths};
    PhotonMapWriter writer(path, header, options.ncomps);
    std::vector<float> rows;
    const int stride = kFirstColour + options.ncomps;
    for (std::uint64_t first = 0; first < options.paths; first += kBlock) {
        DrawBlock(brdf, options, random, first, std::min(kBlock, options.paths - first), rows);
        for (std::size_t j = 0; j < rows.size(); j += stride) writer.Append(&rows[j]);
    }
    writer.Close();
    return header;
}

}  // namespace gonio
