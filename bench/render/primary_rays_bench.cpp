// Primary-ray throughput: our RayScene against raw Embree rtcIntersect1, on the same camera rays
// through the same geometry, with 1 and 2 threads (issue 2's benchmark).
//
//   build/bin/primary_rays_bench --benchmark_counters_tabular=true
//
// For a ratio that means something on a noisy machine, compare BM_RawEmbree and BM_RayScene of
// the same run, and interleave repetitions (--benchmark_repetitions=5
// --benchmark_enable_random_interleaving=true).
//
// Scenes: a 1M-triangle height-field mesh filling the view, and 10,000 spheres (radius 0.3 on a
// 0.6 grid). Raw Embree sees the mesh as the same triangles and the spheres as Embree's own
// sphere points (its fastest sphere); we trace our exact analytic quadric spheres. Raw Embree
// runs with its default scene flags (the reference) and with RTC_SCENE_FLAG_ROBUST,
// which RayScene uses, to tell our overhead from the price of robust traversal.

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <memory>
#include <vector>

#include "renderer/geometry/quadrics.h"
#include "renderer/raytrace/camera.h"
#include "renderer/raytrace/ray_scene.h"

namespace gonio {
namespace {

constexpr int kWidth = 640, kHeight = 480;

Frame MakeFrame(bool spheres) {
    Frame frame;
    frame.options.xres = kWidth;
    frame.options.yres = kHeight;
    frame.options.projection = "perspective";
    frame.options.fov = 45;
    auto attributes = std::make_shared<const Attributes>();
    SceneShape shape;
    shape.attributes = attributes;
    if (spheres) {
        // 100 x 100 spheres of radius 0.3 on a 0.6 grid, filling the view at z = 40.
        for (int j = 0; j < 100; ++j) {
            for (int i = 0; i < 100; ++i) {
                shape.geometry = QuadricShape{MakeSphere(0.3f, -0.3f, 0.3f, 360), {}};
                shape.worldFromObject = M44f().setTranslation(
                    V3f(0.6f * (i - 49.5f), 0.6f * (j - 49.5f), 40 + 0.3f * ((i + j) % 3)));
                frame.shapes.push_back(shape);
            }
        }
    } else {
        // A 1000 x 500 grid (1M triangles) of a wavy height field facing the camera.
        TriangleMesh mesh;
        const int nx = 1000, ny = 500;
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const float x = 20.f * i / nx - 10, y = 10.f * j / ny - 5;
                mesh.positions.emplace_back(x, y, 12 + 0.3f * std::sin(3 * x) * std::cos(2 * y));
            }
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const uint32_t a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
                mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
            }
        shape.geometry = std::move(mesh);
        frame.shapes.push_back(std::move(shape));
    }
    return frame;
}

std::vector<CameraRay> MakeRays(const Frame& frame) {
    const Camera camera(frame.options);
    std::vector<CameraRay> rays;
    rays.reserve(kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            rays.push_back(camera.GenerateRay(x + 0.5f, y + 0.5f, 0, 0));
    return rays;
}

// The same geometry as plain Embree objects: triangles, and sphere points for the quadrics.
struct RawEmbree {
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = rtcNewScene(device);

    RawEmbree(const Frame& frame, bool robust) {
        if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        std::vector<float> spheres;
        for (const SceneShape& shape : frame.shapes) {
            if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
                RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
                auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
                    g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, mesh->positions.size()));
                std::memcpy(v, mesh->positions.data(), 12 * mesh->positions.size());
                auto* i = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
                    g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, mesh->TriangleCount()));
                std::memcpy(i, mesh->indices.data(), 4 * mesh->indices.size());
                rtcCommitGeometry(g);
                rtcAttachGeometry(scene, g);
                rtcReleaseGeometry(g);
            } else {
                const V3f c = shape.worldFromObject.translation();
                spheres.insert(spheres.end(), {c.x, c.y, c.z, 0.3f});
            }
        }
        if (!spheres.empty()) {
            RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
                g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 16, spheres.size() / 4));
            std::memcpy(v, spheres.data(), 4 * spheres.size());
            rtcCommitGeometry(g);
            rtcAttachGeometry(scene, g);
            rtcReleaseGeometry(g);
        }
        rtcCommitScene(scene);
    }
    ~RawEmbree() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }

    bool Intersect(const CameraRay& ray) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = ray.org.x, rh.ray.org_y = ray.org.y, rh.ray.org_z = ray.org.z;
        rh.ray.dir_x = ray.dir.x, rh.ray.dir_y = ray.dir.y, rh.ray.dir_z = ray.dir.z;
        rh.ray.tnear = ray.tnear;
        rh.ray.tfar = ray.tfar;
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
    std::vector<CameraRay> rays;

    explicit Fixture(bool spheres) : frame(MakeFrame(spheres)) {
        ours = std::make_unique<RayScene>(frame, diagnostics);
        raw = std::make_unique<RawEmbree>(frame, false);
        rawRobust = std::make_unique<RawEmbree>(frame, true);
        rays = MakeRays(frame);
    }
};

Fixture& Scene(bool spheres) {
    static Fixture mesh(false), quadrics(true);
    return spheres ? quadrics : mesh;
}

template <class TraceOne>
void TraceAll(benchmark::State& state, const std::vector<CameraRay>& rays, TraceOne trace) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(1));
    size_t hits = 0;
    for (auto _ : state) {
        std::atomic<size_t> count{0};
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096),
                          [&](const tbb::blocked_range<size_t>& r) {
                              size_t local = 0;
                              for (size_t i = r.begin(); i < r.end(); ++i) local += trace(rays[i]);
                              count += local;
                          });
        hits = count;
    }
    state.counters["rays/s"] =
        benchmark::Counter(double(rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * hits / rays.size();
}

void BM_RayScene(benchmark::State& state) {
    Fixture& f = Scene(state.range(0));
    TraceAll(state, f.rays, [&](const CameraRay& ray) {
        RayHit hit;
        return f.ours->Intersect(ray.org, ray.dir, ray.tnear, ray.tfar, 0, &hit);
    });
}

void BM_RawEmbree(benchmark::State& state) {
    Fixture& f = Scene(state.range(0));
    const RawEmbree& raw = state.range(2) ? *f.rawRobust : *f.raw;
    TraceAll(state, f.rays, [&](const CameraRay& ray) { return raw.Intersect(ray); });
}

// Args: {scene (0 = 1M triangles, 1 = 10k spheres), threads}. Rates are per second of process
// CPU time, i.e. per core: the machine this runs on is often shared, and wall-clock rates
// would measure the other jobs too.
void Args(benchmark::internal::Benchmark* b) {
    b->Args({0, 1})->Args({0, 2})->Args({1, 1})->Args({1, 2})->MeasureProcessCPUTime();
}
// Raw Embree: {scene, threads, robust (0 default flags, 1 RTC_SCENE_FLAG_ROBUST)}.
void RawArgs(benchmark::internal::Benchmark* b) {
    for (int scene : {0, 1})
        for (int threads : {1, 2})
            for (int robust : {0, 1}) b->Args({scene, threads, robust});
    b->MeasureProcessCPUTime();
}
BENCHMARK(BM_RawEmbree)->Apply(RawArgs);
BENCHMARK(BM_RayScene)->Apply(Args);

}  // namespace
}  // namespace gonio

BENCHMARK_MAIN();
