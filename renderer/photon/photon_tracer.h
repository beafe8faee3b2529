#pragma once
// The BRDFLight photon tracer (thesis §3.3 and Appendix C.5, radiometry of DESIGN.md): collimated
// beams over the w×w sampling area at z=0 meet the micro geometry, scatter by its micro BRDF
// until they escape, and every photon escaping upwards becomes one photon-map row
//   θ_in φ_in θ_out φ_out p_in β_1..β_ncomps
// with β = Π f_m cos θ_o / pdf over the bounces and p_in the pdf per steradian of ω′ (the
// estimator of brdfsim divides by it). Paths run in parallel batches with counter-based random
// numbers: the same rows, in the same order, whatever the thread count.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "base/math.h"
#include "renderer/photon/micro_brdf.h"
#include "renderer/raytrace/ray_scene.h"
#include "renderer/scene/frame.h"

namespace gonio {

constexpr int kMaxBounceTag = 65535;

struct PhotonTraceSettings {
    uint64_t paths = 100000;
    // The index of the first path: a run traces paths [firstPath, firstPath + paths). Each
    // path's random numbers depend only on the seed and its index, so runs over adjacent
    // ranges (the shards of a farm job) never share a path, and their maps joined in order
    // are the rows of one run over the whole range.
    uint64_t firstPath = 0;
    float area = 0.1f;
    bool isotropic = false;
    // For isotropic runs: draw the light's azimuth uniformly and store every photon turned by
    // −φ′ (φ_in = 0, φ_out relative to the light), which averages a finite, not quite
    // isotropic patch (a few blades of grass) over all azimuths; without it the light comes
    // from φ′ = 0 as in the thesis and the map is one azimuth of the patch.
    bool averageAzimuth = false;
    uint64_t seed = 0;
    int maxDepth = 100;
    bool periodic = false;
    float thetaMin = 0, thetaMax = kHalfPiF;  // radians
    bool progress = false;
};

struct PhotonStats {
    uint64_t paths = 0;
    uint64_t escapedUp = 0;        // written to the map
    uint64_t escapedDown = 0;      // left below the horizon: dropped, counted
    uint64_t missed = 0;           // the beam line met no geometry
    uint64_t bounceLimit = 0;      // still inside after maxdepth bounces (or wrapping forever)
    uint64_t absorbed = 0;         // scattered into the surface (the Phong lobe below the horizon)
    uint64_t bounces = 0;          // surface hits over all paths
    std::vector<double> energyUp;  // Σ β of the escaped photons, per component
    std::vector<double> energyDown;  // Σ β of the photons that left below the horizon
    double seconds = 0;
    int threads = 1;

    uint64_t Lost() const { return missed + bounceLimit; }
};

struct PhotonTraceResult {
    int ncomps = 3;
    std::vector<float> rows;  // 5 + ncomps floats per photon, in path order
    // Per photon (row): the surface hits of its path, 1 for once scattered (capped at
    // kMaxBounceTag); the photon map's bounce column (docs/formats.md).
    std::vector<uint16_t> bounces;
    PhotonStats stats;
};

// The micro BRDF of every shape of the frame (top level and object definitions), from the
// surface shaders found on the frame's shader search path (micro_brdf.h).
using MicroBrdfTable = std::unordered_map<const SceneShape*, MicroBrdf>;
MicroBrdfTable BuildMicroBrdfTable(const Frame& frame, Diagnostics& diagnostics);

// The memory TracePhotons holds at most: every path's photon row and bounce tag, for `paths` paths
// of `ncomps` colour components (it keeps the rows in path order, so that a seed gives one map
// whatever the thread count).
double PhotonTraceBytes(uint64_t paths, int ncomps);

PhotonTraceResult TracePhotons(const Frame& frame, const RayScene& scene,
                               const MicroBrdfTable& brdfs, const PhotonTraceSettings& settings);

}  // namespace gonio
