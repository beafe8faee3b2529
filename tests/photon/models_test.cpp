// The thesis's micro-geometry models (ribs/): the qualitative results of chapter 5 and the
// reciprocity of the simulated BRDFs, measured on binned photon energies (no splats, so these
// test the tracer alone).
#include <algorithm>

#include "photon_test_util.h"

namespace gonio {
namespace {

// A set of directions: a θ band and a φ interval (degrees; the interval may wrap past 360).
struct Cell {
    double theta0, theta1, phi0, phi1;

    bool Contains(double theta, double phi) const {
        if (theta < theta0 * kDegree || theta >= theta1 * kDegree) return false;
        double d = phi / kDegree - phi0;
        d -= 360 * std::floor(d / 360);
        return d < phi1 - phi0;
    }
    // ∫ cos θ dω over the cell.
    double ProjectedSolidAngle() const {
        return (phi1 - phi0) * kDegree *
               (std::pow(std::sin(theta1 * kDegree), 2) - std::pow(std::sin(theta0 * kDegree), 2)) /
               2;
    }
};

PhotonTraceSettings IncidenceBand(double thetaMinDeg, double thetaMaxDeg, uint64_t paths,
                                  bool averageAzimuth) {
    PhotonTraceSettings s;
    s.paths = paths;
    s.isotropic = true;
    s.averageAzimuth = averageAzimuth;
    s.thetaMin = float(thetaMinDeg * kDegree);
    s.thetaMax = float(thetaMaxDeg * kDegree);
    return s;
}

// The BRDF averaged over an outgoing cell, from a run with a narrow incidence band and φ′ = 0:
// E[β 1_cell] / ∫_cell cos θ dω, with its standard error.
struct Estimate {
    double value = 0, sigma = 0;
};

Estimate CellBrdf(const PhotonTraceResult& r, const Cell& cell, int component = 0) {
    const auto e = test::Bin(
        r, 1,
        [&](const float* row) { return cell.Contains(row[kThetaOut], row[kPhiOut]) ? 0 : -1; },
        [&](const float* row) { return double(row[kFirstColour + component]); });
    const double omega = cell.ProjectedSolidAngle();
    return {e.mean[0] / omega, e.sigma[0] / omega};
}

// F(A→B) = ∫_A ∫_B f cos θ′ cos θ dω′ dω, from one run: (1/N) Σ β cos θ′ / p_in over the
// photons with ω′ in A and ω in B. Reciprocity says F(A→B) = F(B→A).
Estimate Exchange(const PhotonTraceResult& r, const Cell& a, const Cell& b) {
    const auto e = test::Bin(
        r, 1,
        [&](const float* row) {
            return a.Contains(row[kThetaIn], row[kPhiIn]) &&
                           b.Contains(row[kThetaOut], row[kPhiOut])
                       ? 0
                       : -1;
        },
        [](const float* row) {
            return row[kFirstColour] * std::cos(row[kThetaIn]) / row[kProbability];
        });
    return {e.mean[0], e.sigma[0]};
}

// Brushed metal lit across the cylinders (φ′ = 0): the two ends of the cross section at θ = 45°
// (thesis figs. 5.5 and 5.6), towards the light (φ = 0) and on the mirror side (φ = 180°).
double MirrorSideOverLightSide(const std::string& rib, double thetaInDeg) {
    const auto r = test::TraceRib(
        rib, IncidenceBand(std::max(0.0, thetaInDeg - 2), thetaInDeg + 2, 100000, false));
    const Estimate lightSide = CellBrdf(r, {40, 50, -10, 10});
    const Estimate mirrorSide = CellBrdf(r, {40, 50, 170, 190});
    std::printf(
        "brushed metal theta_in %2.0f, theta_out 45: light side %.3f +- %.3f, mirror "
        "side %.3f +- %.3f\n",
        thetaInDeg, lightSide.value, lightSide.sigma, mirrorSide.value, mirrorSide.sigma);
    return mirrorSide.value / std::max(lightSide.value, 1e-3 * mirrorSide.value);
}

// The shape of figs. 5.5-5.7: one end of the cut far above the other, the more so the lower the
// light, the same at normal incidence. The larger end is the mirror side: facets tilted by at
// most ±30° cannot send light from 45° back to 45° on its own side in one bounce (the
// Poulin-Fournier test above checks that geometry exactly), so the thesis's label "backward" for
// the larger peak must count φ from the direction the light travels (docs/brdflight.md).
TEST(BrushedMetal, CrossSectionAsymmetryGrowsWithIncidence) {
    const std::string rib = test::ReadRib("brushed_metal.rib");
    const double r0 = MirrorSideOverLightSide(rib, 2);
    const double r30 = MirrorSideOverLightSide(rib, 30);
    const double r45 = MirrorSideOverLightSide(rib, 45);
    const double r70 = MirrorSideOverLightSide(rib, 70);
    EXPECT_NEAR(r0, 1.0, 0.1);
    EXPECT_GT(r30, 3.0);
    EXPECT_GT(r45, 2 * r30);
    EXPECT_GT(r70, r45);
}

TEST(BrushedMetal, Reciprocity) {
    PhotonTraceSettings s;
    s.paths = 300000;
    const auto r = test::TraceRib(test::ReadRib("brushed_metal.rib"), s);
    const Cell pairs[][2] = {
        {{20, 40, -30, 30}, {50, 70, 150, 210}},   // across the cylinders
        {{20, 40, 60, 120}, {50, 70, 240, 300}},   // along them
        {{25, 45, 20, 70}, {45, 65, 190, 250}},    // diagonal
        {{30, 50, -30, 30}, {30, 50, 150, 210}}};  // symmetric positions, different cells
    for (const auto& pair : pairs) {
        const Estimate ab = Exchange(r, pair[0], pair[1]), ba = Exchange(r, pair[1], pair[0]);
        const double sigma = std::hypot(ab.sigma, ba.sigma);
        std::printf("brushed metal F(A->B) %.5f +- %.5f, F(B->A) %.5f +- %.5f\n", ab.value,
                    ab.sigma, ba.value, ba.sigma);
        EXPECT_GT(ab.value, 10 * ab.sigma);
        EXPECT_LT(std::abs(ab.value - ba.value), 3.5 * sigma);
    }
}

// The grass BRDF at light θ′ on the ring θ_out (twelve 30° sectors of Δφ).
std::vector<Estimate> GrassRing(const PhotonTraceResult& r, double theta0, double theta1) {
    std::vector<Estimate> ring;
    for (int k = 0; k < 12; ++k)
        ring.push_back(CellBrdf(r, {theta0, theta1, k * 30.0 - 15, k * 30.0 + 15}));
    return ring;
}

// The ring folded over Δφ ↔ −Δφ (the BRDF is isotropic): 7 values for Δφ = 0, 30, ..., 180°.
std::vector<double> FoldedRing(const PhotonTraceResult& r, double theta0, double theta1,
                               std::vector<double>* sigma = nullptr) {
    const auto ring = GrassRing(r, theta0, theta1);
    std::vector<double> folded;
    for (int k = 0; k <= 6; ++k) {
        const Estimate &a = ring[k], &b = ring[(12 - k) % 12];
        folded.push_back((a.value + b.value) / 2);
        if (sigma) sigma->push_back(std::hypot(a.sigma, b.sigma) / 2);
    }
    std::printf("grass ring theta_out %2.0f-%2.0f, dphi 0..180:", theta0, theta1);
    for (double v : folded) std::printf(" %.4f", v);
    std::printf("\n");
    return folded;
}

// Thesis fig. 5.16: a backward and a forward peak with the minimum in between, and more light
// towards grazing exits.
TEST(Grass, BackwardAndForwardPeaksRisingTowardsGrazing) {
    const std::string rib = test::ReadRib("grass.rib");
    const auto at45 = test::TraceRib(rib, IncidenceBand(43, 47, 200000, true));
    // The forward peak (Δφ = 180°) shows on the 60° ring, near the blades' specular direction,
    // the backward one (Δφ = 0) towards grazing exits; each stands at least 3σ above the
    // ring's minimum, which lies between 60° and 150°.
    const double ringTheta[2] = {55, 75};
    const int peak[2] = {6, 0};
    for (int i = 0; i < 2; ++i) {
        std::vector<double> sigma;
        const auto ring = FoldedRing(at45, ringTheta[i], ringTheta[i] + 10, &sigma);
        const int lowest = int(std::min_element(ring.begin(), ring.end()) - ring.begin());
        EXPECT_GE(lowest, 2);
        EXPECT_LE(lowest, 5);
        EXPECT_EQ(std::max_element(ring.begin(), ring.end()) - ring.begin(), peak[i]);
        EXPECT_GT(ring[peak[i]] - ring[lowest], 3 * std::hypot(sigma[peak[i]], sigma[lowest]));
    }

    const auto at70 = test::TraceRib(rib, IncidenceBand(68, 72, 200000, true));
    const auto low = FoldedRing(at70, 55, 65), mid = FoldedRing(at70, 65, 75),
               grazing = FoldedRing(at70, 75, 85);
    EXPECT_GT(mid[0], 1.2 * low[0]);
    EXPECT_GT(grazing[0], 1.2 * mid[0]);
    EXPECT_GT(grazing[0], 2 * *std::min_element(grazing.begin(), grazing.end()));
}

// Thesis fig. 5.19: (kd, ks) = (0.5, 0.5) against (0.3, 0.7) at θ′ = 60°, θ = 80°. Shadowing
// and multiple scattering average the blades' lobes out: the level changes a little and the
// shape hardly at all.
TEST(Grass, MicroBrdfChangesTheBrdfOnlyALittle) {
    const auto settings = IncidenceBand(58, 62, 200000, true);
    const auto a = test::TraceRib(test::ReadRib("grass_microbrdf_a.rib"), settings);
    const auto b = test::TraceRib(test::ReadRib("grass_microbrdf_b.rib"), settings);
    const auto ringA = FoldedRing(a, 75, 85), ringB = FoldedRing(b, 75, 85);
    double meanA = 0, meanB = 0;
    for (int k = 0; k <= 6; ++k) meanA += ringA[k] / 7, meanB += ringB[k] / 7;
    double worstShape = 0;
    for (int k = 0; k <= 6; ++k)
        worstShape = std::max(worstShape, std::abs(ringB[k] / meanB / (ringA[k] / meanA) - 1));
    std::printf("grass micro BRDF: level ratio %.3f, worst shape change %.3f\n", meanB / meanA,
                worstShape);
    EXPECT_NEAR(meanB / meanA, 1.0, 0.2);
    EXPECT_LT(worstShape, 0.15);
}

// On the periodic tile the sampling area is the whole tile, so illuminating it and collecting
// everything is the same experiment both ways round and reciprocity holds exactly (an open tile
// lit on a small area of a few blades is only reciprocal on average over blade layouts).
TEST(Grass, Reciprocity) {
    const std::string rib = test::ReadRib("grass_periodic.rib");
    auto band = [](double t0, double t1) {
        auto s = IncidenceBand(t0, t1, 150000, true);
        s.periodic = true;
        s.area = 0.5f;
        return s;
    };
    const auto runA = test::TraceRib(rib, band(35, 45));
    const auto runB = test::TraceRib(rib, band(65, 75));
    const Cell a{35, 45, 0, 360}, b{65, 75, 0, 360};
    for (double sector : {0.0, 90.0, 180.0}) {
        // |Δφ| within 30° of `sector`: symmetric in Δφ, as exchanging ω′ and ω flips its sign.
        const Cell bOut{65, 75, sector - 30, sector + 30}, aOut{35, 45, sector - 30, sector + 30};
        const Estimate ab = Exchange(runA, a, bOut), ba = Exchange(runB, b, aOut);
        const double sigma = std::hypot(ab.sigma, ba.sigma);
        std::printf("grass dphi %3.0f: F(A->B) %.5f +- %.5f, F(B->A) %.5f +- %.5f\n", sector,
                    ab.value, ab.sigma, ba.value, ba.sigma);
        EXPECT_GT(ab.value, 10 * ab.sigma);
        EXPECT_LT(std::abs(ab.value - ba.value), 3.5 * sigma);
    }
}

// Thesis figs. 5.20-5.21: blades lean towards +y. With the light on that side (φ′ ≈ 90°) it
// sees their backs and little comes back; from the other side the upright faces scatter back.
TEST(Grass, MowedGrassBackscattersAgainstTheLean) {
    PhotonTraceSettings s;
    s.paths = 300000;
    const auto r = test::TraceRib(test::ReadRib("grass_mowed.rib"), s);
    const Cell leanSide{40, 55, 65, 115}, otherSide{40, 55, 245, 295};
    const Estimate lightOnLeanSide = Exchange(r, leanSide, leanSide);
    const Estimate lightOnOtherSide = Exchange(r, otherSide, otherSide);
    std::printf(
        "mowed grass backscatter: light on the lean side %.5f +- %.5f, on the other "
        "side %.5f +- %.5f\n",
        lightOnLeanSide.value, lightOnLeanSide.sigma, lightOnOtherSide.value,
        lightOnOtherSide.sigma);
    EXPECT_GT(lightOnOtherSide.value, 2 * lightOnLeanSide.value);
}

}  // namespace
}  // namespace gonio
