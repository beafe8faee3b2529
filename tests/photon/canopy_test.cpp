// The analytic canopy oracle (issue 18 item 3): a periodic tile of many small, randomly placed
// and oriented bi-Lambertian leaves over a black ground is the turbid-medium canopy of
// radiative transfer, whose once-scattered BRDF canopy_oracle.h derives. The photons the tracer
// tags as scattered once must match it away from the hotspot; larger leaves raise the hotspot.
#include <cmath>
#include <sstream>
#include <utility>

#include "base/random.h"
#include "bin_grid.h"
#include "canopy_oracle.h"
#include "renderer/photon/micro_brdf.h"

namespace gonio {
namespace {

using Imath::V3d;
using Imath::V3f;

constexpr double kRho = 0.5, kTau = 0.3, kLai = 1;
constexpr double kTile = 1, kHeight = 1;  // the periodic tile and the canopy's depth

// Γ(β) as the integral it stands for, over leaf normals n uniform on the upper hemisphere:
// Γ/π = (1/2π) ∫ |Ω′·n| |Ω·n| (ρ or τ)/π dn, ρ when Ω′ and Ω leave n on different sides.
double GammaByQuadrature(const V3d& in, const V3d& out) {
    constexpr int m = 400;
    double sum = 0;
    for (int i = 0; i < m; ++i) {
        const double theta = (i + 0.5) * kPi / 2 / m;
        for (int j = 0; j < 4 * m; ++j) {
            const V3d n = test::Direction(theta, (j + 0.5) * kPi / (2 * m));
            const double a = in.dot(n), b = out.dot(n);
            sum += std::abs(a * b) * (a * b < 0 ? kRho : kTau) / kPi * std::sin(theta);
        }
    }
    return sum * (kPi / 2 / m) * (kPi / (2 * m)) / (2 * kPi) * kPi;
}

TEST(CanopyOracle, GammaClosedFormIsTheLeafNormalIntegral) {
    for (double beta : {0.0, 0.4, 1.1, 1.9, 2.6, kPi}) {
        const V3d in(0, 0, -1), out(std::sin(beta), 0, -std::cos(beta));
        EXPECT_NEAR(test::SphericalGamma(std::cos(beta), kRho, kTau), GammaByQuadrature(in, out),
                    2e-5)
            << beta;
    }
}

// `count` square leaves of side `side` with centres uniform in the tile × [0, H] and normals
// uniform on the sphere; leaves over a tile edge are repeated on the other side, so that the
// tile is periodic. The leaves are bi-Lambertian: the leaf model without cuticle (η = 1).
std::string Canopy(int count, double side, uint64_t seed) {
    std::ostringstream rib;
    rib << "Option \"BRDFLight\" \"integer periodic\" 1\nWorldBegin\n"
        << "Attribute \"brdflight\" \"string model\" \"leaf\" \"float eta\" 1 "
        << "\"color reflectance\" [" << kRho << " " << kRho << " " << kRho << "] "
        << "\"color transmittance\" [" << kTau << " " << kTau << " " << kTau << "]\n";
    SampleRandom random(seed, 0, 0, 0);
    const double reach = side / std::sqrt(2.0);
    for (int i = 0; i < count; ++i) {
        const V3d c((random.Next() - 0.5) * kTile, (random.Next() - 0.5) * kTile,
                    random.Next() * kHeight);
        const V3f n = FromLocal(V3f(0, 0, 1), 2 * random.Next() - 1, 2 * kPiF * random.Next());
        V3f t, b;
        OrthonormalBasis(n, &t, &b);
        const float psi = 2 * kPiF * random.Next();
        const V3d u = V3d(std::cos(psi) * t + std::sin(psi) * b) * (side / 2);
        const V3d v = V3d(n.cross(V3f(u))) * 1.0;
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                const V3d o = c + V3d(dx * kTile, dy * kTile, 0);
                if (std::abs(o.x) > kTile / 2 + reach || std::abs(o.y) > kTile / 2 + reach)
                    continue;
                rib << "Polygon \"P\" [";
                for (const V3d& p : {o - u - v, o + u - v, o + u + v, o - u + v})
                    rib << p.x << " " << p.y << " " << p.z << " ";
                rib << "]\n";
            }
        }
    }
    rib << "WorldEnd\n";
    return rib.str();
}

// Energy per path of the once-scattered photons in θ bands × |Δφ| sectors (folded about the
// plane of incidence), measured and from the oracle, for light at θ′ ∈ [39°, 41°]. The bands
// hold about equal solid angles, so that no bin is much noisier than the rest.
struct Comparison {
    PhotonTraceResult trace;
    static constexpr int kBands = 5, kSectors = 4;                         // 45° sectors
    static constexpr double kEdges[kBands + 1] = {0, 25, 40, 52, 63, 75};  // degrees
    test::BinnedEstimate measured;
    std::vector<double> expected;
    static int BinOf(double theta, double dPhi) {
        int band = 0;
        while (band < kBands && theta >= kEdges[band + 1] * kDegree) ++band;
        if (band >= kBands) return -1;
        double a = std::fmod(std::abs(dPhi), 2 * kPi);
        if (a > kPi) a = 2 * kPi - a;
        return band * kSectors + std::min(kSectors - 1, int(a / (kPi / kSectors)));
    }
};

constexpr double kLightTheta = 40 * kDegree;

Comparison Compare(int leaves, double side, uint64_t paths) {
    PhotonTraceSettings s;
    s.paths = paths;
    s.area = float(kTile);
    s.periodic = true;
    s.seed = 17;
    s.thetaMin = float(kLightTheta - kDegree);
    s.thetaMax = float(kLightTheta + kDegree);
    Comparison c;
    c.trace = test::TraceRib(Canopy(leaves, side, 3), s);
    const PhotonTraceResult& r = c.trace;
    const size_t stride = test::Stride(r);
    // Bin() sees rows only; the row index gives the photon's bounce tag.
    c.measured = test::Bin(
        r, Comparison::kBands * Comparison::kSectors,
        [&](const float* row) {
            if (r.bounces[(row - r.rows.data()) / stride] != 1) return -1;
            return Comparison::BinOf(row[kThetaOut], row[kPhiOut] - row[kPhiIn]);
        },
        [](const float* row) { return double(row[kFirstColour]); });
    // ∫_bin f₁ cos θ dω, averaged over cos θ′ uniform on the band (8-point Gauss), both halves
    // of the fold.
    c.expected.assign(Comparison::kBands * Comparison::kSectors, 0.0);
    const double c0 = std::cos(s.thetaMax), c1 = std::cos(s.thetaMin);
    constexpr int m = 24;
    for (int g = 0; g < 8; ++g) {
        const double mu0 = 0.5 * (c0 + c1) + 0.5 * (c1 - c0) * test::kGaussX[g];
        const V3d toLight = test::Direction(std::acos(mu0), 0);
        for (int b = 0; b < Comparison::kBands * Comparison::kSectors; ++b) {
            const int band = b / Comparison::kSectors, sector = b % Comparison::kSectors;
            const double t0 = Comparison::kEdges[band] * kDegree;
            const double dTheta =
                (Comparison::kEdges[band + 1] - Comparison::kEdges[band]) * kDegree / m;
            const double dPhi = kPi / Comparison::kSectors / m;
            double sum = 0;
            for (int i = 0; i < m; ++i) {
                const double theta = t0 + (i + 0.5) * dTheta;
                for (int j = 0; j < m; ++j) {
                    const double phi = (sector * m + j + 0.5) * dPhi;
                    const V3d w = test::Direction(theta, phi);
                    sum += test::CanopySingleScatterBrdf(toLight, w, kLai, kRho, kTau) * w.z *
                           std::sin(theta);
                }
            }
            // both signs of Δφ: twice the half-sector
            c.expected[b] += 0.5 * test::kGaussW[g] * 2 * sum * dTheta * dPhi;
        }
    }
    return c;
}

// The bin holding the backscatter direction (θ = θ′, Δφ = 0) and its neighbours in θ.
bool NearHotspot(int b) {
    const int band = b / Comparison::kSectors, sector = b % Comparison::kSectors;
    return sector == 0 && (band == 1 || band == 2);
}

// Measured over turbid once-scattered energy in the cone of half-angle `gamma` about each
// photon's backscatter direction (ω = ω′), with its standard error.
std::pair<double, double> HotspotRatio(const PhotonTraceResult& r, double gamma) {
    const size_t stride = test::Stride(r);
    const test::BinnedEstimate hot = test::Bin(
        r, 1,
        [&](const float* row) {
            if (r.bounces[(row - r.rows.data()) / stride] != 1) return -1;
            const V3d in = test::Direction(row[kThetaIn], 0);
            const V3d out = test::Direction(row[kThetaOut], row[kPhiOut] - row[kPhiIn]);
            return in.dot(out) >= std::cos(gamma) ? 0 : -1;
        },
        [](const float* row) { return double(row[kFirstColour]); });
    // ∫_cone f₁ cos θ dω in polar coordinates about ω′, averaged over the incidence band
    double expected = 0;
    constexpr int m = 32;
    for (int g = 0; g < 8; ++g) {
        const double theta0 = kLightTheta + kDegree * test::kGaussX[g];
        const V3d toLight = test::Direction(theta0, 0);
        const V3d t = test::Direction(theta0 + kPi / 2, 0), b(0, 1, 0);
        double sum = 0;
        for (int i = 0; i < m; ++i) {
            const double a = (i + 0.5) * gamma / m;
            for (int j = 0; j < m; ++j) {
                const double phi = (j + 0.5) * 2 * kPi / m;
                const V3d w =
                    toLight * std::cos(a) + (t * std::cos(phi) + b * std::sin(phi)) * std::sin(a);
                sum +=
                    test::CanopySingleScatterBrdf(toLight, w, kLai, kRho, kTau) * w.z * std::sin(a);
            }
        }
        expected += 0.5 * test::kGaussW[g] * sum * (gamma / m) * (2 * kPi / m);
    }
    return {hot.mean[0] / expected, hot.sigma[0] / expected};
}

// The mean measured/turbid ratio over the bins away from the hotspot, checking each within 3%.
double CheckAwayFromHotspot(const Comparison& c, double side) {
    int checked = 0;
    double far = 0;
    for (size_t b = 0; b < c.expected.size(); ++b) {
        const double ratio = c.measured.mean[b] / c.expected[b];
        const double noise = c.measured.sigma[b] / c.expected[b];
        const int band = int(b) / Comparison::kSectors, sector = int(b) % Comparison::kSectors;
        std::printf("side %.2f theta %2.0f-%2.0f |dphi| %3d-%3d: measured/turbid %.4f +- %.4f%s\n",
                    side, Comparison::kEdges[band], Comparison::kEdges[band + 1], sector * 45,
                    sector * 45 + 45, ratio, noise, NearHotspot(b) ? "  (hotspot)" : "");
        if (NearHotspot(b)) continue;
        far += ratio;
        ++checked;
    }
    EXPECT_EQ(checked, 18);
    return far / checked;
}

// Leaves of side 0.01 in a 1 × 1 × 1 canopy of LAI 1: 10,000 leaves, each 1/100 of the depth.
// The finite leaves still raise the once-scattered light everywhere by about u_L·s (leaf area
// density times leaf size: the paths in and out share the leaves near the scattering point):
// measured, +2.2% at s = 0.02 and +1.0% at s = 0.01 (3M paths each), which extrapolates to
// 0 ± 0.5% as s → 0. At 3M paths a bin's noise is 0.6-0.8%.
TEST(CanopyOracle, OnceScatteredMatchesTurbidMediumAwayFromHotspot) {
    const double side = 0.01;
    const Comparison c =
        Compare(int(std::lround(kLai * kTile * kTile / (side * side))), side, 3000000);
    CheckAwayFromHotspot(c, side);
    for (size_t b = 0; b < c.expected.size(); ++b) {
        if (NearHotspot(int(b))) continue;
        // The photon noise must be well under the 3% asked for, or the test proves nothing.
        EXPECT_LT(c.measured.sigma[b] / c.expected[b], 0.01) << b;
        EXPECT_NEAR(c.measured.mean[b] / c.expected[b], 1.0, 0.03) << b;
    }
    // Small leaves: no hotspot above the noise in the 10° cone about backscatter (measured
    // 1.018 ± 0.009 against 1.010 away from it).
    const auto [hot, noise] = HotspotRatio(c.trace, 10 * kDegree);
    std::printf("side %.2f: 10 deg hotspot cone measured/turbid %.3f +- %.3f\n", side, hot, noise);
    EXPECT_LT(hot, 1.05);
}

// The turbid medium has no hotspot; real leaves of side 0.1 (a tenth of the depth) do: the
// once-scattered light in the 10° cone about backscatter rises well above the level of the
// rest of the hemisphere (measured 1.198 ± 0.016 of the oracle there, against 1.061 away from
// the hotspot, 1M paths), and more so in the 5° cone (1.30 ± 0.03).
TEST(CanopyOracle, HotspotAppearsWithLargerLeaves) {
    const double side = 0.1;
    const Comparison c =
        Compare(int(std::lround(kLai * kTile * kTile / (side * side))), side, 1000000);
    const double far = CheckAwayFromHotspot(c, side);
    const auto [hot10, noise10] = HotspotRatio(c.trace, 10 * kDegree);
    const auto [hot5, noise5] = HotspotRatio(c.trace, 5 * kDegree);
    std::printf("side %.2f: hotspot cones 10 deg %.3f +- %.3f, 5 deg %.3f +- %.3f; away %.3f\n",
                side, hot10, noise10, hot5, noise5, far);
    EXPECT_GT(hot10 / far, 1.06);  // 1.13 measured, noise 0.016
    EXPECT_GT(hot5, hot10);        // 0.10 apart, noise 0.035
}

}  // namespace
}  // namespace gonio
