#include "renderer/photon/photon_tracer.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "base/math.h"
#include "base/progress.h"
#include "base/random.h"
#include "renderer/photon/leaf_optics.h"
#include "renderer/photon/row_angles.h"
#include "renderer/photon/scene_bounds.h"
#include "renderer/shading/frame_shaders.h"

namespace gonio {
namespace {

using Imath::V3f;

constexpr uint64_t kBatch = 4096;
constexpr int kFirstColumns = 5;  // θ_in φ_in θ_out φ_out p_in, then the colour
// A periodic ray that crosses this many tile walls without hitting or leaving the slab of the
// geometry runs (almost) horizontally through it: counted with the bounce-limit photons.
constexpr int kMaxWraps = 10000;

class PathRandom {
  public:
    PathRandom(uint64_t seed, uint64_t path) : state_(HashCombine(MixBits(seed), path)) {}
    float Next() { return ToUnitFloat(MixBits(state_ += kSplitMix64Step)); }

  private:
    uint64_t state_;
};

enum class Segment { Hit, Escaped, Stuck };

// Everything a path needs that does not change during the run.
struct TraceContext {
    const RayScene& scene;
    const MicroBrdfTable& brdfs;
    const PhotonTraceSettings& settings;
    int ncomps;
    float half = 0;                // half the tile side
    float cosMin = 1, cosMax = 0;  // of θ_in: cos θmax ≤ cos θ′ ≤ cos θmin
    float pIn = 0;                 // pdf of ω′ per steradian of an anisotropic run
    float launch = 0;  // beam origins this far from the sampling area lie outside the bounds
    float zMin = 0, zMax = 0;  // vertical extent of the geometry
    float offset = 0;          // ray origin offset off a surface
};

// Intersects org + t·dir; for a periodic tile the ray runs in the column over the tile and
// re-enters on the far side when it crosses a wall (org is moved to the last entry point), and
// it has escaped once it leaves the slab [zMin, zMax] of the geometry.
Segment TraceSegment(const TraceContext& c, V3f& org, const V3f& dir, RayHit* hit) {
    if (!c.settings.periodic) {
        return c.scene.Intersect(org, dir, 0, std::numeric_limits<float>::infinity(), 0, hit)
                   ? Segment::Hit
                   : Segment::Escaped;
    }
    const float inf = std::numeric_limits<float>::infinity();
    for (int wraps = 0; wraps < kMaxWraps; ++wraps) {
        const float tx = dir.x > 0   ? (c.half - org.x) / dir.x
                         : dir.x < 0 ? (-c.half - org.x) / dir.x
                                     : inf;
        const float ty = dir.y > 0   ? (c.half - org.y) / dir.y
                         : dir.y < 0 ? (-c.half - org.y) / dir.y
                                     : inf;
        const float tz = dir.z > 0   ? (c.zMax - org.z) / dir.z
                         : dir.z < 0 ? (c.zMin - org.z) / dir.z
                                     : inf;
        const float tWall = std::max(0.0f, std::min(tx, ty));
        if (c.scene.Intersect(org, dir, 0, std::min(tWall, std::max(tz, 0.0f)), 0, hit))
            return Segment::Hit;
        if (tz <= tWall) return Segment::Escaped;
        org += tWall * dir;
        if (tx <= ty)
            org.x = dir.x > 0 ? -c.half : c.half;
        else
            org.y = dir.y > 0 ? -c.half : c.half;
    }
    return Segment::Stuck;
}

// The start of the beam through x: outside the geometry on the light's side (for a periodic
// tile: above the slab, moved back into the column).
V3f BeamOrigin(const TraceContext& c, const V3f& x, const V3f& wIn) {
    if (!c.settings.periodic) return x + c.launch * wIn;
    const double s = (double(c.zMax) - x.z) / wIn.z + 1e-4;
    const double w = 2.0 * c.half;
    auto wrap = [&](double v) { return static_cast<float>(v - w * std::floor(v / w + 0.5)); };
    return V3f(wrap(x.x + s * wIn.x), wrap(x.y + s * wIn.y), static_cast<float>(x.z + s * wIn.z));
}

// The paths [first, first + kBatch): their rows go to the batch's own slice of the result
// buffer (room for every path to escape), compacted in path order once all batches are done.
struct Batch {
    float* rows = nullptr;
    uint16_t* bounces = nullptr;  // one per row
    size_t values = 0;
    PhotonStats stats;
};

class PathTracer {
  public:
    PathTracer(const TraceContext& c, Batch& out) : c_(c), out_(out), beta_(c.ncomps) {}

    void Trace(uint64_t path) {
        PathRandom random(c_.settings.seed, path);
        float thetaIn, sinIn, cosIn, pIn;
        DrawIncidence(random.Next(), &thetaIn, &sinIn, &cosIn, &pIn);
        const bool fixedAzimuth = c_.settings.isotropic && !c_.settings.averageAzimuth;
        const float phiIn = fixedAzimuth ? 0.0f : 2 * kPiF * random.Next();
        const V3f wIn(sinIn * std::cos(phiIn), sinIn * std::sin(phiIn), cosIn);
        const float w = 2 * c_.half;
        const V3f x((random.Next() - 0.5f) * w, (random.Next() - 0.5f) * w, 0);

        V3f org = BeamOrigin(c_, x, wIn), dir = -wIn;
        RayHit hit;
        if (TraceSegment(c_, org, dir, &hit) != Segment::Hit) {
            ++out_.stats.missed;
            return;
        }
        std::fill(beta_.begin(), beta_.end(), 1.0f);
        for (int depth = 1;; ++depth) {
            ++out_.stats.bounces;
            c_.scene.EvaluateLean(org, dir, hit, &sp_);
            const V3f wo = Scatter(sp_, -dir, random);
            if (wo == V3f(0)) {
                ++out_.stats.absorbed;
                return;
            }
            org = sp_.P + c_.offset * FacingNormal(sp_.Ng, wo);
            dir = wo;
            const Segment next = TraceSegment(c_, org, dir, &hit);
            if (next == Segment::Escaped) return Escape(thetaIn, phiIn, pIn, wo, depth);
            if (next == Segment::Stuck || depth >= c_.settings.maxDepth) {
                ++out_.stats.bounceLimit;
                return;
            }
        }
    }

  private:
    // θ′ and p_in, the pdf of ω′ per steradian. Anisotropic runs: cos θ′ uniform (uniform on
    // the zone of the hemisphere, DESIGN.md). Isotropic runs: θ′ uniform, as brdfsim's synthetic
    // maps, and p_in that of the rotation-symmetric law, (1/Δθ)/(2π sin θ′): their domain is
    // θ′ × ω, and a density uniform in θ′ keeps the photons' weights β/p_in bounded at the
    // pole, where cos θ′ uniform would give them infinite variance.
    // Also returns sin θ′ and cos θ′, computed once.
    void DrawIncidence(float u, float* theta, float* sinTheta, float* cosTheta, float* pIn) const {
        const float t0 = c_.settings.thetaMin, t1 = c_.settings.thetaMax;
        if (!c_.settings.isotropic) {
            const float cosIn = c_.cosMax + (c_.cosMin - c_.cosMax) * (1 - u);
            *theta = PolarAngle(cosIn);
            *sinTheta = std::sqrt(std::max(0.0f, 1 - cosIn * cosIn));
            *cosTheta = cosIn;
            *pIn = c_.pIn;
            return;
        }
        *theta = t0 + (t1 - t0) * (1 - u);  // in (θmin, θmax]
        *sinTheta = std::sin(*theta);
        *cosTheta = std::cos(*theta);
        *pIn = 1 / ((t1 - t0) * 2 * kPiF * std::max(*sinTheta, 1e-7f));
    }

    static V3f FacingNormal(const V3f& n, const V3f& w) { return n.dot(w) < 0 ? -n : n; }

    // Samples the micro BRDF at sp for light arriving from wi and multiplies β by f cos/pdf;
    // returns 0 when the photon is absorbed (sampled into an opaque surface, or β vanished).
    // A leaf's transmitted photon leaves on the far side: the caller offsets its origin along
    // the geometric normal on the side of ωo.
    V3f Scatter(const LeanSurfacePoint& sp, const V3f& wi, PathRandom& random) {
        const MicroBrdf& brdf = BrdfOf(sp.shape);
        // Surfaces reflect on the side the photon arrives from (thin blades are two-sided).
        const V3f ng = FacingNormal(sp.Ng, wi);
        const V3f n = FacingNormal(sp.N, ng);
        const float u0 = random.Next(), u1 = random.Next(), u2 = random.Next();
        const auto [wo, value] = brdf.Sample(n, wi, u0, u1, u2);
        const float cosOut = std::abs(n.dot(wo)), side = wo.dot(ng);
        // Through the surface (both normals agree) is transmission for a leaf, absorption for
        // Phong; shading and geometric normals that disagree about the side absorb.
        const bool through = n.dot(wo) < 0;
        if (side == 0 || through != (side < 0) || (through && !brdf.Transmits()) || cosOut <= 0 ||
            !(value.pdf > 0)) {
            return V3f(0);
        }
        bool alive = false;
        for (int k = 0; k < c_.ncomps; ++k) {
            const float cs = k < int(sp.Cs.size()) ? sp.Cs[k] : 1.0f;
            beta_[k] *= brdf.Component(value, k, cs) * cosOut / value.pdf;
            alive |= beta_[k] > 0;
        }
        return alive ? wo : V3f(0);
    }

    void Escape(float thetaIn, float phiIn, float pIn, const V3f& wo, int depth) {
        if (wo.z <= 0) {
            ++out_.stats.escapedDown;
            for (int k = 0; k < c_.ncomps; ++k) out_.stats.energyDown[k] += beta_[k];
            return;
        }
        ++out_.stats.escapedUp;
        float phiOut = Azimuth(wo.y, wo.x);
        if (c_.settings.isotropic) {  // relative to the light: the map holds φ_in = 0
            phiOut -= phiIn;
            phiIn = 0;
        }
        phiOut -= 2 * kPiF * std::floor(phiOut / (2 * kPiF));
        float* row = out_.rows + out_.values;
        row[0] = thetaIn, row[1] = phiIn, row[2] = PolarAngle(wo.z);
        row[3] = phiOut, row[4] = pIn;
        std::copy(beta_.begin(), beta_.end(), row + kFirstColumns);
        out_.bounces[out_.values / (kFirstColumns + c_.ncomps)] =
            static_cast<uint16_t>(std::min(depth, int(kMaxBounceTag)));
        out_.values += kFirstColumns + c_.ncomps;
        for (int k = 0; k < c_.ncomps; ++k) out_.stats.energyUp[k] += beta_[k];
    }

    // Consecutive hits mostly meet the same shape: one table look-up per change of shape.
    const MicroBrdf& BrdfOf(const SceneShape* shape) {
        if (shape != lastShape_) {
            lastShape_ = shape;
            lastBrdf_ = &c_.brdfs.at(shape);
        }
        return *lastBrdf_;
    }

    const TraceContext& c_;
    Batch& out_;
    std::vector<float> beta_;
    LeanSurfacePoint sp_;  // reused by every hit
    const SceneShape* lastShape_ = nullptr;
    const MicroBrdf* lastBrdf_ = nullptr;
};

void Accumulate(const PhotonStats& from, PhotonStats* to) {
    to->escapedUp += from.escapedUp;
    to->escapedDown += from.escapedDown;
    to->missed += from.missed;
    to->bounceLimit += from.bounceLimit;
    to->absorbed += from.absorbed;
    to->bounces += from.bounces;
    for (size_t k = 0; k < to->energyUp.size(); ++k) {
        to->energyUp[k] += from.energyUp[k];
        to->energyDown[k] += from.energyDown[k];
    }
}

// A leaf's reflectance and transmittance hold one value or one per colour component.
void CheckLeafColours(const LeafOptics& leaf, const ParamDict& params, int ncomps,
                      Diagnostics& diagnostics) {
    const LeafParams& p = leaf.Params();
    for (const auto& [name, values] :
         {std::pair{"reflectance", &p.reflectance}, std::pair{"transmittance", &p.transmittance}}) {
        if (values->size() == 1 || int(values->size()) == ncomps) continue;
        diagnostics.Error(params.Location(name), std::string("Attribute \"brdflight\" \"") + name +
                                                     "\": expected 1 or " + std::to_string(ncomps) +
                                                     " values (the colour components), got " +
                                                     std::to_string(values->size()));
    }
}

}  // namespace

MicroBrdfTable BuildMicroBrdfTable(const Frame& frame, Diagnostics& diagnostics) {
    sl::ShadingSystem shaders(diagnostics, frame.options.colorComponents);
    shaders.SetSearchPath(ShaderSearchPath(frame));
    std::map<const Attributes*, MicroBrdf> byState;
    auto brdfOf = [&](const Attributes& attributes) {
        auto known = byState.find(&attributes);
        if (known != byState.end()) return known->second;
        // Without a Surface the micro geometry is matte, as in an image render.
        ShaderInstance request = attributes.surface;
        if (!request.IsSet()) request = ShaderInstance{"matte", {}, {}, attributes.surface.loc};
        const auto surface =
            LoadShaderInstance(shaders, request, sl::ShaderType::Surface, Imath::M44f(),
                               Declarations(), frame.options, diagnostics);
        const MicroBrdf brdf =
            surface ? MicroBrdfFromShader(*surface, attributes, diagnostics) : MicroBrdf{};
        if (brdf.leaf) {
            CheckLeafColours(*brdf.leaf, attributes.user.at("brdflight"),
                             frame.options.colorComponents, diagnostics);
        }
        return byState.emplace(&attributes, brdf).first->second;
    };
    MicroBrdfTable table;
    for (const SceneShape& shape : frame.shapes) table[&shape] = brdfOf(*shape.attributes);
    for (const ObjectInstanceUse& use : frame.instances) {
        for (const SceneShape& shape : use.definition->shapes)
            table[&shape] = brdfOf(*shape.attributes);
    }
    return table;
}

double PhotonTraceBytes(uint64_t paths, int ncomps) {
    return double(paths) * (double(kFirstColumns + ncomps) * sizeof(float) + sizeof(uint16_t));
}

PhotonTraceResult TracePhotons(const Frame& frame, const RayScene& scene,
                               const MicroBrdfTable& brdfs, const PhotonTraceSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    const Imath::Box3f bounds = WorldBounds(frame);
    float reach = 0;
    for (int i = 0; i < 8; ++i) {
        const V3f corner((i & 1) ? bounds.max.x : bounds.min.x,
                         (i & 2) ? bounds.max.y : bounds.min.y,
                         (i & 4) ? bounds.max.z : bounds.min.z);
        reach = std::max(reach, corner.length());
    }
    TraceContext c{scene, brdfs, settings, frame.options.colorComponents};
    c.half = settings.area / 2;
    c.cosMin = std::cos(settings.thetaMin);
    c.cosMax = std::max(0.0f, std::cos(settings.thetaMax));
    c.pIn = 1 / (2 * kPiF * (c.cosMin - c.cosMax));
    c.launch = reach + settings.area + 1;
    c.offset = 1e-5f * std::max(bounds.size().length(), 1e-3f);
    // The slab reaches a little past the geometry so that a ground plane at its bottom is hit.
    c.zMin = bounds.min.z - 10 * c.offset;
    c.zMax = bounds.max.z + 10 * c.offset;

    PhotonTraceResult result;
    result.ncomps = c.ncomps;
    const size_t stride = kFirstColumns + c.ncomps;
    result.rows.resize(settings.paths * stride);
    result.bounces.resize(settings.paths);
    const uint64_t numBatches = (settings.paths + kBatch - 1) / kBatch;
    std::vector<Batch> batches(numBatches);
    Progress progress("BRDFLight", settings.paths, settings.progress);
    tbb::parallel_for(uint64_t(0), numBatches, [&](uint64_t b) {
        // Counted on this thread's stack and stored once: neighbouring batches' counters share
        // cache lines, and two threads bumping them per path cost about 5% on two cores.
        Batch batch;
        batch.stats.energyUp.assign(c.ncomps, 0.0);
        batch.stats.energyDown.assign(c.ncomps, 0.0);
        batch.rows = result.rows.data() + b * kBatch * stride;
        batch.bounces = result.bounces.data() + b * kBatch;
        PathTracer tracer(c, batch);
        const uint64_t first = b * kBatch, last = std::min(settings.paths, first + kBatch);
        for (uint64_t path = first; path < last; ++path) tracer.Trace(settings.firstPath + path);
        batches[b] = std::move(batch);
        progress.Advance(last - first);
    });
    progress.Done();

    result.stats.paths = settings.paths;
    result.stats.energyUp.assign(c.ncomps, 0.0);
    result.stats.energyDown.assign(c.ncomps, 0.0);
    size_t values = 0;
    for (const Batch& batch : batches) {  // slices only move down: copying forwards is safe
        std::copy(batch.rows, batch.rows + batch.values, result.rows.data() + values);
        const size_t photons = batch.values / stride;
        std::copy(batch.bounces, batch.bounces + photons, result.bounces.data() + values / stride);
        values += batch.values;
        Accumulate(batch.stats, &result.stats);
    }
    result.rows.resize(values);
    result.bounces.resize(values / stride);
    result.stats.threads = static_cast<int>(std::min<size_t>(
        tbb::this_task_arena::max_concurrency(),
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace gonio
