#include "brdfsim/splat_set.h"

#include <algorithm>
#include <cmath>

#include "base/math.h"
#include "brdfsim/hemisphere_grid.h"

namespace gonio {

namespace {

// A photon exactly at grazing exit or (isotropic) exactly at the pole has zero density; these
// floors keep its weight finite without a measurable bias.
constexpr double kMinCosOut = 1e-6;
constexpr double kMinSinIn = 1e-5;

Imath::V3d Direction(double theta, double phi) {
    return Imath::V3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                      std::cos(theta));
}

}  // namespace

SplatSet::SplatSet(const PhotonMap& map, const SplatParams& p) : params(p) {
    if (map.Size() == 0 || map.paths == 0) throw PhotonMapError("the photon map holds no photons");
    if (!(p.radius > 0.0) || p.radius > kPi / 2) {
        throw std::invalid_argument("splat radius (spread) must be in (0, 90] degrees");
    }
    ncomps = map.ncomps;
    paths = map.paths;
    photons = map.Size();
    chordRadius2 = static_cast<float>(std::pow(2.0 * std::sin(0.5 * p.radius), 2));
    invRadius = static_cast<float>(1.0 / p.radius);
    const bool reflect = p.horizon == Horizon::kReflect;
    mass = reflect ? (p.isotropic ? SphereKernelMass3D(p.radius, p.norm)
                                  : SphereKernelMass4D(p.radius, p.norm))
                   : 0.0;
    struct Keyed {
        std::uint64_t key;
        std::size_t row;
    };
    std::vector<Keyed> order;
    order.reserve(map.Size());
    const HemisphereGrid fine(16, 64);
    for (std::size_t i = 0; i < map.Size(); ++i) {
        const float* row = map.Row(i);
        const float* colour = row + kFirstColour;
        if (*std::max_element(colour, colour + ncomps) < p.energyMin) continue;
        const Imath::V3d wIn = Direction(row[kThetaIn], p.isotropic ? 0.0f : row[kPhiIn]);
        const Imath::V3d wOut =
            Direction(row[kThetaOut], row[kPhiOut] - (p.isotropic ? row[kPhiIn] : 0.0f));
        const auto cellIn = static_cast<std::uint64_t>(fine.CellOf(Imath::V3f(wIn)));
        const auto cellOut = static_cast<std::uint64_t>(fine.CellOf(Imath::V3f(wOut)));
        order.push_back({(cellIn << 40) | (cellOut << 20), i});
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
    geometry.reserve(order.size());
    weights.reserve(order.size() * ncomps);
    energies.reserve(order.size() * ncomps);
    for (const Keyed& keyed : order) {
        const float* row = map.Row(keyed.row);
        const float* colour = row + kFirstColour;
        const double thetaI = row[kThetaIn], thetaO = row[kThetaOut];
        const Imath::V3d wIn = Direction(thetaI, row[kPhiIn]);
        // Isotropic maps store ω relative to φ_in: the domain is θ_in × (θ_out, Δφ).
        const Imath::V3d wOut =
            Direction(thetaO, row[kPhiOut] - (p.isotropic ? row[kPhiIn] : 0.0f));
        geometry.push_back({static_cast<float>(wIn.x), static_cast<float>(wIn.y),
                            static_cast<float>(wIn.z), static_cast<float>(thetaI),
                            static_cast<float>(wOut.x), static_cast<float>(wOut.y),
                            static_cast<float>(wOut.z), 0.0f});
        // p_in is per steradian; an isotropic map samples θ' only, with density 2π sin θ' p_in.
        const double pdf = p.isotropic
                               ? row[kProbability] * 2 * kPi * std::max(std::sin(thetaI), kMinSinIn)
                               : row[kProbability];
        const double cosOut = std::max(std::cos(thetaO), kMinCosOut);
        const double photonMass =
            reflect ? mass : InDomainKernelMass(p.radius, p.norm, p.isotropic, thetaI, thetaO);
        for (int c = 0; c < ncomps; ++c) {
            // DESIGN.md: f ≈ 1/N Σ β K / (p_in cos θ_out,k), K of unit mass.
            weights.push_back(static_cast<float>(colour[c] / (paths * pdf * cosOut * photonMass)));
            energies.push_back(static_cast<float>(colour[c] / pdf));
        }
    }
}

int SplatSet::NumImages() const {
    if (params.horizon == Horizon::kRenormalize) return 1;
    return params.isotropic ? 6 : 4;
}

SplatQuery SplatSet::MakeQuery(const Imath::V3f& wIn, const Imath::V3f& wOut) const {
    SplatQuery q;
    const float sinR = static_cast<float>(std::sin(params.radius));
    const bool reflect = params.horizon == Horizon::kReflect;
    Imath::V3f out = wOut;
    float theta = 0.0f;
    if (params.isotropic) {
        theta = std::acos(std::clamp(wIn.z, -1.0f, 1.0f));
        const float s = std::sqrt(wIn.x * wIn.x + wIn.y * wIn.y);
        if (s > 1e-7f) {  // rotate ω by -φ_in: the domain holds Δφ
            const float c = wIn.x / s, sn = wIn.y / s;
            out = Imath::V3f(c * wOut.x + sn * wOut.y, -sn * wOut.x + c * wOut.y, wOut.z);
        }
    }
    const int images = params.isotropic ? 6 : 4;
    for (int v = 0; v < images; ++v) {
        const int first = v >> 1;  // image of the incoming part
        const bool mirrorOut = v & 1;
        Imath::V3f in = wIn, o = out;
        float t = theta;
        bool active = reflect || v == 0;
        if (params.isotropic) {
            if (first == 1) {  // through the pole: θ' → -θ', ω turned by π
                t = -theta;
                o = Imath::V3f(-o.x, -o.y, o.z);
                active = active && theta < params.radius;
            } else if (first == 2) {  // at the horizon: θ' → π - θ'
                t = static_cast<float>(kPi) - theta;
                active = active && theta > kPi / 2 - params.radius;
            }
        } else if (first == 1) {
            in.z = -in.z;
            active = active && wIn.z < sinR;
        }
        if (mirrorOut) {
            o.z = -o.z;
            active = active && out.z < sinR;
        }
        q.inX[v] = in.x, q.inY[v] = in.y, q.inZ[v] = in.z, q.thetaIn[v] = t;
        q.outX[v] = o.x, q.outY[v] = o.y, q.outZ[v] = o.z;
        if (active) q.activeMask |= 1u << v;
    }
    return q;
}

void SplatSet::ImageCentre(std::size_t k, int v, Imath::V3d* in, double* theta,
                           Imath::V3d* out) const {
    const int first = v >> 1;
    const SplatGeometry& g = geometry[k];
    *in = Imath::V3d(g.inX, g.inY, g.inZ);
    *out = Imath::V3d(g.outX, g.outY, g.outZ);
    *theta = g.thetaIn;
    if (params.isotropic) {
        if (first == 1) {
            *theta = -*theta;
            *out = Imath::V3d(-out->x, -out->y, out->z);
        } else if (first == 2) {
            *theta = kPi - *theta;
        }
    } else if (first == 1) {
        in->z = -in->z;
    }
    if (v & 1) out->z = -out->z;
}

std::vector<double> SplatSet::EnergyPerPath() const {
    std::vector<double> sum(ncomps, 0.0);
    for (std::size_t i = 0; i < energies.size(); ++i) sum[i % ncomps] += energies[i];
    for (double& s : sum) s /= static_cast<double>(paths);
    return sum;
}

std::size_t SplatSetBytes(const SplatSet& s) {
    return sizeof(SplatGeometry) * s.geometry.size() +
           sizeof(float) * (s.weights.size() + s.energies.size());
}

}  // namespace gonio
