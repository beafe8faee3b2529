#include "brdfsim/brdf_report.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "base/math.h"

namespace gonio {

namespace {}  // namespace

PhotonMapSummary SummarizePhotonMap(const std::string& path) {
    PhotonMapReader reader(path);
    PhotonMapSummary s;
    s.photons = reader.Header().count;
    s.paths = reader.Header().paths;
    std::vector<float> rows;
    while (true) {
        rows.clear();
        const bool more = reader.ReadBatch(1 << 18, rows);
        s.ncomps = reader.NumComponents();
        if (s.energyPerPath.empty() && s.ncomps) s.energyPerPath.assign(s.ncomps, 0.0);
        const int stride = kFirstColour + s.ncomps;
        for (std::size_t i = 0; s.ncomps && i + stride <= rows.size(); i += stride) {
            const float* row = &rows[i];
            s.allPhiInZero = s.allPhiInZero && row[kPhiIn] == 0.0f;
            s.thetaInMin = std::min<double>(s.thetaInMin, row[kThetaIn]);
            s.thetaInMax = std::max<double>(s.thetaInMax, row[kThetaIn]);
            for (int c = 0; c < s.ncomps; ++c) {
                s.energyPerPath[c] += row[kFirstColour + c] / row[kProbability];
            }
        }
        if (!more) break;
    }
    for (double& e : s.energyPerPath) e /= std::max<std::uint64_t>(s.paths, 1);
    return s;
}

void PrintPhotonMapInfo(const std::string& path, const PhotonMapSummary& s, std::FILE* out) {
    std::fprintf(out, "photon map      %s\n", path.c_str());
    std::fprintf(out, "photons         %llu written, %llu traced paths (%.2f%% escaped upwards)\n",
                 static_cast<unsigned long long>(s.photons),
                 static_cast<unsigned long long>(s.paths),
                 s.paths ? 100.0 * s.photons / s.paths : 0.0);
    std::fprintf(out, "components      %d\n", s.ncomps);
    std::fprintf(
        out, "kind            %s\n",
        s.allPhiInZero ? "isotropic (phi_in = 0: use brdf iopt)" : "anisotropic (use brdf opt)");
    if (s.photons) {
        std::fprintf(out, "theta_in range  %.2f .. %.2f deg\n", s.thetaInMin / kDegree,
                     s.thetaInMax / kDegree);
    }
    // Anisotropic: (1/N) Σ β/p_in = ∫ albedo dω' over 2π sr. Isotropic maps give p_in of the
    // rotation-symmetric distribution (docs/formats.md), so the same holds.
    std::fprintf(out, "mean albedo     ");
    for (double e : s.energyPerPath) std::fprintf(out, " %.4f", e / (2 * kPi));
    std::fprintf(out, "   (escaped energy per path / 2pi)\n");
}

std::vector<double> PhotonEnergyAt(const SplatSet& s, const Imath::V3f& wIn) {
    std::vector<double> energy(s.ncomps, 0.0);
    const SplatQuery q = s.MakeQuery(wIn, Imath::V3f(0, 0, 1));
    const double radius = s.params.radius;
    for (std::size_t k = 0; k < s.Size(); ++k) {
        const SplatGeometry& g = s.geometry[k];
        double m = 0.0;
        for (int v = 0; v < s.NumImages(); v += 2) {  // incoming images only
            if (!(q.activeMask & (1u << v))) continue;
            double d;
            if (s.params.isotropic) {
                d = std::abs(q.thetaIn[v] - g.thetaIn);
            } else {
                const double dot = q.inX[v] * g.inX + q.inY[v] * g.inY + q.inZ[v] * g.inZ;
                d = std::acos(std::clamp(dot, -1.0, 1.0));
            }
            m += KernelOutMarginal(radius, s.params.norm, d);
        }
        if (m == 0.0) continue;
        // weights hold β / (N p cos θ_out mass); the cos comes back here.
        const double cosOut = std::max<double>(g.outZ, 1e-6);
        for (int c = 0; c < s.ncomps; ++c) energy[c] += s.weights[k * s.ncomps + c] * cosOut * m;
    }
    return energy;
}

double ReciprocityError(const Brdf& brdf, int pairs) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> ab(brdf.NumComponents()), ba(brdf.NumComponents());
    double diff = 0.0, sum = 0.0;
    const double cosMax = std::cos(80 * kDegree);
    for (int i = 0; i < pairs; ++i) {
        const double ta = std::acos(1 - u(rng) * (1 - cosMax)), pa = 2 * kPi * u(rng);
        const double tb = std::acos(1 - u(rng) * (1 - cosMax)), pb = 2 * kPi * u(rng);
        brdf.EvalAngles(ta, pa, tb, pb, ab.data());
        brdf.EvalAngles(tb, pb, ta, pa, ba.data());
        diff += std::abs(ab[0] - ba[0]);
        sum += 0.5 * (ab[0] + ba[0]);
    }
    return sum > 0 ? diff / sum : 0.0;
}

void PrintGrdInfo(const std::string& path, const GrdFile& file, std::FILE* out) {
    const SplatSet& s = *file.splats;
    std::fprintf(out, "grid            %s\n", path.c_str());
    std::fprintf(
        out, "kind            %s\n",
        file.IsIsotropic() ? "isotropic (theta_in x (theta_out, dphi))" : "anisotropic (4D)");
    std::fprintf(out, "photons         %llu splats of %llu photons, %llu traced paths\n",
                 static_cast<unsigned long long>(s.Size()),
                 static_cast<unsigned long long>(s.photons),
                 static_cast<unsigned long long>(s.paths));
    std::fprintf(out, "splat radius    %.4f rad (%.2f deg), norm %s, horizon %s\n", s.params.radius,
                 s.params.radius / kDegree, NormName(s.params.norm), HorizonName(s.params.horizon));
    std::fprintf(out, "energy_min      %g\n", s.params.energyMin);
    std::fprintf(out, "kernel mass     %.6g (on the sphere)\n", s.mass);
    const GridStats stats = ComputeGridStats(file.Lists(), s.Size());
    std::fprintf(out, "subdivision     %d rings, %d rects max: %zu cells\n", file.rings, file.rects,
                 stats.cells);
    std::fprintf(out, "splats per cell average %.1f, max %zu, ratio %.4f (thesis Table 4.1)\n",
                 stats.averageSplats, stats.maxSplats, stats.ratio);
    std::fprintf(out, "memory          splats %.1f MB, cell lists %.1f MB", SplatSetBytes(s) / 1e6,
                 file.Lists().Bytes() / 1e6);
    if (file.baked) {
        const auto& d = file.baked->Dims();
        std::fprintf(out, ", baked table %dx%dx%dx%d %.1f MB", d[0], d[1], d[2], d[3],
                     file.baked->MemoryBytes() / 1e6);
    }
    std::fprintf(out, "\n");
    const std::vector<double> energy = s.EnergyPerPath();
    const double measure = file.IsIsotropic() ? 0.5 * kPi : 2 * kPi;
    std::fprintf(out, "mean albedo     %.4f (photons: escaped energy per path / %s)\n",
                 energy[0] / measure, file.IsIsotropic() ? "(pi/2)" : "2pi");
    std::fprintf(out, "albedo          ");
    for (double theta : {0.0, 30.0, 60.0, 80.0}) {
        const auto a = Albedo(*file.grid, DirectionFromAngles(theta * kDegree, 0.0), 32);
        std::fprintf(out, " %g deg: %.4f ", theta, a[0]);
    }
    std::fprintf(out, " (integral of f cos over the outgoing hemisphere)\n");
    std::fprintf(out, "reciprocity     %.2f%% mean |f(a->b) - f(b->a)| / f over 200 pairs\n",
                 100 * ReciprocityError(*file.grid, 200));
}

void DefaultGridFor(double radius, int* rings, int* rects) {
    *rings = std::clamp(static_cast<int>(std::lround(0.5 * kPi / radius)), 2, 24);
    *rects = 4 * *rings;
}

}  // namespace gonio
