#pragma once
// Synthetic photon maps drawn straight from an analytic BRDF, with the photon tracer's radiometry
// (DESIGN.md): incident directions uniform over the hemisphere (p_in = 1/2π), β = f cos θ / pdf,
// photons leaving below the horizon counted as paths but not written. Two choices keep every
// photon's weight β / (p_in cos θ_out) bounded, so maps of a million photons are not dominated by
// a few grazing ones: isotropic maps (φ_in = 0) draw θ_in uniformly in [0, π/2], the natural
// measure of their domain, and exit directions come from a defensive mixture (half uniform over
// the hemisphere, half the BRDF's importance sampling). With pure BRDF sampling, as a tracer
// does, the weights of a Lambertian map grow like 1/cos θ_out at grazing exits.

#include <cstdint>
#include <functional>
#include <string>

#include "brdfsim/analytic_brdf.h"
#include "brdfsim/photon_map.h"

namespace gonio {

struct SynthOptions {
    std::uint64_t paths = 100000;
    std::uint64_t seed = 1;
    bool isotropic = false;
    // Randomly shifted low-discrepancy points (Roberts' R-sequence) instead of independent
    // random numbers: the same distribution with far less noise, for sharp tests of the estimator.
    bool stratified = false;
    int ncomps = 3;
    bool defensive = true;  // false: exits from the BRDF's importance sampling alone
};

PhotonMap SynthesizePhotonMap(const AnalyticBrdf& brdf, const SynthOptions& options);
// Streams to `path` (temporary name, then rename); returns the header written.
PhotonMapHeader WriteSyntheticPhotonMap(const AnalyticBrdf& brdf, const SynthOptions& options,
                                        const std::string& path);

}  // namespace gonio
