// Shading throughput of the standard `plastic` under two lights (a distantlight and a
// pointlight), through the interpreter (ShadingSystem + ShaderExecutor + a ShadingContext, as
// `gonio shade` runs it) and through a hand-written C++ plastic with the same formula, on the
// same batch of points, side by side (issue 3: the interpreted shader costs at most 2x the C++).
// Both include running the lights. The C++ result is checked against the interpreter's before
// timing, so the two really compute the same thing.

#include <Imath/ImathVec.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "shaderlang/runtime/builtins_lighting.h"
#include "shaderlang/shading_system.h"
#include "shaderlang/simple_context.h"

namespace gonio {
namespace {

using Imath::V3f;

// The lights, in current space, and plastic's parameters (its declared defaults).
const V3f kDistantFrom(0, 0, 0), kDistantTo(0.5f, -1, 1);
const float kDistantIntensity = 0.8f;
const V3f kPointFrom(2, 3, -1);
const float kPointIntensity = 12;
constexpr float kKa = 1, kKd = 0.5f, kKs = 0.5f, kRoughness = 0.1f;

// A batch of n points on the front of a unit sphere 4 units in front of the camera, with the
// camera at the origin (I = P), component-major as the interpreter wants them.
struct Batch {
    int n = 0;
    std::vector<float> P, N, I, Cs, Os;

    explicit Batch(int points) : n(points) {
        P.resize(3 * size_t(n)), N.resize(3 * size_t(n)), I.resize(3 * size_t(n));
        Cs.resize(3 * size_t(n)), Os.assign(3 * size_t(n), 1.0f);
        const int side = int(std::ceil(std::sqrt(double(n))));
        for (int i = 0; i < n; ++i) {
            const float x = -0.9f + 1.8f * (i % side + 0.5f) / side;
            const float y = -0.9f + 1.8f * (i / side + 0.5f) / side;
            const float z = -std::sqrt(std::max(0.0f, 1 - x * x - y * y));
            Set(&N, i, V3f(x, y, z));
            Set(&P, i, V3f(x, y, z + 4));
            Set(&I, i, V3f(x, y, z + 4));
            Set(&Cs, i, V3f(0.8f, 0.4f + 0.2f * x, 0.2f));
        }
    }
    void Set(std::vector<float>* planes, int i, const V3f& v) const {
        (*planes)[i] = v.x, (*planes)[n + i] = v.y, (*planes)[2 * n + i] = v.z;
    }
    V3f Get(const std::vector<float>& planes, int i) const {
        return V3f(planes[i], planes[n + i], planes[2 * n + i]);
    }
};

// ---- interpreted -------------------------------------------------------------------------

void Assign(sl::ShaderInstance& instance, const std::string& name, std::vector<float> values) {
    std::string error;
    if (!instance.SetParameter(name, values, &error)) {
        std::fprintf(stderr, "shading_bench: %s\n", error.c_str());
        std::exit(1);
    }
}

std::shared_ptr<const sl::Shader> Compile(const std::string& name, Diagnostics& diagnostics) {
    auto shader = sl::CompileShaderFile(std::string(GONIO_SHADER_DIR) + "/" + name + ".sl",
                                        sl::CompileOptions{}, diagnostics);
    if (!shader) {
        std::fprintf(stderr, "shading_bench: cannot compile %s.sl\n", name.c_str());
        std::exit(1);
    }
    return shader;
}

// plastic and its two lights, ready to run over a batch.
class InterpretedPlastic {
  public:
    explicit InterpretedPlastic(const Batch& batch) : batch_(batch), context_(diagnostics_) {
        surface_ = std::make_unique<sl::ShaderInstance>(Compile("plastic", diagnostics_));
        surface_->Specialize();
        auto distant = std::make_shared<sl::ShaderInstance>(Compile("distantlight", diagnostics_));
        Assign(*distant, "from", {kDistantFrom.x, kDistantFrom.y, kDistantFrom.z});
        Assign(*distant, "to", {kDistantTo.x, kDistantTo.y, kDistantTo.z});
        Assign(*distant, "intensity", {kDistantIntensity});
        distant->Specialize();
        auto point = std::make_shared<sl::ShaderInstance>(Compile("pointlight", diagnostics_));
        Assign(*point, "from", {kPointFrom.x, kPointFrom.y, kPointFrom.z});
        Assign(*point, "intensity", {kPointIntensity});
        point->Specialize();
        context_.AddLight(distant);
        context_.AddLight(point);
        globals_.n = batch.n;
        globals_.P = batch.P.data(), globals_.N = batch.N.data(), globals_.Ng = batch.N.data();
        globals_.I = batch.I.data(), globals_.Cs = batch.Cs.data(), globals_.Os = batch.Os.data();
    }

    // Shades the batch; the lights run inside (the first diffuse() asks the context for them).
    void Run() {
        context_.BeginBatch(globals_, 3);
        executor_.Run(*surface_, globals_, context_);
    }
    sl::FloatArg Ci() const { return executor_.Output("Ci"); }

  private:
    const Batch& batch_;
    Diagnostics diagnostics_;
    sl::SimpleShadingContext context_;
    std::unique_ptr<sl::ShaderInstance> surface_;
    sl::ShaderExecutor executor_;
    sl::ShaderGlobals globals_;
};

// ---- hand-written C++ ------------------------------------------------------------------------

// The same plastic: Ci = Os·(Cs·(Ka·ambient + Kd·diffuse(Nf)) + Ks·specular(Nf, V, roughness)),
// the lights computed per point as the light shaders do (distantlight: L = from - to, Cl =
// intensity; pointlight: L = from - P, Cl = intensity / L·L). Lights count where N·L ≥ 0.
class NativePlastic {
  public:
    explicit NativePlastic(const Batch& batch) : batch_(batch), Ci_(3 * size_t(batch.n)) {}

    void Run() {
        const int n = batch_.n;
        const V3f distantL = (kDistantFrom - kDistantTo).normalized();
        // specular()'s exponent as the interpreter picks it (8/roughness, as Aqsis).
        const float exponent = sl::builtins::kSpecularExponentScale / kRoughness;
        for (int i = 0; i < n; ++i) {
            const V3f P = batch_.Get(batch_.P, i), I = batch_.Get(batch_.I, i);
            V3f Nf = batch_.Get(batch_.N, i).normalized();
            if (Nf.dot(I) > 0) Nf = -Nf;  // faceforward(N, I)
            const V3f V = -I.normalized();
            const float ambient = 0;  // neither light is an ambient light
            float diffuse = 0, specular = 0;
            AddLight(Nf, V, distantL, kDistantIntensity, exponent, &diffuse, &specular);
            const V3f toPoint = kPointFrom - P;
            AddLight(Nf, V, toPoint.normalized(), kPointIntensity / toPoint.length2(), exponent,
                     &diffuse, &specular);
            for (int c = 0; c < 3; ++c) {
                const float os = batch_.Os[c * n + i], cs = batch_.Cs[c * n + i];
                Ci_[c * n + i] = os * (cs * (kKa * ambient + kKd * diffuse) + kKs * specular);
            }
        }
    }
    const std::vector<float>& Ci() const { return Ci_; }

  private:
    static void AddLight(const V3f& Nf, const V3f& V, const V3f& Ln, float Cl, float exponent,
                         float* diffuse, float* specular) {
        const float cosine = Nf.dot(Ln);
        if (cosine < 0) return;
        *diffuse += Cl * cosine;
        *specular += Cl * std::pow(std::max(0.0f, Nf.dot((Ln + V).normalized())), exponent);
    }

    const Batch& batch_;
    std::vector<float> Ci_;
};

// Aborts the benchmark if the two plastics disagree: the comparison is only fair if they
// compute the same image.
void CheckSameResult(int n) {
    Batch batch(n);
    InterpretedPlastic interpreted(batch);
    NativePlastic native(batch);
    interpreted.Run();
    native.Run();
    const sl::FloatArg ci = interpreted.Ci();
    float worst = 0;
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
            worst = std::max(worst, std::abs(ci.At(c, i) - native.Ci()[c * n + i]));
    if (!ci.data || worst > 1e-4f) {
        std::fprintf(stderr, "shading_bench: interpreted and C++ plastic differ by %g\n",
                     double(worst));
        std::exit(1);
    }
}

void ReportPoints(benchmark::State& state, int n) {
    state.counters["points/s"] =
        benchmark::Counter(double(n) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_PlasticInterpreted(benchmark::State& state) {
    const int n = int(state.range(0));
    CheckSameResult(n);
    Batch batch(n);
    InterpretedPlastic plastic(batch);
    for (auto _ : state) {
        plastic.Run();
        benchmark::DoNotOptimize(plastic.Ci().data);
        benchmark::ClobberMemory();
    }
    ReportPoints(state, n);
}

void BM_PlasticNative(benchmark::State& state) {
    const int n = int(state.range(0));
    Batch batch(n);
    NativePlastic plastic(batch);
    for (auto _ : state) {
        plastic.Run();
        benchmark::DoNotOptimize(plastic.Ci().data());
        benchmark::ClobberMemory();
    }
    ReportPoints(state, n);
}

// 256 is the renderer's batch (renderer/shading/shader_shading.cpp); 1024 is gonio shade's.
BENCHMARK(BM_PlasticInterpreted)->Arg(256)->Arg(1024);
BENCHMARK(BM_PlasticNative)->Arg(256)->Arg(1024);

}  // namespace
}  // namespace gonio

BENCHMARK_MAIN();
