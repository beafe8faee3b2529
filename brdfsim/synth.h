#pragma once
// Synthetic photon maps drawn straight from an analytic BRDF, with the photon tracer's radiometry
// (DESIGN.md): incident directions uniform over the hemisphere (p_in = 1/2π; isotropic maps fix
// φ_in = 0 and draw cos θ_in uniformly), outgoing directions importance-sampled, β = f cos θ / pdf,
// photons leaving below the horizon counted as paths but not written.

#include <cstdint>
#include <functional>
#include <string>

#include "analytic_brdf.h"
#include "photon_map.h"

namespace gonio {

struct SynthOptions {
    std::uint64_t paths = 100000;
    std::uint64_t seed = 1;
    bool isotropic = false;
    // Randomly shifted low-discrepancy points (Roberts' R-sequence) instead of independent
    // random numbers: the same distribution with far less noise, for sharp tests of the estimator.
    bool stratified = false;
    int ncomps = 3;
};

PhotonMap SynthesizePhotonMap(const AnalyticBrdf& brdf, const SynthOptions& options);
// Streams to `path` (temporary name, then rename); returns the header written.
PhotonMapHeader WriteSyntheticPhotonMap(const AnalyticBrdf& brdf, const SynthOptions& options,
                                        const std::string& path);

}  // namespace gonio
