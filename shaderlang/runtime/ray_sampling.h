#pragma once
// What the ray-traced built-ins (occlusion, indirectdiffuse, gather, transmission, visibility)
// share: their options, stratified directions in a cone, and a batch of rays per point traced
// through ShadingContext::TraceSampledRays. Internal to shaderlang/runtime/.

#include <functional>
#include <string>
#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

// The ("name", value) options after a call's fixed arguments (docs/shading-language.md,
// Ray-traced built-ins). Numbers may vary per point; unknown names are warned about once.
struct RayOptions {
    const FloatArg* maxdist = nullptr;       // rays end there (default: no end)
    const FloatArg* bias = nullptr;          // rays start there (default: trace()'s offset)
    const FloatArg* coneangle = nullptr;     // half-angle of the cone (default: the call's)
    const FloatArg* samplebase = nullptr;    // origins jittered over that many pixels (default 0)
    const FloatArg* samples = nullptr;       // transmission(): rays per point (default 1)
    const FloatArg* samplecone = nullptr;    // transmission(): cone about the segment (default 0)
    bool cosine = true;                      // "distribution": "cosine" (default) or "uniform"
    std::string environmentMap;              // misses look this map up ("" none)
    std::string environmentSpace = "world";  // ... with the direction in this space
    const FloatArg* environmentColor = nullptr;  // occlusion(): output, the map's mean
    std::string outputs;  // gather(): the output names, comma-separated (set by the compiler)

    float MaxDist(int p) const { return maxdist ? Float(*maxdist, p) : 1e30f; }
    float Bias(int p) const { return bias ? Float(*bias, p) : -1.0f; }
    float ConeAngle(int p, float fallback) const {
        return coneangle ? Float(*coneangle, p) : fallback;
    }
};

// Reads options from argument `first` on; `what` names the call in warnings.
RayOptions ReadRayOptions(const BuiltinCall& call, int first, const std::string& what);

// The number of samples a call takes (its `samples` argument at the first active point),
// at least 1.
int SampleCount(const BuiltinCall& call, const FloatArg& samples);

// `count` directions about the unit `axis` within the cone of half-angle `angle` (clamped to
// [0, π/2]), cosine-weighted (pdf ∝ cos θ) or uniform in solid angle, stratified over a
// sqrt(count) × sqrt(count) grid of the unit square with one random point per stratum (the
// rest, when count is not a product of the grid, at random), drawn from point p's random
// stream. Malley's method (pbrt-v3 §13.6.3): cos θ = sqrt(1 − u₁ sin²angle) for cosine
// weighting, cos θ = 1 − u₁(1 − cos angle) for uniform, φ = 2π u₂.
void ConeDirections(ShadingContext& context, int p, const V3& axis, float angle, bool cosine,
                    int count, std::vector<V3>* out);

// An origin jittered uniformly over a disc of radius `radius` perpendicular to `axis`.
V3 JitterOrigin(ShadingContext& context, int p, const V3& origin, const V3& axis, float radius);

// The batch points a ray-traced built-in computes: the main points any of whose copies
// (neighbour points) is active; each result is then copied to its active copies.
std::vector<int> MainActivePoints(const BuiltinCall& call);
void CopyToNeighbours(const BuiltinCall& call, const FloatArg& out, int p);

// Rays of many points, traced in chunks of a bounded size: Add() the rays of a point, and
// `done(point, dir, ray, hits)` runs for every ray once its chunk is traced (in the order
// added; `ray` indexes `hits`). `what` names the call in warnings. Traced() is false once the
// context said it has no scene (every result is then 0).
class RayBatch {
  public:
    using Done = std::function<void(int point, const V3& dir, int ray, const SampledHits& hits)>;
    RayBatch(ShadingContext& context, std::string what, SampledRays::Kind kind, Done done);
    void Add(int point, const V3& org, const V3& dir, float maxdist, float bias);
    void Flush();
    bool Traced() const { return traced_; }

  private:
    ShadingContext& context_;
    std::string what_;
    SampledRays::Kind kind_;
    Done done_;
    std::vector<float> org_, dir_, maxdist_, bias_;
    std::vector<int> point_;
    bool traced_ = true;
};

// Adds to `sum` (ncomps × n) the environment map's colour along each current-space
// direction of dirs[p] at point p (the map looked up in the option's environmentspace);
// nothing without an environment map.
void SumEnvironment(ShadingContext& context, const RayOptions& options,
                    const std::vector<std::vector<V3>>& dirs, int ncomps, std::vector<float>* sum);

}  // namespace gonio::sl::builtins
