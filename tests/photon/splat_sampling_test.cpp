// Splat sampling (brdfsim/splat_sampler.h) on grids made from photon maps the BRDFLight tracer
// writes, not drawn from a formula: a plastic plane (normalised Phong, kd 0.4, ks 0.6,
// exponent 10) and a matte box open at the top (interreflection, a lobe no formula gives). The
// same χ² test and checks as tests/brdfsim/splat_sampler_test.cpp, Bonferroni over this file.
#include "../brdfsim/sampler_chi_square.h"
#include "brdfsim/brdf_grid.h"
#include "photon_test_util.h"

namespace gonio {
namespace {

constexpr int kTests = 3;  // the χ² tests of this file

std::shared_ptr<SplatSet> TracedSplats(const std::string& body, uint64_t paths) {
    PhotonTraceSettings settings;
    settings.paths = paths;
    settings.seed = 3;
    const PhotonMap map = test::ToPhotonMap(test::TraceRib(test::World(body), settings));
    SplatParams params;
    params.radius = 0.3;
    return std::make_shared<SplatSet>(map, params);
}

TEST(SplatSampling, TracedPlasticPlane) {
    auto splats = TracedSplats(
        "Surface \"plastic\" \"Kd\" 0.4 \"Ks\" 0.6 \"roughness\" 0.1\n" + test::Square(1), 20000);
    const BrdfGrid grid(splats, 4, 9);
    test::CheckSampler(splats, grid, 35, 0.4, kTests);
    test::CheckSampler(splats, grid, 75, 2.5, kTests);
}

TEST(SplatSampling, TracedOpenBox) {
    // A floor and four walls of height 0.5 around it: light reflected between them.
    auto splats = TracedSplats("Surface \"matte\" \"Kd\" 0.8\n" + test::Square(1) +
                                   "\nPolygon \"P\" [-1 -1 0  1 -1 0  1 -1 0.5  -1 -1 0.5]"
                                   "\nPolygon \"P\" [-1 1 0  1 1 0  1 1 0.5  -1 1 0.5]"
                                   "\nPolygon \"P\" [-1 -1 0  -1 1 0  -1 1 0.5  -1 -1 0.5]"
                                   "\nPolygon \"P\" [1 -1 0  1 1 0  1 1 0.5  1 -1 0.5]",
                               20000);
    const BrdfGrid grid(splats, 4, 9);
    test::CheckSampler(splats, grid, 50, 1.0, kTests);
}

}  // namespace
}  // namespace gonio
