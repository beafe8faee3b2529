// BRDFLight throughput: photon paths per second of the tracer on ribs/grass.rib and
// ribs/brushed_metal.rib with 1 and 2 threads, next to the ray rate of raw Embree (rtcIntersect1)
// and of our RayScene on the same geometry and the tracer's own beam rays, and to a minimal
// photon tracer written straight on Embree (diffuse bounces, nothing recorded): issue 5's
// benchmark.
//
//   build/bin/photon_bench --benchmark_counters_tabular=true
//
// Raw Embree sees grass as the same triangles and each brushed-metal cylinder as an Embree round
// linear curve of the same radius and axis (its native cylinder, with round instead of flat
// ends); the tracer intersects our exact quadric cylinders and disks. The raw scenes are built
// twice: with Embree's default flags (the reference, and what the tracer's RayScene
// uses) and with RTC_SCENE_FLAG_ROBUST (what the renderer's camera rays use), to show the price
// of robustness. Rates are per second of process CPU time (per
// core), which stays meaningful on a loaded machine.

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <vector>

#include "base/random.h"
#include "renderer/photon/micro_brdf.h"
#include "renderer/photon/photon_tracer.h"
#include "renderer/raytrace/ray_scene.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"

namespace gonio {
namespace {

constexpr int kRays = 200000;
constexpr uint64_t kPaths = 200000;

Frame LoadFrame(const std::string& name) {
    Diagnostics diagnostics;
    Frame frame;
    const std::string path = std::string(GONIO_RIBS_DIR) + "/" + name;
    SceneBuilder builder(path, diagnostics, [&](const Frame& f) { frame = f; });
    ParseRibFile(path, builder, diagnostics);
    builder.Finish(FileLoc{});
    return frame;
}

struct BeamRay {
    V3f org, dir;
};

// The tracer's first rays: ω′ uniform on the hemisphere, through a point of the 0.1 × 0.1 area.
std::vector<BeamRay> MakeBeams() {
    std::vector<BeamRay> rays;
    for (int i = 0; i < kRays; ++i) {
        uint64_t state = HashCombine(17, i);
        auto next = [&] { return ToUnitFloat(MixBits(state += kSplitMix64Step)); };
        const float cosT = 1 - next(), phi = 6.2831853f * next();
        const float sinT = std::sqrt(1 - cosT * cosT);
        const V3f w(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
        const V3f x((next() - 0.5f) * 0.1f, (next() - 0.5f) * 0.1f, 0);
        rays.push_back({x + 2.0f * w, -w});
    }
    return rays;
}

struct RawEmbree {
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = rtcNewScene(device);

    RawEmbree(const Frame& frame, bool robust) {
        if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        std::vector<float> curve;  // x y z r per control point, two per cylinder
        for (const SceneShape& shape : frame.shapes) {
            if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
                AddMesh(*mesh, shape.worldFromObject);
            } else if (const auto* q = std::get_if<QuadricShape>(&shape.geometry)) {
                const Imath::Box3f b = q->quadric->Bounds();
                if (b.max.z - b.min.z <= 0) continue;  // the end disks
                for (float z : {b.min.z, b.max.z}) {
                    V3f p;
                    shape.worldFromObject.multVecMatrix(V3f(0, 0, z), p);
                    curve.insert(curve.end(), {p.x, p.y, p.z, b.max.x});
                }
            }
        }
        if (!curve.empty()) AddCylinders(curve);
        rtcCommitScene(scene);
    }
    ~RawEmbree() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }

    void AddMesh(const TriangleMesh& mesh, const M44f& m) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<V3f*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, mesh.positions.size()));
        for (size_t i = 0; i < mesh.positions.size(); ++i) m.multVecMatrix(mesh.positions[i], v[i]);
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, mesh.TriangleCount()));
        std::memcpy(idx, mesh.indices.data(), 4 * mesh.indices.size());
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
    }

    void AddCylinders(const std::vector<float>& points) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
        const size_t n = points.size() / 4;
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 16, n));
        std::memcpy(v, points.data(), 4 * points.size());
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, 4, n / 2));
        for (size_t i = 0; i < n / 2; ++i) idx[i] = static_cast<unsigned>(2 * i);
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
    }

    // A minimal photon path on plain Embree: the beam, then cosine-weighted bounces about
    // Embree's own geometric normal until the ray escapes (at most 100). Returns the bounces.
    int TracePath(const BeamRay& beam, uint64_t path) const {
        uint64_t state = HashCombine(99, path);
        auto next = [&] { return ToUnitFloat(MixBits(state += kSplitMix64Step)); };
        V3f org = beam.org, dir = beam.dir;
        for (int bounce = 0; bounce < 100; ++bounce) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            RTCRayHit rh{};
            rh.ray.org_x = org.x, rh.ray.org_y = org.y, rh.ray.org_z = org.z;
            rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
            rh.ray.tfar = std::numeric_limits<float>::infinity();
            rh.ray.mask = ~0u;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &context, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return bounce;
            V3f n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
            n.normalize();
            if (n.dot(dir) > 0) n = -n;
            org = org + rh.ray.tfar * dir + 1e-5f * n;
            dir = FromLocal(n, std::sqrt(1 - next()), 6.2831853f * next());
        }
        return 100;
    }

    bool Intersect(const BeamRay& ray) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = ray.org.x, rh.ray.org_y = ray.org.y, rh.ray.org_z = ray.org.z;
        rh.ray.dir_x = ray.dir.x, rh.ray.dir_y = ray.dir.y, rh.ray.dir_z = ray.dir.z;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
};

struct Fixture {
    Frame frame;
    Diagnostics diagnostics{nullptr};
    std::unique_ptr<RayScene> ours;
    std::unique_ptr<RawEmbree> raw, rawRobust;
    MicroBrdfTable brdfs;
    std::vector<BeamRay> beams = MakeBeams();

    explicit Fixture(const std::string& rib) : frame(LoadFrame(rib)) {
        ours = std::make_unique<RayScene>(frame, diagnostics, RayScene::Traversal::kFast);
        raw = std::make_unique<RawEmbree>(frame, false);
        rawRobust = std::make_unique<RawEmbree>(frame, true);
        brdfs = BuildMicroBrdfTable(frame, diagnostics);
    }
};

Fixture& Scene(int which) {
    static std::map<int, std::unique_ptr<Fixture>> fixtures;
    auto& f = fixtures[which];
    if (!f) f = std::make_unique<Fixture>(which == 0 ? "grass.rib" : "brushed_metal.rib");
    return *f;
}

// The sum of count(i) over the fixture's beams, on the cores the benchmark allows.
template <typename Count>
int64_t SumOverBeams(const Count& count) {
    std::atomic<int64_t> sum{0};
    tbb::parallel_for(tbb::blocked_range<int>(0, kRays, 4096), [&](const auto& r) {
        int64_t local = 0;
        for (int i = r.begin(); i != r.end(); ++i) local += count(i);
        sum += local;
    });
    return sum;
}

template <typename Trace>
void TraceBeams(benchmark::State& state, const Trace& trace) {
    const Fixture& f = Scene(static_cast<int>(state.range(0)));
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(1));
    int64_t hits = 0;
    for (auto _ : state) hits = SumOverBeams([&](int i) { return trace(f, f.beams[i]); });
    state.counters["rays/s"] =
        benchmark::Counter(double(kRays), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["hit%"] = 100.0 * hits / kRays;
}

const RawEmbree& Raw(const Fixture& f, const benchmark::State& state) {
    return state.range(2) ? *f.rawRobust : *f.raw;
}

void BM_RawEmbreeBeams(benchmark::State& state) {
    TraceBeams(state,
               [&](const Fixture& f, const BeamRay& r) { return Raw(f, state).Intersect(r); });
}

void BM_RaySceneBeams(benchmark::State& state) {
    TraceBeams(state, [](const Fixture& f, const BeamRay& r) {
        RayHit hit;
        return f.ours->Intersect(r.org, r.dir, 0, std::numeric_limits<float>::infinity(), 0, &hit);
    });
}

// Plain-Embree photons: the same beams, diffuse bounces, no shading or records.
void BM_RawEmbreePhotons(benchmark::State& state) {
    const Fixture& f = Scene(static_cast<int>(state.range(0)));
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(1));
    const RawEmbree& raw = Raw(f, state);
    int64_t bounces = 0;
    for (auto _ : state)
        bounces = SumOverBeams([&](int i) { return int64_t(raw.TracePath(f.beams[i], i)); });
    state.counters["paths/s"] =
        benchmark::Counter(double(kRays), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["rays/s"] =
        benchmark::Counter(double(kRays + bounces), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["bounces"] = double(bounces) / kRays;
}

void BM_PhotonTracer(benchmark::State& state) {
    const Fixture& f = Scene(static_cast<int>(state.range(0)));
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(1));
    PhotonTraceSettings settings;
    settings.paths = kPaths;
    settings.isotropic = state.range(0) == 0;
    settings.averageAzimuth = settings.isotropic;
    PhotonStats stats;
    for (auto _ : state) stats = TracePhotons(f.frame, *f.ours, f.brdfs, settings).stats;
    state.counters["paths/s"] =
        benchmark::Counter(double(kPaths), benchmark::Counter::kIsIterationInvariantRate);
    // One ray for the beam and one after every bounce.
    state.counters["rays/s"] = benchmark::Counter(double(kPaths + stats.bounces),
                                                  benchmark::Counter::kIsIterationInvariantRate);
    state.counters["bounces"] = double(stats.bounces) / kPaths;
}

// Args: scene (0 grass, 1 brushed metal), threads.
void Args(benchmark::internal::Benchmark* b) {
    for (int scene : {0, 1})
        for (int threads : {1, 2}) b->Args({scene, threads});
    // Rates per second of process CPU time, i.e. per core: the machine this runs on is often
    // shared, and wall-clock rates would measure the other jobs too.
    b->ArgNames({"scene", "threads"})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
}

// Args for raw Embree: scene, threads, robust (0 default flags, 1 RTC_SCENE_FLAG_ROBUST).
void RawArgs(benchmark::internal::Benchmark* b) {
    for (int scene : {0, 1})
        for (int threads : {1, 2})
            for (int robust : {0, 1}) b->Args({scene, threads, robust});
    b->ArgNames({"scene", "threads", "robust"})
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime();
}

BENCHMARK(BM_RawEmbreeBeams)->Apply(RawArgs);
BENCHMARK(BM_RaySceneBeams)->Apply(Args);
BENCHMARK(BM_RawEmbreePhotons)->Apply(RawArgs);
BENCHMARK(BM_PhotonTracer)->Apply(Args);

}  // namespace
}  // namespace gonio

BENCHMARK_MAIN();
