// The built-ins a gather loop is made of (compiler/gather_loop.h):
//   gather(category, P, dir, angle, samples, options..., "__outputs", names, "__id", k)
//       traces every sample's ray for the active points and keeps the hits in the context's
//       RayState; the rays are those of occlusion() (ray_sampling.h: stratified, cosine-
//       distributed about dir within angle unless "distribution" "uniform").
//   __gather_next(k)   uniform: 1 and on to the next sample while there is one, else 0
//   __gather_hit(k)    whether this sample's ray hit something at each point
//   __gather_value(k, "name")   the output "name" of this sample at each point
// The category is accepted as PRMan's gather takes it; every category traces rays.

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/runtime/ray_sampling.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl {

// One gather loop's samples over the batch: sample j of point p at index j·n + p.
struct GatherSamples {
    int n = 0, samples = 0, current = -1;
    std::vector<uint8_t> hit;
    std::vector<float> t, org, dir, P, N, colour;  // org, dir, P, N: 3 floats per entry
};

struct RayBuiltinState {
    std::map<int, GatherSamples> loops;  // by the loop's id
};

namespace builtins {

namespace {

GatherSamples* Loop(const BuiltinCall& call, int argument) {
    if (!call.context) return nullptr;
    std::shared_ptr<RayBuiltinState>& state = call.context->RayState();
    if (!state) state = std::make_shared<RayBuiltinState>();
    return &state->loops[int(Float(call.args[argument], 0))];
}

int LoopId(const BuiltinCall& call) {
    for (int a = 5; a + 1 < call.argCount; a += 2)
        if (call.argTypes[a].base == BaseType::String && call.strings[a].data &&
            call.strings[a].data[0] == "__id")
            return a + 1;
    return -1;
}

void GatherKernel(const BuiltinCall& call) {
    const int idArg = LoopId(call);
    GatherSamples* loop = idArg >= 0 ? Loop(call, idArg) : nullptr;
    if (!loop) {
        if (call.context)
            call.context->RuntimeWarning("gather",
                                         "gather() is a loop statement: gather(...) "
                                         "{ ... } else { ... }");
        return;
    }
    ShadingContext& context = *call.context;
    const RayOptions o = ReadRayOptions(call, 5, "gather()");
    const int n = call.n, nc = call.colorComponents;
    const int samples = SampleCount(call, call.args[4]);
    *loop = GatherSamples{};
    loop->n = n, loop->samples = samples;
    const size_t entries = size_t(n) * samples;
    loop->hit.assign(entries, 0), loop->t.assign(entries, 0);
    for (auto* v : {&loop->org, &loop->dir, &loop->P, &loop->N}) v->assign(3 * entries, 0);
    const bool shaded = o.outputs.find("surface:") != std::string::npos;
    if (shaded) loop->colour.assign(size_t(nc) * entries, 0);
    // Rays are added point by point, sample by sample; `next` finds each one's entry.
    std::vector<size_t> entryOf;
    size_t next = 0;
    RayBatch batch(context, "gather()",
                   shaded ? SampledRays::Kind::Shaded : SampledRays::Kind::FirstHit,
                   [&](int, const V3&, int k, const SampledHits& h) {
                       const size_t e = entryOf[next++];
                       loop->hit[e] = h.hit[k];
                       loop->t[e] = h.t[k];
                       const size_t count = h.hit.size();
                       for (int c = 0; c < 3; ++c) {
                           loop->P[3 * e + c] = h.P[c * count + k];
                           loop->N[3 * e + c] = h.N[c * count + k];
                       }
                       for (int c = 0; shaded && c < nc; ++c)
                           loop->colour[size_t(nc) * e + c] = h.colour[c * count + k];
                   });
    std::vector<V3> dirs;
    for (int p : MainActivePoints(call)) {
        const V3 axis = Normalized(Triple(call.args[2], p));
        if (axis.length() == 0.0f) continue;
        const V3 P = Triple(call.args[1], p);
        ConeDirections(context, p, axis, Float(call.args[3], p), o.cosine, samples, &dirs);
        for (int j = 0; j < samples; ++j) {
            const size_t e = size_t(j) * n + p;
            for (int c = 0; c < 3; ++c)
                loop->org[3 * e + c] = P[c], loop->dir[3 * e + c] = dirs[j][c];
            entryOf.push_back(e);
            batch.Add(p, P, dirs[j], o.MaxDist(p), o.Bias(p));
        }
    }
    batch.Flush();
}

// The sample's entry for point p (neighbour points read their main point's).
size_t Entry(const BuiltinCall& call, const GatherSamples& loop, int p) {
    const int main = std::clamp(call.context->MainPointCount(), 1, call.n);
    return size_t(loop.current) * loop.n + size_t(p % main);
}

bool Valid(const BuiltinCall& call, const GatherSamples* loop) {
    return loop && loop->n == call.n && loop->current >= 0 && loop->current < loop->samples;
}

void GatherNextKernel(const BuiltinCall& call) {
    GatherSamples* loop = Loop(call, 0);
    float more = 0;
    if (loop && loop->current + 1 < loop->samples) {
        ++loop->current;
        more = 1;
    }
    // Uniform unless the loop sits under a varying condition; then every active point reads it.
    ForEachPoint(call, [&](int p) { call.result.At(0, p) = more; });
}

void GatherHitKernel(const BuiltinCall& call) {
    const GatherSamples* loop = Loop(call, 0);
    const bool valid = Valid(call, loop);
    ForEachPoint(call, [&](int p) {
        call.result.At(0, p) = valid && loop->hit[Entry(call, *loop, p)] ? 1.0f : 0.0f;
    });
}

void GatherValueKernel(const BuiltinCall& call) {
    const GatherSamples* loop = Loop(call, 0);
    const bool valid = Valid(call, loop);
    const std::string& name = call.strings[1].data[0];
    const int width = call.result.width, nc = call.colorComponents;
    ForEachPoint(call, [&](int p) {
        float value[16] = {};
        int count = 1;
        if (valid) {
            const size_t e = Entry(call, *loop, p);
            const std::vector<float>* triple = name == "ray:origin"      ? &loop->org
                                               : name == "ray:direction" ? &loop->dir
                                               : name == "primitive:P"   ? &loop->P
                                               : name == "primitive:N"   ? &loop->N
                                                                         : nullptr;
            if (triple) {
                count = 3;
                for (int c = 0; c < 3; ++c) value[c] = (*triple)[3 * e + c];
            } else if (name == "surface:Ci" && !loop->colour.empty()) {
                count = std::min(nc, 16);
                for (int c = 0; c < count; ++c) value[c] = loop->colour[size_t(nc) * e + c];
            } else if (name == "ray:length") {
                value[0] = loop->t[e];
            }
        }
        // A float output of a triple takes its first component; a triple of a float, all.
        for (int c = 0; c < width; ++c)
            call.result.At(c, p) = value[count == 1 ? 0 : std::min(c, count - 1)];
    });
}

}  // namespace

void AddGatherBuiltins(BuiltinList* list) {
    list->Add("gather", "x", "spvff*", GatherKernel, kSamplesRays | kHasSideEffects);
    list->Add("__gather_next", "f", "f", GatherNextKernel, kHasSideEffects);
    list->Add("__gather_hit", "f", "f", GatherHitKernel, kVaryingResult | kHasSideEffects);
    for (const char* type : {"f", "c", "p", "v", "n"})
        list->Add("__gather_value", type, "fs", GatherValueKernel,
                  kVaryingResult | kHasSideEffects);
}

}  // namespace builtins

}  // namespace gonio::sl
