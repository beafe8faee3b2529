// The cost of brdf() inside a shader (issue 6): the same light loop over one distant light with
// diffuse(), with brdf() on a .grd that has a baked table, and with brdf() on a .grd without
// one (every lookup sums the splats of its cell), over one batch of 256 points, as the renderer
// shades them. The grids are a Phong BRDF (kd 0.5, ks 0.5, exponent 10) synthesised with 100,000
// photons, splat radius 0.3, iopt 6 24 — the size of a demo grid.

#include <Imath/ImathVec.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "brdfsim/analytic_brdf.h"
#include "brdfsim/baked_table.h"
#include "brdfsim/brdf_grid.h"
#include "brdfsim/grd_cache.h"
#include "brdfsim/grd_file.h"
#include "brdfsim/synth.h"
#include "shaderlang/shading_system.h"
#include "shaderlang/simple_context.h"

namespace gonio {
namespace {

constexpr int kPoints = 256;

// Writes phong.grd (baked) and phong_grid.grd (grid only) once, into a scratch folder.
const std::string& GridFolder() {
    static const std::string folder = [] {
        const std::string dir =
            (std::filesystem::temp_directory_path() / "gonio_brdf_call_bench").string();
        std::filesystem::create_directories(dir);
        SynthOptions options;
        options.paths = 100000;
        options.isotropic = true;
        const PhotonMap map = SynthesizePhotonMap(AnalyticBrdf::Parse("phong:0.5,0.5,10"), options);
        SplatParams params;
        params.radius = 0.3;
        params.isotropic = true;
        auto splats = std::make_shared<const SplatSet>(map, params);
        const BrdfIsoGrid grid(splats, 6, 24);
        const BakedTable baked(grid, 16);
        WriteGrd(dir + "/phong.grd", *splats, 6, 24, grid.Lists(), &baked);
        WriteGrd(dir + "/phong_grid.grd", *splats, 6, 24, grid.Lists(), nullptr);
        return dir;
    }();
    return folder;
}

// A surface over one light: `body` computes the colour C from Nf, V (and L inside illuminance).
std::string SurfaceSource(const std::string& body) {
    return "surface s(string grid = \"\") {\n"
           "    normal Nf = faceforward(normalize(N), I);\n"
           "    vector V = -normalize(I);\n"
           "    color C = 0;\n" +
           body + "\n    Ci = C;\n}\n";
}

const char* const kBrdfBody =
    "illuminance (P, Nf, PI / 2) {\n"
    "    vector Ln = normalize(L);\n"
    "    C += Cl * brdf(grid, Nf, V, Ln, dPdu) * (Nf . Ln);\n"
    "}";

// A scene-less context that reads .grd files the way the renderer's does (NamedTextures):
// through a cache, evaluated plane by plane.
class BrdfContext : public sl::SimpleShadingContext {
  public:
    using SimpleShadingContext::SimpleShadingContext;

    bool MeasuredBrdf(const std::string& name, int count, const float* wIn, const float* wOut,
                      const uint8_t* active, float* out) override {
        std::string error;
        const std::shared_ptr<const GrdFile> file = cache_.Get(name, &error);
        if (!file) {
            std::fprintf(stderr, "brdf_call_bench: %s: %s\n", name.c_str(), error.c_str());
            std::exit(1);
        }
        EvalPlanes(file->Fastest(), ColorComponents(), count, wIn, wOut, active, out);
        return true;
    }

  private:
    GrdCache cache_;
};

// One surface shader and a distant light over a batch of points on a sphere's front.
class Shading {
  public:
    Shading(const std::string& body, const std::string& grid) : context_(diagnostics_) {
        auto shader = sl::CompileShaderSource(SurfaceSource(body), "bench.sl", {}, diagnostics_);
        auto light = sl::CompileShaderSource("light l() { solar(vector(1, 1, -1), 0) { Cl = 1; } }",
                                             "light.sl", {}, diagnostics_);
        if (!shader || !light) {
            std::fprintf(stderr, "brdf_call_bench: the shaders do not compile\n");
            std::exit(1);
        }
        surface_ = std::make_unique<sl::ShaderInstance>(shader);
        std::string error;
        if (!grid.empty() && !surface_->SetParameter("grid", {GridFolder() + "/" + grid}, &error)) {
            std::fprintf(stderr, "brdf_call_bench: %s\n", error.c_str());
            std::exit(1);
        }
        surface_->Specialize();
        auto lightInstance = std::make_shared<sl::ShaderInstance>(light);
        lightInstance->Specialize();
        context_.AddLight(lightInstance);
        MakeBatch();
    }

    void Run() {
        context_.BeginBatch(globals_, 3);
        executor_.Run(*surface_, globals_, context_);
    }

  private:
    void MakeBatch() {
        const int n = kPoints;
        P_.resize(3 * n), N_.resize(3 * n), Cs_.assign(3 * n, 1.0f), Os_.assign(3 * n, 1.0f);
        for (int i = 0; i < n; ++i) {
            const float x = -0.9f + 1.8f * float(i % 16 + 0.5f) / 16;
            const float y = -0.9f + 1.8f * float(i / 16 + 0.5f) / 16;
            const float z = -std::sqrt(std::max(0.0f, 1 - x * x - y * y));
            P_[i] = x, P_[n + i] = y, P_[2 * n + i] = z + 4;
            N_[i] = x, N_[n + i] = y, N_[2 * n + i] = z;
        }
        globals_.n = n;
        globals_.P = globals_.I = P_.data();
        globals_.N = globals_.Ng = N_.data();
        globals_.Cs = Cs_.data(), globals_.Os = Os_.data();
        dPdu_.assign(3 * n, 0.0f);
        for (int i = 0; i < n; ++i) dPdu_[i] = 1.0f;
        globals_.dPdu = dPdu_.data();
    }

    Diagnostics diagnostics_;
    BrdfContext context_;
    std::unique_ptr<sl::ShaderInstance> surface_;
    sl::ShaderExecutor executor_;
    sl::ShaderGlobals globals_;
    std::vector<float> P_, N_, Cs_, Os_, dPdu_;
};

void RunShading(benchmark::State& state, const std::string& body, const std::string& grid) {
    Shading shading(body, grid);
    for (auto _ : state) shading.Run();
    state.counters["points/s"] = benchmark::Counter(double(kPoints) * double(state.iterations()),
                                                    benchmark::Counter::kIsRate);
    state.counters["ns/point"] = benchmark::Counter(
        double(kPoints) * double(state.iterations()),
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}

void BM_Diffuse(benchmark::State& state) { RunShading(state, "C = diffuse(Nf);", ""); }
void BM_BrdfBaked(benchmark::State& state) { RunShading(state, kBrdfBody, "phong.grd"); }
void BM_BrdfGrid(benchmark::State& state) { RunShading(state, kBrdfBody, "phong_grid.grd"); }

BENCHMARK(BM_Diffuse);
BENCHMARK(BM_BrdfBaked);
BENCHMARK(BM_BrdfGrid);

}  // namespace
}  // namespace gonio

BENCHMARK_MAIN();
