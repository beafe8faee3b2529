// The cost of tessellating Blobby primitives (renderer/geometry/blobby.h): time per MakeBlobby,
// triangles made, grid points sampled, the cell side chosen.

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "renderer/geometry/blobby.h"

namespace gonio {
namespace {

struct BlobbyInput {
    std::vector<int> code;
    std::vector<float> floats;
};

void AddMatrix(std::vector<float>* floats, float scale, const V3f& at) {
    floats->insert(floats->end(),
                   {scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0, at.x, at.y, at.z, 1});
}

// Adds every leaf so far: the last instruction "0 n 0 1 ... n−1".
void AddAll(BlobbyInput* in, int leaves) {
    in->code.insert(in->code.end(), {0, leaves});
    for (int i = 0; i < leaves; ++i) in->code.push_back(i);
}

BlobbyInput Sphere() {
    BlobbyInput in{{1001, 0}, {}};
    AddMatrix(&in.floats, 1, V3f(0));
    return in;
}

BlobbyInput Lattice() {
    BlobbyInput in;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 5; ++i) {
                in.code.insert(in.code.end(), {1001, int(in.floats.size())});
                AddMatrix(&in.floats, 0.5f, V3f(0.3f * i, 0.3f * j, 0.3f * k));
            }
    AddAll(&in, 100);
    return in;
}

// 480 segments of radius 0.1 winding 12 times around a torus of radii 2 and 0.5.
BlobbyInput Spiral() {
    BlobbyInput in;
    auto at = [](int i) {
        const double u = 2 * M_PI * i / 480, v = 12 * u;
        const double r = 2 + 0.5 * std::cos(v);
        return V3f(float(r * std::cos(u)), float(r * std::sin(u)), float(0.5 * std::sin(v)));
    };
    for (int i = 0; i < 480; ++i) {
        const V3f a = at(i), b = at(i + 1);
        in.code.insert(in.code.end(), {1002, int(in.floats.size())});
        in.floats.insert(in.floats.end(), {a.x, a.y, a.z, b.x, b.y, b.z, 0.1f});
        AddMatrix(&in.floats, 1, V3f(0));
    }
    AddAll(&in, 480);
    return in;
}

void Tessellate(benchmark::State& state, const BlobbyInput& in) {
    BlobbyMesh last;
    for (auto _ : state) {
        std::vector<std::string> notes;
        auto result = MakeBlobby(0, in.code, in.floats, {}, {}, BlobbyTessellation{}, &notes);
        if (!result) {
            state.SkipWithError(result.Error().c_str());
            return;
        }
        last = result.Take();
        benchmark::DoNotOptimize(last.mesh.positions.data());
    }
    state.counters["triangles"] = double(last.mesh.TriangleCount());
    state.counters["sampled"] = double(last.sampledPoints);
    state.counters["cell"] = double(last.cell);
}

void BM_BlobbySphere(benchmark::State& state) { Tessellate(state, Sphere()); }
void BM_BlobbyLattice100(benchmark::State& state) { Tessellate(state, Lattice()); }
void BM_BlobbySpiral480(benchmark::State& state) { Tessellate(state, Spiral()); }

BENCHMARK(BM_BlobbySphere)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BlobbyLattice100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BlobbySpiral480)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gonio

BENCHMARK_MAIN();
