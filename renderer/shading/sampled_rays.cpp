// The renderer's side of the ray-traced built-ins (occlusion, indirectdiffuse, gather,
// transmission, visibility; shaderlang/runtime/builtins_raytrace.cpp): their rays, sampled by
// the shading language in current space, traced through the frame's RayScene. Shaded rays go
// one depth deeper through the worker, as trace()'s do (RenderContext::Trace).

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/hash.h"
#include "renderer/raytrace/transparent_layers.h"
#include "renderer/shading/render_context.h"
#include "renderer/shading/shader_needs.h"

namespace gonio {

namespace {

V3f Plane3(const float* planes, int count, int k) {
    return V3f(planes[k], planes[count + k], planes[2 * size_t(count) + k]);
}

void SetPlane3(std::vector<float>* planes, int count, int k, const V3f& v) {
    for (int c = 0; c < 3; ++c) (*planes)[size_t(c) * count + k] = v[c];
}

}  // namespace

// A pixel's width at P: P moved by one pixel along raster x, at the same raster depth, and
// back to current space (the camera's own projection, so it holds for either projection).
float RenderContext::PixelWidth(const V3f& P) const {
    const M44f rasterFromCurrent =
        camera_.ScreenFromCamera() * camera_.NdcFromScreen() * camera_.RasterFromNdc();
    V3f raster, moved;
    rasterFromCurrent.multVecMatrix(P, raster);
    rasterFromCurrent.inverse().multVecMatrix(raster + V3f(1, 0, 0), moved);
    const float width = (moved - P).length();
    return std::isfinite(width) ? width : 0.0f;
}

bool RenderContext::ShadesSampledRays() const {
    return depth_ + 1 <= shaders_.TraceMaxDepth() &&
           depth_ + 1 <= TraceMaxDiffuseDepth(*batch_->attributes);
}

bool RenderContext::TraceSampledRays(const std::string&, const sl::SampledRays& rays,
                                     sl::SampledHits* hits) {
    using Kind = sl::SampledRays::Kind;
    const int count = rays.count, nc = colorComponents_;
    hits->hit.assign(size_t(count), 0);
    hits->t.assign(size_t(count), 0.f);
    hits->P.assign(3 * size_t(count), 0.f);
    hits->N.assign(3 * size_t(count), 0.f);
    hits->colour.assign(size_t(nc) * count, rays.kind == Kind::Transmission ? 1.f : 0.f);
    // Traced at the shutter's opening, as trace() and shadows are.
    const float time = shaders_.GetFrame().options.shutterOpen;
    const M44f& currentFromWorld = shaders_.CurrentFromWorld();
    // Normals go by the inverse transpose: n_current = n_world · (worldFromCurrent)ᵀ.
    const M44f normalToCurrent = worldFromCurrent_.transposed();
    const bool shade = rays.kind == Kind::Shaded && ShadesSampledRays();
    const float defaultBias = TraceBias(*batch_->attributes);
    TracedRays shaded;
    shaded.time = time;
    std::vector<int> shadedIndex;
    std::vector<int> perPoint(size_t(n_), 0);  // each point's rays so far: its random streams
    LeanSurfacePoint lean;
    SurfacePoint full;
    for (int k = 0; k < count; ++k) {
        V3f org, dir;
        worldFromCurrent_.multVecMatrix(Plane3(rays.org, count, k), org);
        worldFromCurrent_.multDirMatrix(Plane3(rays.dir, count, k), dir);
        // World units per current-space unit along the ray (1 unless the camera scales).
        const float scale = dir.length();
        if (!(scale > 0) || !std::isfinite(scale)) continue;
        dir /= scale;
        // The self-hit offset of trace() unless "bias" (or Attribute "trace" "bias") gives one.
        const float bias = rays.bias[k] >= 0 ? rays.bias[k] : defaultBias;
        const float tnear = bias >= 0 ? bias * scale : 1e-4f * std::max(1.f, org.length());
        const float tfar = std::min(rays.maxdist[k] * scale, std::numeric_limits<float>::max());
        if (!(tfar > tnear)) continue;
        if (rays.kind == Kind::Transmission) {
            float start = tnear, remaining = 1;
            for (int layer = 0;
                 layer < kMaxTransparentLayers && remaining > kNegligibleTransmittance; ++layer) {
                RayHit hit;
                ++rays_.sampled;
                if (!scene_.Intersect(org, dir, start, tfar, time, &hit)) break;
                hits->hit[k] = 1;
                scene_.Evaluate(org, dir, hit, &full);
                remaining = 0;
                for (int c = 0; c < nc; ++c) {
                    float& T = hits->colour[size_t(c) * count + k];
                    T *= 1 - std::clamp(c < int(full.Os.size()) ? full.Os[c] : 1.f, 0.f, 1.f);
                    remaining = std::max(remaining, T);
                }
                start = ContinuePast(hit.t);
            }
            continue;
        }
        if (rays.kind == Kind::AnyHit) {
            ++rays_.sampled;
            hits->hit[k] = scene_.Occluded(org, dir, tnear, tfar, time);
            continue;
        }
        RayHit hit;
        ++rays_.sampled;
        if (!scene_.Intersect(org, dir, tnear, tfar, time, &hit)) continue;
        hits->hit[k] = 1;
        scene_.EvaluateLean(org, dir, hit, &lean);
        V3f P, N;
        currentFromWorld.multVecMatrix(lean.P, P);
        normalToCurrent.multDirMatrix(lean.N, N);
        N.normalize();
        // The normal of the side the ray arrives at.
        if (N.dot(Plane3(rays.dir, count, k)) > 0) N = -N;
        hits->t[k] = (P - Plane3(rays.org, count, k)).length();
        SetPlane3(&hits->P, count, k, P);
        SetPlane3(&hits->N, count, k, N);
        if (!shade) continue;
        shaded.org.push_back(org), shaded.dir.push_back(dir);
        shaded.tnear.push_back(tnear), shaded.tfar.push_back(tfar);
        const int point = rays.point[k];
        if (batch_->randomSeeds.size() == size_t(n_) && point >= 0 && point < n_)
            shaded.randomSeeds.push_back(
                HashCombine(MixBits(batch_->randomSeeds[point] ^ uint64_t(depth_ + 1)),
                            uint64_t(perPoint[point]++)));
        shadedIndex.push_back(k);
    }
    if (shadedIndex.empty()) return true;
    std::vector<float> colours(shadedIndex.size() * nc, 0.f);
    tracer_.TraceRays(depth_ + 1, shaded, colours.data());
    for (size_t j = 0; j < shadedIndex.size(); ++j)
        for (int c = 0; c < nc; ++c)
            hits->colour[size_t(c) * count + shadedIndex[j]] = colours[j * nc + c];
    return true;
}

}  // namespace gonio
