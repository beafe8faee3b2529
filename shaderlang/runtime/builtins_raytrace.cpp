// Ray-traced built-ins (RISpec 3.2 §15.9's PRMan/Pixie extensions): occlusion, indirectdiffuse,
// transmission, visibility. Each samples rays per point (ray_sampling.h) and asks the renderer
// to trace them (ShadingContext::TraceSampledRays); the gather loop's helpers are in
// builtins_gather.cpp. docs/shading-language.md (Ray-traced built-ins) states the options.
//
// occlusion(P, N, samples): the fraction of `samples` rays, cosine-distributed about N within
// "coneangle" (π/2), that hit something within "maxdist". With a cosine distribution this is
// the cosine-weighted occluded fraction of the cone, (1/π)∫ V(ω) cos θ dω for the hemisphere.
// indirectdiffuse(P, N, samples): the mean colour the same rays bring (their hits shaded, as
// trace() shades them; misses look up "environmentmap"): for the hemisphere, the irradiance
// divided by π, E/π = (1/π)∫ L(ω) cos θ dω, estimated by (1/N) Σ L(ω_k) with ω_k ∝ cos θ.

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/math.h"
#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/runtime/ray_sampling.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

void ClearResult(const BuiltinCall& call) {
    for (int p = 0; p < call.n; ++p)
        if (call.IsActive(p))
            for (int c = 0; c < call.result.width; ++c) call.result.At(c, p) = 0.0f;
}

// The origin of a ray from P about `axis`: P, or jittered over "samplebase" pixels.
V3 RayOrigin(const BuiltinCall& call, const RayOptions& o, int p, const V3& P, const V3& axis) {
    const float base = o.samplebase ? Float(*o.samplebase, p) : 0.0f;
    if (!(base > 0)) return P;
    return JitterOrigin(*call.context, p, P, axis, 0.5f * base * call.context->PixelWidth(P));
}

// occlusion() and indirectdiffuse(): `samples` rays per point about N; hits counted or
// their colours summed, misses' directions kept for the environment map.
void HemisphereKernel(const BuiltinCall& call, bool shaded, const char* what) {
    ClearResult(call);
    if (!call.context) return;
    ShadingContext& context = *call.context;
    // Past the diffuse depth an indirectdiffuse() brings nothing: its hits would not be shaded.
    if (shaded && !context.ShadesSampledRays()) return;
    const RayOptions o = ReadRayOptions(call, 3, what);
    const int samples = SampleCount(call, call.args[2]);
    const int n = call.n, nc = call.colorComponents;
    std::vector<float> hits(size_t(n), 0.0f), colour(size_t(nc) * n, 0.0f);
    std::vector<std::vector<V3>> misses(static_cast<size_t>(n));
    const bool wantMisses = !o.environmentMap.empty();
    RayBatch batch(context, what, shaded ? SampledRays::Kind::Shaded : SampledRays::Kind::AnyHit,
                   [&](int p, const V3& dir, int k, const SampledHits& h) {
                       if (!h.hit[k]) {
                           if (wantMisses) misses[p].push_back(dir);
                           return;
                       }
                       hits[p] += 1;
                       if (shaded)
                           for (int c = 0; c < nc; ++c)
                               colour[size_t(c) * n + p] += h.colour[size_t(c) * h.hit.size() + k];
                   });
    const std::vector<int> points = MainActivePoints(call);
    std::vector<V3> dirs;
    for (int p : points) {
        const V3 axis = Normalized(Triple(call.args[1], p));
        if (axis.length() == 0.0f) continue;
        const V3 P = Triple(call.args[0], p);
        ConeDirections(context, p, axis, o.ConeAngle(p, kHalfPiF), o.cosine, samples, &dirs);
        for (const V3& d : dirs)
            batch.Add(p, RayOrigin(call, o, p, P, axis), d, o.MaxDist(p), o.Bias(p));
    }
    batch.Flush();
    if (!batch.Traced()) return;
    std::vector<float> environment(size_t(nc) * n, 0.0f);
    SumEnvironment(context, o, misses, nc, &environment);
    const float weight = 1.0f / float(samples);
    for (int p : points) {
        if (shaded) {
            for (int c = 0; c < nc; ++c)
                call.result.At(c, p) =
                    (colour[size_t(c) * n + p] + environment[size_t(c) * n + p]) * weight;
        } else {
            call.result.At(0, p) = hits[p] * weight;
            if (o.environmentColor && o.environmentColor->varying) {
                for (int c = 0; c < nc; ++c)
                    o.environmentColor->At(c, p) = environment[size_t(c) * n + p] * weight;
                CopyToNeighbours(call, *o.environmentColor, p);
            }
        }
        CopyToNeighbours(call, call.result, p);
    }
}

void OcclusionKernel(const BuiltinCall& call) { HemisphereKernel(call, false, "occlusion()"); }

void IndirectDiffuseKernel(const BuiltinCall& call) {
    HemisphereKernel(call, true, "indirectdiffuse()");
}

// transmission(Psrc, Pdst): the colour that gets from Psrc to Pdst through every surface
// between (the product of their 1 − Os), averaged over "samples" rays towards points within
// "samplecone" of Pdst (uniform in solid angle). visibility(P1, P2): 1 when nothing lies
// between the points, else 0. Both stop 1e-4 of the distance short of the end point (as
// shadow rays do), so that the surface at the end does not block itself.
void SegmentKernel(const BuiltinCall& call, bool transmission) {
    ClearResult(call);
    if (!call.context) return;
    ShadingContext& context = *call.context;
    const char* what = transmission ? "transmission()" : "visibility()";
    const RayOptions o = ReadRayOptions(call, 2, what);
    const int n = call.n, nc = call.colorComponents;
    const int samples = o.samples ? SampleCount(call, *o.samples) : 1;
    std::vector<float> sum(size_t(nc) * n, 0.0f);
    RayBatch batch(
        context, what, transmission ? SampledRays::Kind::Transmission : SampledRays::Kind::AnyHit,
        [&](int p, const V3&, int k, const SampledHits& h) {
            for (int c = 0; c < nc; ++c)
                sum[size_t(c) * n + p] += transmission ? h.colour[size_t(c) * h.hit.size() + k]
                                                       : (h.hit[k] ? 0.0f : 1.0f);
        });
    const std::vector<int> points = MainActivePoints(call);
    std::vector<V3> dirs;
    for (int p : points) {
        const V3 from = Triple(call.args[0], p), to = Triple(call.args[1], p);
        const float length = (to - from).length();
        if (!(length > 0) || !std::isfinite(length)) continue;
        const V3 axis = (to - from) / length;
        const float cone = o.samplecone ? Float(*o.samplecone, p) : 0.0f;
        if (cone > 0) {
            ConeDirections(context, p, axis, cone, false, samples, &dirs);
        } else {
            dirs.assign(size_t(samples), axis);
        }
        for (const V3& d : dirs) batch.Add(p, from, d, length * (1 - 1e-4f), o.Bias(p));
    }
    batch.Flush();
    if (!batch.Traced()) return;
    for (int p : points) {
        const V3 from = Triple(call.args[0], p), to = Triple(call.args[1], p);
        const bool empty = !((to - from).length() > 0);
        for (int c = 0; c < call.result.width; ++c)
            call.result.At(c, p) = empty ? 1.0f : sum[size_t(c) * n + p] / float(samples);
        CopyToNeighbours(call, call.result, p);
    }
}

void TransmissionKernel(const BuiltinCall& call) { SegmentKernel(call, true); }
void VisibilityKernel(const BuiltinCall& call) { SegmentKernel(call, false); }

}  // namespace

void AddRayBuiltins(BuiltinList* list) {
    const unsigned traced = kVaryingResult | kSamplesRays;
    for (const char* normal : {"n", "v"}) {
        list->Add("occlusion", "f", std::string("p") + normal + "f*", OcclusionKernel,
                  traced | kOutputOptions);
        list->Add("indirectdiffuse", "c", std::string("p") + normal + "f*", IndirectDiffuseKernel,
                  traced);
    }
    list->Add("transmission", "c", "pp*", TransmissionKernel, traced);
    list->Add("visibility", "f", "pp*", VisibilityKernel, traced);
}

}  // namespace gonio::sl::builtins
