// brdfsim benchmarks: .pm read speed, opt and iopt on 1M photons, lookups per second of
// BrdfSimple, BrdfGrid / BrdfIsoGrid and the baked table on 300k-photon maps of splat radius 0.5
// (the thesis's brushed-metal case), with the memory of each representation as counters.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "brdfsim/baked_table.h"
#include "brdfsim/brdf_grid.h"
#include "brdfsim/brdf_report.h"
#include "brdfsim/brdf_simple.h"
#include "brdfsim/photon_map.h"
#include "brdfsim/synth.h"

namespace gonio {
namespace {

PhotonMap Synthetic(const char* model, std::uint64_t paths, bool isotropic) {
    SynthOptions options;
    options.paths = paths;
    options.isotropic = isotropic;
    return SynthesizePhotonMap(AnalyticBrdf::Parse(model), options);
}

std::string TempPhotonMap() {
    static const std::string path = [] {
        const std::string p = "/tmp/gonio_bench_" + std::to_string(::getpid()) + ".pm";
        WritePhotonMap(p, Synthetic("phong:0.3,0.7,25", 1000000, false));
        return p;
    }();
    return path;
}

void BM_ReadPhotonMap(benchmark::State& state) {
    const std::string path = TempPhotonMap();
    std::size_t photons = 0;
    for (auto _ : state) {
        const PhotonMap map = ReadPhotonMap(path);
        photons += map.Size();
        benchmark::DoNotOptimize(map.rows.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(photons));
    state.counters["photons/s"] =
        benchmark::Counter(static_cast<double>(photons), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReadPhotonMap)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// opt / iopt from a map in memory: splats (sort, weights) and cell lists, R = 0.3, default grid.
void BM_Opt1M(benchmark::State& state) {
    const bool isotropic = state.range(0);
    const PhotonMap map = Synthetic("phong:0.3,0.7,25", 1000000, isotropic);
    SplatParams params;
    params.radius = 0.3;
    params.isotropic = isotropic;
    int rings, rects;
    DefaultGridFor(params.radius, &rings, &rects);
    std::size_t bytes = 0;
    for (auto _ : state) {
        auto splats = std::make_shared<const SplatSet>(map, params);
        if (isotropic) {
            BrdfIsoGrid grid(splats, rings, rects);
            bytes = grid.MemoryBytes();
        } else {
            BrdfGrid grid(splats, rings, rects);
            bytes = grid.MemoryBytes();
        }
    }
    state.counters["MB"] = bytes / 1e6;
    state.SetLabel(std::string(isotropic ? "iopt" : "opt") + " R=0.3 grid " +
                   std::to_string(rings) + "x" + std::to_string(rects));
}
BENCHMARK(BM_Opt1M)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

struct Representations {
    std::unique_ptr<Brdf> simple, grid, baked;
    std::vector<std::pair<Imath::V3f, Imath::V3f>> queries;
};

// The representations of a map at R = 0.5, and 4096 random direction pairs to look up.
Representations MakeRepresentations(const PhotonMap& map, bool isotropic) {
    Representations r;
    SplatParams params;
    params.radius = 0.5;
    params.isotropic = isotropic;
    auto splats = std::make_shared<const SplatSet>(map, params);
    int rings, rects;
    DefaultGridFor(params.radius, &rings, &rects);
    r.simple = std::make_unique<BrdfSimple>(splats);
    if (isotropic) {
        r.grid = std::make_unique<BrdfIsoGrid>(splats, rings, rects);
    } else {
        r.grid = std::make_unique<BrdfGrid>(splats, rings, rects);
    }
    r.baked = std::make_unique<BakedTable>(*r.grid, 16);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 4096; ++i) {
        auto direction = [&] {
            const float z = 1 - 0.98f * u(rng), phi = 6.2831853f * u(rng);
            const float s = std::sqrt(1 - z * z);
            return Imath::V3f(s * std::cos(phi), s * std::sin(phi), z);
        };
        const Imath::V3f a = direction();
        r.queries.emplace_back(a, direction());
    }
    return r;
}

// 300,000 photons, R = 0.5: the thesis's brushed-metal size, drawn from a Phong lobe over a
// Lambert part, so that splats cover the whole domain.
const Representations& Case(bool isotropic) {
    static std::map<bool, Representations> cases;
    Representations& r = cases[isotropic];
    if (!r.simple)
        r = MakeRepresentations(Synthetic("phong:0.5,0.5,10", 300000, isotropic), isotropic);
    return r;
}

// The thesis's brushed-metal case itself (Table 4.1: 300,000 photons, R = 0.5, anisotropic):
// the photon map of ribs/brushed_metal.rib, which bench/brdfsim/run_brushed_metal.sh renders
// and names in GONIO_BRUSHED_METAL_PM. Null without it.
const Representations* BrushedMetalCase() {
    static const std::unique_ptr<Representations> r = []() -> std::unique_ptr<Representations> {
        const char* path = std::getenv("GONIO_BRUSHED_METAL_PM");
        if (!path) return nullptr;
        return std::make_unique<Representations>(MakeRepresentations(ReadPhotonMap(path), false));
    }();
    return r.get();
}

void Lookups(benchmark::State& state, const Brdf& brdf, const Representations& r) {
    float f[3];
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& [a, b] = r.queries[i++ & 4095];
        brdf.Eval(a, b, f);
        benchmark::DoNotOptimize(f[0]);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
    state.counters["MB"] = brdf.MemoryBytes() / 1e6;
}

void BM_LookupSimple(benchmark::State& state) {
    const Representations& r = Case(state.range(0));
    Lookups(state, *r.simple, r);
}
void BM_LookupGrid(benchmark::State& state) {
    const Representations& r = Case(state.range(0));
    Lookups(state, *r.grid, r);
}
void BM_LookupBaked(benchmark::State& state) {
    const Representations& r = Case(state.range(0));
    Lookups(state, *r.baked, r);
}
void BM_LookupBrushedMetal(benchmark::State& state) {
    const Representations* r = BrushedMetalCase();
    if (!r) {
        state.SkipWithError("set GONIO_BRUSHED_METAL_PM (bench/brdfsim/run_brushed_metal.sh)");
        return;
    }
    const Brdf* representations[] = {r->simple.get(), r->grid.get(), r->baked.get()};
    Lookups(state, *representations[state.range(0)], *r);
    state.SetLabel(state.range(0) == 0 ? "simple" : state.range(0) == 1 ? "grid" : "baked");
}
BENCHMARK(BM_LookupBrushedMetal)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

BENCHMARK(BM_LookupSimple)->ArgName("iso")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LookupGrid)->ArgName("iso")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LookupBaked)->ArgName("iso")->Arg(0)->Arg(1)->Unit(benchmark::kNanosecond);

}  // namespace
}  // namespace gonio

BENCHMARK_MAIN();
