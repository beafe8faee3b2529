#include "renderer/pathtrace/path_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/hash.h"
#include "base/math.h"
#include "renderer/raytrace/shadow_transmission.h"
#include "renderer/raytrace/transforms.h"
#include "renderer/raytrace/transparent_layers.h"

namespace gonio {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The power heuristic with exponent 2 (Veach 1997, eq. 9.13), one sample of each strategy.
float PowerHeuristic(double pdfThis, double pdfOther) {
    const double a = pdfThis * pdfThis, b = pdfOther * pdfOther;
    return a + b > 0 ? float(a / (a + b)) : 0.0f;
}

// Rays leave a surface from a point pushed off it along the geometric normal, on the side they
// go to, by a margin relative to the point's magnitude (float precision of the hit).
Imath::V3f OffsetOrigin(const Imath::V3f& P, const Imath::V3f& Ng, const Imath::V3f& dir) {
    const float scale = std::max({1.0f, std::abs(P.x), std::abs(P.y), std::abs(P.z)});
    const float side = Ng.dot(dir) >= 0 ? 1.0f : -1.0f;
    return P + Ng * (side * 1e-4f * scale);
}

// A surface's opacity for paths and shadow rays: its Os (Opacity, or the "Os" primitive
// variable), clamped to [0, 1]; its shader's Oi is not run.
float OpacityOf(const SurfacePoint& sp, int c) {
    return c < int(sp.Os.size()) ? std::clamp(sp.Os[size_t(c)], 0.0f, 1.0f) : 1.0f;
}

Imath::V3f AnyPerpendicular(const Imath::V3f& n) {
    const Imath::V3f helper = std::abs(n.x) < 0.9f ? Imath::V3f(1, 0, 0) : Imath::V3f(0, 1, 0);
    return (helper - n * helper.dot(n)).normalized();
}

}  // namespace

std::unique_ptr<PathIntegrator> PathIntegrator::ForFrame(const Frame& frame, const RayScene& scene,
                                                         Diagnostics& diagnostics) {
    const PathTraceOptions options = ReadPathTraceOptions(frame);
    if (!options.enabled) return nullptr;
    return std::make_unique<PathIntegrator>(frame, scene, diagnostics, options);
}

PathIntegrator::PathIntegrator(const Frame& frame, const RayScene& scene, Diagnostics& diagnostics,
                               const PathTraceOptions& options)
    : frame_(frame),
      scene_(scene),
      diagnostics_(diagnostics),
      options_(options),
      shaders_(frame, diagnostics),
      materials_(frame, shaders_, diagnostics),
      worldFromCurrent_(frame.options.cameraFromWorld.inverse()) {
    // Shaders take cross products in camera space: where it is mirrored against world space
    // (a negative determinant), the same formula gives the opposite world vector.
    const Imath::M44f& m = frame.options.cameraFromWorld;
    const float det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                      m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    crossSign_ = det < 0 ? -1.0f : 1.0f;
    for (size_t i = 0; i < frame.lights.size(); ++i)
        if (shaders_.Lights()[i].area)
            for (size_t shape : frame.lights[i].shapes) emitters_[&frame.shapes[shape]] = int(i);
}

PathIntegrator::~PathIntegrator() = default;

std::unique_ptr<PathWorker> PathIntegrator::MakeWorker() const {
    return std::make_unique<PathWorker>(*this);
}

PathWorker::PathWorker(const PathIntegrator& integrator)
    : c_(integrator),
      ncomps_(integrator.frame_.options.colorComponents),
      lightContext_(integrator.frame_, integrator.diagnostics_),
      beta_(size_t(ncomps_)),
      f_(size_t(ncomps_)),
      Ld_(size_t(ncomps_)),
      Le_(size_t(ncomps_)),
      T_(size_t(ncomps_)) {}

ShadingFrame PathWorker::MakeFrame(const SurfacePoint& sp, const Imath::V3f& wo,
                                   const PathMaterial& material) const {
    ShadingFrame frame;
    frame.n = sp.N.dot(wo) >= 0 ? sp.N : -sp.N;
    Imath::V3f axis = sp.dPdu;
    const float s = c_.crossSign_;
    if (material.splat) {
        const SplatSurface& splat = *material.splat;
        switch (splat.axis) {
            case SplatSurface::Axis::kDPdu:
                break;
            case SplatSurface::Axis::kDPdv:
                axis = sp.dPdv;
                break;
            case SplatSurface::Axis::kAcrossDPdu:
                axis = s * frame.n.cross(sp.dPdu);
                break;
            case SplatSurface::Axis::kAcrossDPdv:
                axis = s * frame.n.cross(sp.dPdv);
                break;
            case SplatSurface::Axis::kDirection:
                axis = splat.direction;
                break;
        }
        if (splat.angle != 0) {  // Rodrigues' rotation about n, as rotate() does it
            const float c = std::cos(splat.angle), sn = std::sin(splat.angle);
            axis = axis * c + s * frame.n.cross(axis) * sn + frame.n * frame.n.dot(axis) * (1 - c);
        }
    }
    const Imath::V3f tangent = axis - frame.n * frame.n.dot(axis);
    frame.x = tangent.length() > 1e-6f * axis.length() && axis.length() > 0
                  ? tangent.normalized()
                  : AnyPerpendicular(frame.n);
    frame.y = s * frame.n.cross(frame.x);
    return frame;
}

bool PathWorker::Transmittance(const Imath::V3f& P, const Imath::V3f& Ng, const Imath::V3f& dir,
                               float dist, float time, float* T) {
    const Imath::V3f org = OffsetOrigin(P, Ng, dir);
    const float tfar = std::isinf(dist) ? kInfinity : dist * (1 - 1e-4f);
    if (c_.shaders_.AllShadowsOpaque()) {
        ++rays_;
        const bool open = !c_.scene_.Occluded(org, dir, 0, tfar, time);
        std::fill(T, T + ncomps_, open ? 1.0f : 0.0f);
        return open;
    }
    rays_ += uint64_t(ShadowTransmission(c_.scene_, org, dir, 0, tfar, time, ncomps_, T));
    return std::any_of(T, T + ncomps_, [](float t) { return t > 0; });
}

bool PathWorker::NextScatteringHit(const Imath::V3f& org, const Imath::V3f& dir, float tnear,
                                   float tfar, float time, uint64_t* state, float* t) {
    for (int layer = 0; layer < kMaxTransparentLayers; ++layer) {
        if (!NextVisibleHit(c_.scene_, org, dir, time, tfar, &tnear, &sp_, t, &rays_)) return false;
        float mean = 0;
        for (int c = 0; c < ncomps_; ++c) mean += OpacityOf(sp_, c) / float(ncomps_);
        if (mean >= 1) return true;
        const float pass = 1 - mean;
        if (ToUnitFloat(SplitMix64(*state)) >= pass) {
            for (int c = 0; c < ncomps_; ++c) beta_[c] *= OpacityOf(sp_, c) / mean;
            return true;
        }
        for (int c = 0; c < ncomps_; ++c) beta_[c] *= (1 - OpacityOf(sp_, c)) / pass;
    }
    return false;
}

bool PathWorker::RunLight(int index, const Imath::V3f& Ps, const Imath::V3f& Ns,
                          const AreaLightSample* area, float time, uint64_t seed,
                          sl::LightResult* result) {
    const FrameLight& light = c_.shaders_.Lights()[size_t(index)];
    const Imath::M44f& currentFromWorld = c_.frame_.options.cameraFromWorld;
    const Imath::V3f Pc = TransformPoint(currentFromWorld, Ps);
    const Imath::V3f Nc = TransformNormal(c_.worldFromCurrent_, Ns);
    sl::ShaderGlobals globals;
    globals.n = 1;
    globals.Ps = &Pc.x;
    globals.Ns = &Nc.x;
    globals.time = time;
    Imath::V3f P, N;
    if (area) {
        P = TransformPoint(currentFromWorld, area->P);
        N = Normalized(TransformNormal(c_.worldFromCurrent_, area->N));
        globals.P = &P.x;
        globals.N = globals.Ng = &N.x;
    }
    lightContext_.Begin(&c_.frame_.lights[size_t(index)].light.shader, seed);
    lightExecutor_.RunLight(*light.instance, globals, lightContext_, result);
    return !result->ambient && result->lit[0];
}

bool PathWorker::Emitted(int index, const Imath::V3f& from, float time, uint64_t seed) {
    const Imath::V3f toViewer = from - sp_.P;
    const float d2 = toViewer.length2();
    const float cosLight = sp_.N.dot(toViewer) / std::sqrt(d2);
    if (!(cosLight > 0) || !c_.shaders_.Lights()[size_t(index)].instance) return false;
    const AreaLightSample here{sp_.P, sp_.N, 0};
    sl::LightResult result;
    // `from` is the previous path vertex, whose normal is not kept here.
    if (!RunLight(index, from, Imath::V3f(0.f), &here, time, seed, &result)) return false;
    for (int c = 0; c < ncomps_; ++c) Le_[c] = result.Cl[size_t(c)] * d2 / cosLight;
    return true;
}

void PathWorker::DirectLight(const SurfacePoint& sp, const ShadingFrame& frame, float time,
                             uint64_t* state, float* Ld) {
    std::fill(Ld, Ld + ncomps_, 0.0f);
    const std::vector<FrameLight>& lights = c_.shaders_.Lights();
    for (int index : sp.attributes->activeLights) {
        const FrameLight& light = lights[size_t(index)];
        // Each light draws its numbers whether or not it runs: the stream stays aligned.
        const float u0 = ToUnitFloat(SplitMix64(*state)), u1 = ToUnitFloat(SplitMix64(*state)),
                    u2 = ToUnitFloat(SplitMix64(*state));
        const uint64_t seed = SplitMix64(*state);
        if (!light.instance) continue;
        AreaLightSample sample{};
        if (light.area) sample = light.area->Sample(u0, u1, u2);
        sl::LightResult result;
        if (!RunLight(index, sp.P, sp.N, light.area ? &sample : nullptr, time, seed, &result))
            continue;
        // Ambient light is what the paths themselves gather; solar() without an axis (light
        // from all directions) has no direction to sample.
        if (!result.fromAllDirections.empty() && result.fromAllDirections[0]) continue;
        const Imath::V3f L = TransformVector(c_.worldFromCurrent_,
                                             Imath::V3f(result.L[0], result.L[1], result.L[2]));
        const float dist = L.length();
        if (!(dist > 0)) continue;
        const Imath::V3f wi = L / dist;
        const float cosTheta = frame.n.dot(wi);
        if (cosTheta <= 0) continue;
        const double pdfBsdf = bsdf_.Eval(wi, f_.data());
        if (std::all_of(f_.begin(), f_.end(), [](float v) { return v == 0; })) continue;
        // An area light's Cl is per unit of its area (arealight.sl): divided by the sample's
        // density. The MIS weight compares the densities of wi per steradian; the light's is
        // taken as uniform by area (1/Area), within 2e-5 of the exact one
        // (area_light_geometry.h) and the same function Radiance uses, so that the two
        // weights sum to 1 exactly.
        float weight = 1;
        if (light.area) {
            const float cosLight = std::abs(sample.N.dot(wi));
            if (!(sample.pdfArea > 0) || !(cosLight > 0)) continue;
            const double pdfLight = dist * dist / (cosLight * light.area->Area());
            weight = PowerHeuristic(pdfLight, pdfBsdf) / sample.pdfArea;
        }
        if (!Transmittance(sp.P, sp.Ng, wi, result.atInfinity ? kInfinity : dist, time, T_.data()))
            continue;
        for (int c = 0; c < ncomps_; ++c)
            Ld[c] += weight * f_[c] * T_[c] * result.Cl[size_t(c)] * cosTheta;
    }
}

bool PathWorker::Radiance(const CameraRay& ray, uint64_t seed, float* L, float* depth) {
    std::fill(L, L + ncomps_, 0.0f);
    std::fill(beta_.begin(), beta_.end(), 1.0f);
    uint64_t state = seed;
    auto next = [&] { return ToUnitFloat(SplitMix64(state)); };
    Imath::V3f org = ray.org, dir = ray.dir;
    float tnear = ray.tnear, tfar = ray.tfar;
    bool covered = false;
    // The vertex the ray left (the camera for bounce 0), and how the ray was drawn there.
    Imath::V3f from = ray.org;
    const Attributes* fromAttributes = nullptr;
    double fromPdf = 0;
    for (int bounce = 0;; ++bounce) {
        float t = 0;
        if (!NextScatteringHit(org, dir, tnear, tfar, ray.time, &state, &t)) break;
        if (bounce == 0) {
            covered = true;
            *depth = t;  // the camera ray's parameter: camera-space z (camera.h)
        }
        auto emitter = c_.emitters_.find(sp_.shape);
        if (emitter != c_.emitters_.end() && Emitted(emitter->second, from, ray.time, next())) {
            // Seen by the camera, or by a BSDF sample at a vertex whose lights did not
            // include this one, the emission counts whole; else it shares with the light's
            // own sample (DirectLight) by the power heuristic.
            float weight = 1;
            if (fromAttributes && fromAttributes->activeLights.count(emitter->second)) {
                const Imath::V3f toFrom = from - sp_.P;
                const float d2 = toFrom.length2();
                const float cosLight = sp_.N.dot(toFrom) / std::sqrt(d2);
                const double pdfLight =
                    d2 / (cosLight * c_.shaders_.Lights()[size_t(emitter->second)].area->Area());
                weight = PowerHeuristic(fromPdf, pdfLight);
            }
            for (int c = 0; c < ncomps_; ++c) L[c] += weight * beta_[c] * Le_[c];
        }
        if (bounce >= c_.options_.maxDepth) break;
        const PathMaterial& material = c_.materials_.Of(sp_.attributes);
        const Imath::V3f wo = -dir.normalized();
        const ShadingFrame frame = MakeFrame(sp_, wo, material);
        bsdf_.Begin(material, frame, sp_.Cs.data(), ncomps_, wo);
        DirectLight(sp_, frame, ray.time, &state, Ld_.data());
        for (int c = 0; c < ncomps_; ++c) L[c] += beta_[c] * Ld_[c];
        const float u0 = next(), u1 = next(), u2 = next();
        Imath::V3f wi;
        double pdf = 0;
        if (!bsdf_.Sample(u0, u1, u2, SplitMix64(state), &wi, f_.data(), &pdf)) break;
        const float weight = std::abs(frame.n.dot(wi)) / float(pdf);
        float largest = 0;
        for (int c = 0; c < ncomps_; ++c) {
            beta_[c] *= f_[c] * weight;
            largest = std::max(largest, beta_[c]);
        }
        if (!(largest > 0)) break;
        // Russian roulette: go on with probability q, and weigh the survivors by 1/q.
        if (bounce + 1 >= c_.options_.rrDepth && largest < 1) {
            if (next() >= largest) break;
            for (float& b : beta_) b /= largest;
        }
        from = sp_.P;
        fromAttributes = sp_.attributes;
        fromPdf = pdf;
        org = OffsetOrigin(sp_.P, sp_.Ng, wi);
        dir = wi;
        tnear = 0;
        tfar = kInfinity;
    }
    return covered;
}

}  // namespace gonio
