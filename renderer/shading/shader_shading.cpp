// The shading language in the render loop: a batch of points that share an attribute state is
// laid out component-major in current (camera) space and run through its displacement, surface
// and atmosphere shaders; the lights are run once per batch by the RenderContext. Shaders that
// take derivatives run on each point's two neighbour points as well (neighbour_points.h), and
// trace() shades what its rays hit one depth deeper, with one DepthShader per ray depth.

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "renderer/raytrace/camera.h"
#include "renderer/raytrace/ray_scene.h"
#include "renderer/raytrace/transparent_layers.h"
#include "renderer/shading/frame_shaders.h"
#include "renderer/shading/neighbour_points.h"
#include "renderer/shading/render_context.h"
#include "renderer/shading/shading_files.h"
#include "renderer/shading/surface_shading.h"

namespace gonio {
namespace {

constexpr int kMaxBatch = 256;  // points per interpreter run: registers stay in cache

// Component-major planes for one batch (batch.h layout).
struct Planes {
    std::vector<float> data;
    int n = 0;
    void Reset(int components, int points) {
        n = points;
        data.assign(size_t(components) * points, 0.f);
    }
    void Set(int i, const V3f& v) { data[i] = v.x, data[n + i] = v.y, data[2 * n + i] = v.z; }
    float* Plane(int component) { return data.data() + size_t(component) * n; }
};

int OutputFloats(const std::vector<ShaderOutput>& outputs) {
    int total = 0;
    for (const ShaderOutput& output : outputs) total += output.width;
    return total;
}

// The shading state of one ray depth. trace() at depth d shades its hits at depth d + 1 while
// depth d's registers, globals and points are still in use, so every depth has its own.
class DepthShader {
  public:
    DepthShader(const FrameShaders& shaders, const RayScene& scene, const Camera& camera,
                ShadingFiles& textures, RayTracer& tracer, int depth, ShadingWorker& fallback,
                RayCounts& rays)
        : shaders_(shaders),
          scene_(scene),
          context_(shaders, scene, camera, textures, lightExecutor_, tracer, depth, rays),
          rays_(rays),
          fallback_(fallback),
          ncomps_(shaders.GetFrame().options.colorComponents) {}

    void Shade(const ShadingBatch& batch, float* Ci, float* Oi);
    // The layers of the traced rays shaded at this depth (ShaderWorker::TraceRays).
    TransparentLayers& Layers() { return layers_; }

  private:
    // Appends to `chunk` the neighbour points of its points (first those along x, then those
    // along y) and fills the neighbour tables; `rays` are the chunk's neighbour rays.
    void AddNeighbourPoints(ShadingBatch* chunk, const NeighbourRays* rays);
    void ShadeChunk(const ShaderGroup& group, const ShadingBatch& chunk, int mainCount, float* Ci,
                    float* Oi);
    void FillGlobals(const ShaderGroup& group, const ShadingBatch& chunk);
    void CopyOut(const sl::ShaderExecutor& executor, const char* name, int count,
                 float* pointMajor);
    // The batch's AOVs: the surface shader's variable of each name (an output parameter, or a
    // global it uses), else the global as the batch gave it.
    void CopyOutputs(const ShadingBatch& chunk, int count);
    sl::FloatArg GlobalPlanes(const std::string& name);
    // Whether a shader of the group calls lightsource(): then the lights keep their parameters.
    bool ReadsLightParameters(const ShaderGroup& group);

    const FrameShaders& shaders_;
    const RayScene& scene_;
    // One executor per shader kind: message passing reads the parameters that the displacement
    // and surface shaders left in their registers while the next shader runs.
    sl::ShaderExecutor displacementExecutor_, surfaceExecutor_, lightExecutor_, volumeExecutor_;
    RenderContext context_;
    RayCounts& rays_;  // the worker's, shared by all depths
    ShadingWorker& fallback_;
    int ncomps_;
    sl::ShaderGlobals globals_;
    Planes P_, N_, Ng_, I_, dPdu_, dPdv_, u_, v_, s_, t_, Cs_, Os_, du_, dv_;
    std::vector<Planes> primvars_;
    std::vector<float> scratch_;
    std::vector<SurfacePoint> neighbourPoints_;
    TransparentLayers layers_;
    BatchNeighbours neighbours_;
    std::vector<float> neighbourDu_, neighbourDv_;  // per main point
    std::unordered_map<const ShaderGroup*, bool> readsLightParameters_;
};

void DepthShader::Shade(const ShadingBatch& batch, float* Ci, float* Oi) {
    const ShaderGroup* group = shaders_.Group(batch.attributes);
    if (!group || !group->surface) {
        fallback_.Shade(batch, Ci, Oi);
        return;
    }
    const int count = static_cast<int>(batch.points.size());
    const bool withNeighbours =
        shaders_.WantsNeighbours(*group) && batch.neighbourRays.size() == size_t(count);
    // With neighbours a chunk holds three points per point of the batch.
    const int chunkSize = withNeighbours ? kMaxBatch / 3 : kMaxBatch;
    for (int first = 0; first < count; first += chunkSize) {
        const int last = std::min(count, first + chunkSize);
        ShadingBatch chunk;
        chunk.attributes = batch.attributes;
        chunk.points.assign(batch.points.begin() + first, batch.points.begin() + last);
        chunk.incident.assign(batch.incident.begin() + first, batch.incident.begin() + last);
        chunk.depth.assign(batch.depth.begin() + first, batch.depth.begin() + last);
        if (batch.randomSeeds.size() == size_t(count))
            chunk.randomSeeds.assign(batch.randomSeeds.begin() + first,
                                     batch.randomSeeds.begin() + last);
        if (batch.outputs && batch.outputValues) {
            chunk.outputs = batch.outputs;
            chunk.outputValues = batch.outputValues + size_t(first) * OutputFloats(*batch.outputs);
        }
        if (withNeighbours) AddNeighbourPoints(&chunk, batch.neighbourRays.data() + first);
        ShadeChunk(*group, chunk, last - first, Ci + size_t(first) * ncomps_,
                   Oi + size_t(first) * ncomps_);
    }
}

void DepthShader::AddNeighbourPoints(ShadingBatch* chunk, const NeighbourRays* rays) {
    const int m = static_cast<int>(chunk->points.size()), n = 3 * m;
    if (neighbourPoints_.size() < size_t(2 * m)) neighbourPoints_.resize(2 * m);
    for (int axis = 0; axis < 2; ++axis) {
        for (int i = 0; i < m; ++i) {
            const SurfacePoint& centre = *chunk->points[i];
            const V3f& I = chunk->incident[i];
            SurfacePoint* neighbour = &neighbourPoints_[axis * m + i];
            V3f incident;
            rays_.differential += uint64_t(FindNeighbourPoint(
                scene_, centre, centre.P - I, I, rays[i].org[axis], rays[i].dir[axis],
                rays[i].tnear, rays[i].time, neighbour, &incident));
            chunk->points.push_back(neighbour);
            chunk->incident.push_back(incident);
            chunk->depth.push_back(chunk->depth[i]);
            // A neighbour point draws its own random numbers, but the same ones every render.
            if (chunk->randomSeeds.size() > size_t(i))
                chunk->randomSeeds.push_back(MixBits(chunk->randomSeeds[i] + axis + 1));
        }
    }
    // Point i's neighbours are m+i (along x) and 2m+i (along y). The neighbours get two
    // independent steps of their own, so that their derivatives (a texture footprint, a
    // derivative of a derivative) are defined too: m+i steps back to i (MakeStencil's backward
    // difference) and on to 2m+i; 2m+i steps to i, and back to m+i.
    BatchNeighbours& nb = neighbours_;
    nb.mainCount = m;
    nb.u.assign(n, -1);
    nb.v.assign(n, -1);
    nb.steps.assign(4 * size_t(n), 0.f);
    auto setStep = [&](int point, int direction, const Imath::V2f& step) {
        nb.steps[size_t(2 * direction) * n + point] = step.x;
        nb.steps[size_t(2 * direction + 1) * n + point] = step.y;
    };
    neighbourDu_.resize(m), neighbourDv_.resize(m);
    for (int i = 0; i < m; ++i) {
        const SurfacePoint& centre = *chunk->points[i];
        const Imath::V2f x = ParametricStep(centre, chunk->points[m + i]->P - centre.P);
        const Imath::V2f y = ParametricStep(centre, chunk->points[2 * m + i]->P - centre.P);
        nb.u[i] = m + i, nb.v[i] = 2 * m + i;
        nb.v[m + i] = 2 * m + i;
        nb.u[2 * m + i] = i;
        setStep(i, 0, x), setStep(i, 1, y);
        setStep(m + i, 1, y - x);
        setStep(2 * m + i, 0, -y);
        // du, dv: the extent in u and v of the pixel's footprint.
        neighbourDu_[i] = std::fabs(x.x) + std::fabs(y.x);
        neighbourDv_[i] = std::fabs(x.y) + std::fabs(y.y);
    }
}

void DepthShader::FillGlobals(const ShaderGroup& group, const ShadingBatch& chunk) {
    const int n = static_cast<int>(chunk.points.size());
    const M44f& currentFromWorld = shaders_.CurrentFromWorld();
    const M44f normalFromWorld = currentFromWorld.inverse().transposed();
    for (Planes* p : {&P_, &N_, &Ng_, &I_, &dPdu_, &dPdv_}) p->Reset(3, n);
    for (Planes* p : {&u_, &v_, &s_, &t_, &du_, &dv_}) p->Reset(1, n);
    Cs_.Reset(ncomps_, n);
    Os_.Reset(ncomps_, n);
    for (int i = 0; i < n; ++i) {
        const SurfacePoint& sp = *chunk.points[i];
        V3f v;
        currentFromWorld.multVecMatrix(sp.P, v), P_.Set(i, v);
        normalFromWorld.multDirMatrix(sp.N, v), N_.Set(i, v.normalized());
        normalFromWorld.multDirMatrix(sp.Ng, v), Ng_.Set(i, v.normalized());
        currentFromWorld.multDirMatrix(chunk.incident[i], v), I_.Set(i, v);
        currentFromWorld.multDirMatrix(sp.dPdu, v), dPdu_.Set(i, v);
        currentFromWorld.multDirMatrix(sp.dPdv, v), dPdv_.Set(i, v);
        u_.data[i] = sp.u, v_.data[i] = sp.v, s_.data[i] = sp.s, t_.data[i] = sp.t;
        for (int c = 0; c < ncomps_; ++c) {
            Cs_.data[size_t(c) * n + i] = sp.Cs[c];
            Os_.data[size_t(c) * n + i] = sp.Os[c];
        }
    }
    globals_ = sl::ShaderGlobals();
    globals_.n = n;
    globals_.P = P_.data.data(), globals_.N = N_.data.data(), globals_.Ng = Ng_.data.data();
    globals_.I = I_.data.data(), globals_.dPdu = dPdu_.data.data();
    globals_.dPdv = dPdv_.data.data();
    globals_.u = u_.data.data(), globals_.v = v_.data.data();
    globals_.du = du_.data.data(), globals_.dv = dv_.data.data();
    globals_.s = s_.data.data(), globals_.t = t_.data.data();
    globals_.Cs = Cs_.data.data(), globals_.Os = Os_.data.data();

    // Primitive variables bound to parameters; a point whose shape lacks one keeps zeros.
    primvars_.resize(group.boundPrimvars.size());
    std::vector<float> value;
    for (size_t k = 0; k < group.boundPrimvars.size(); ++k) {
        const std::string& name = group.boundPrimvars[k];
        const sl::ShaderParam* param = group.surface->Master().FindParam(name);
        const int width = param->type.Width(ncomps_) * std::max(1, param->type.arrayLength);
        primvars_[k].Reset(width, n);
        for (int i = 0; i < n; ++i) {
            if (!scene_.InterpolatePrimVar(*chunk.points[i], name, &value)) continue;
            for (int c = 0; c < width && c < int(value.size()); ++c)
                primvars_[k].data[size_t(c) * n + i] = value[c];
        }
        globals_.primvars.push_back({name, param->type, true, primvars_[k].data.data(), nullptr});
    }
}

void DepthShader::CopyOut(const sl::ShaderExecutor& executor, const char* name, int count,
                          float* pointMajor) {
    const sl::FloatArg out = executor.Output(name);
    if (!out.data) return;
    for (int i = 0; i < count; ++i)
        for (int c = 0; c < ncomps_; ++c) pointMajor[i * ncomps_ + c] = out.At(c, i);
}

sl::FloatArg DepthShader::GlobalPlanes(const std::string& name) {
    const std::pair<const char*, Planes*> globals[] = {
        {"P", &P_},       {"N", &N_},   {"Ng", &Ng_}, {"I", &I_},  {"dPdu", &dPdu_},
        {"dPdv", &dPdv_}, {"u", &u_},   {"v", &v_},   {"s", &s_},  {"t", &t_},
        {"du", &du_},     {"dv", &dv_}, {"Cs", &Cs_}, {"Os", &Os_}};
    for (const auto& [globalName, planes] : globals) {
        if (name != globalName || planes->n == 0) continue;
        return sl::FloatArg{planes->data.data(), int(planes->data.size()) / planes->n, true,
                            planes->n};
    }
    return sl::FloatArg{};
}

void DepthShader::CopyOutputs(const ShadingBatch& chunk, int count) {
    const int total = OutputFloats(*chunk.outputs);
    int offset = 0;
    for (const ShaderOutput& output : *chunk.outputs) {
        sl::FloatArg value = surfaceExecutor_.Output(output.name);
        if (!value.data) value = GlobalPlanes(output.name);
        const int width = std::min(output.width, value.width);
        for (int i = 0; i < count && value.data; ++i)
            for (int c = 0; c < width; ++c)
                chunk.outputValues[size_t(i) * total + offset + c] = value.At(c, i);
        offset += output.width;
    }
}

bool DepthShader::ReadsLightParameters(const ShaderGroup& group) {
    auto [it, isNew] = readsLightParameters_.try_emplace(&group, false);
    if (isNew) {
        for (const auto* instance : {&group.displacement, &group.surface, &group.atmosphere})
            if (*instance && sl::CallsBuiltin(**instance, "lightsource")) it->second = true;
    }
    return it->second;
}

void DepthShader::ShadeChunk(const ShaderGroup& group, const ShadingBatch& chunk, int mainCount,
                             float* Ci, float* Oi) {
    const int n = static_cast<int>(chunk.points.size());
    const bool withNeighbours = n > mainCount;
    FillGlobals(group, chunk);
    if (withNeighbours) {
        for (int i = 0; i < n; ++i) {
            du_.data[i] = neighbourDu_[i % mainCount];
            dv_.data[i] = neighbourDv_[i % mainCount];
        }
    }
    context_.Begin(chunk, globals_.P, group.surfaceRequest,
                   withNeighbours ? &neighbours_ : nullptr);
    context_.CaptureLightParameters(ReadsLightParameters(group));

    context_.SetMessageShader(sl::MessageSource::Displacement, group.displacement.get(),
                              &displacementExecutor_);
    if (group.displacement && displacementExecutor_.Run(*group.displacement, globals_, context_)) {
        // A ray tracer keeps the geometry: displacement changes the shading normal only.
        const sl::FloatArg N = displacementExecutor_.Output("N");
        if (N.data)
            for (int i = 0; i < n; ++i) N_.Set(i, V3f(N.At(0, i), N.At(1, i), N.At(2, i)));
    }
    context_.SetMessageShader(sl::MessageSource::Surface, group.surface.get(), &surfaceExecutor_);
    surfaceExecutor_.Run(*group.surface, globals_, context_);
    CopyOut(surfaceExecutor_, "Ci", mainCount, Ci);
    CopyOut(surfaceExecutor_, "Oi", mainCount, Oi);
    if (chunk.outputs && chunk.outputValues) CopyOutputs(chunk, mainCount);

    if (group.atmosphere) {
        // The atmosphere shader sees the surface's result as its input Ci, Oi.
        scratch_.assign(size_t(2) * ncomps_ * n, 0.f);
        float* ci = scratch_.data();
        float* oi = ci + size_t(ncomps_) * n;
        const sl::FloatArg surfaceCi = surfaceExecutor_.Output("Ci");
        const sl::FloatArg surfaceOi = surfaceExecutor_.Output("Oi");
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < ncomps_; ++c) {
                if (surfaceCi.data) ci[size_t(c) * n + i] = surfaceCi.At(c, i);
                if (surfaceOi.data) oi[size_t(c) * n + i] = surfaceOi.At(c, i);
            }
        globals_.Ci = ci, globals_.Oi = oi;
        context_.SetMessageShader(sl::MessageSource::Atmosphere, group.atmosphere.get(),
                                  &volumeExecutor_);
        if (volumeExecutor_.Run(*group.atmosphere, globals_, context_)) {
            CopyOut(volumeExecutor_, "Ci", mainCount, Ci);
            CopyOut(volumeExecutor_, "Oi", mainCount, Oi);
        }
    }
}

// The next hit along a traced ray past *tnear and before tfar that faces the ray (or is
// two-sided), as camera rays find theirs; *tnear moves past it. Each ray cast adds one to *rays.
class ShaderWorker : public ShadingWorker, public RayTracer {
  public:
    ShaderWorker(const FrameShaders& shaders, const RayScene& scene, const Camera& camera,
                 ShadingFiles& textures, const SurfaceShading& fallback)
        : shaders_(shaders),
          scene_(scene),
          camera_(camera),
          textures_(textures),
          fallback_(fallback.MakeWorker()),
          ncomps_(shaders.GetFrame().options.colorComponents) {}

    void Shade(const ShadingBatch& batch, float* Ci, float* Oi) override {
        AtDepth(0).Shade(batch, Ci, Oi);
    }
    bool WantsNeighbourRays(const Attributes* attributes) const override {
        const ShaderGroup* group = shaders_.Group(attributes);
        return group && group->surface && shaders_.WantsNeighbours(*group);
    }
    void TraceRays(int depth, const TracedRays& rays, float* colours) override;

  private:
    DepthShader& AtDepth(int depth) {
        while (int(depths_.size()) <= depth)
            depths_.push_back(std::make_unique<DepthShader>(shaders_, scene_, camera_, textures_,
                                                            *this, int(depths_.size()), *fallback_,
                                                            rays_));
        return *depths_[depth];
    }

    const FrameShaders& shaders_;
    const RayScene& scene_;
    const Camera& camera_;
    ShadingFiles& textures_;
    std::unique_ptr<ShadingWorker> fallback_;
    int ncomps_;
    std::vector<std::unique_ptr<DepthShader>> depths_;
};

// Like the camera rays of a tile: each ray's hits are shaded layer by layer, the hits of one
// layer in batches that share attributes (in order of first appearance, so that the result
// does not depend on threads), and composited front to back through transparent surfaces.
void ShaderWorker::TraceRays(int depth, const TracedRays& rays, float* colours) {
    DepthShader& shader = AtDepth(depth);
    TransparentLayers& layers = shader.Layers();
    const int count = static_cast<int>(rays.org.size()), nc = ncomps_;
    const bool haveNeighbours = rays.neighbours.size() == size_t(count);
    const bool haveTfar = rays.tfar.size() == size_t(count);
    std::fill(colours, colours + size_t(count) * nc, 0.f);
    std::vector<float> transmittance(size_t(count) * nc, 1.f), tnear = rays.tnear;
    std::vector<float> Ci, Oi;
    layers.Trace(
        count,
        [&](int r, SurfacePoint* sp, TransparentLayers::Hit* hit) {
            hit->tnear = tnear[size_t(r)];
            const float tfar =
                haveTfar ? rays.tfar[size_t(r)] : std::numeric_limits<float>::infinity();
            return NextVisibleHit(scene_, rays.org[size_t(r)], rays.dir[size_t(r)], rays.time, tfar,
                                  &tnear[size_t(r)], sp, &hit->t, &rays_.trace);
        },
        [&](int layer, const TransparentLayers::Group& group) {
            const Attributes* attributes = group.attributes;
            ShadingBatch batch;
            batch.attributes = attributes;
            const bool neighbours =
                haveNeighbours && !attributes->matte && WantsNeighbourRays(attributes);
            for (int k : group.members) {
                const TransparentLayers::Hit& hit = layers.HitAt(k);
                const int r = hit.ray;
                batch.points.push_back(&layers.PointAt(k));
                batch.incident.push_back(rays.dir[size_t(r)] * hit.t);
                V3f current;
                shaders_.CurrentFromWorld().multVecMatrix(layers.PointAt(k).P, current);
                batch.depth.push_back(current.z);
                if (rays.randomSeeds.size() == size_t(count))
                    batch.randomSeeds.push_back(MixBits(rays.randomSeeds[size_t(r)] + layer));
                if (!neighbours) continue;
                batch.neighbourRays.push_back(rays.neighbours[size_t(r)]);
                batch.neighbourRays.back().tnear = hit.tnear;
            }
            Ci.assign(group.members.size() * nc, 0.f);
            Oi.assign(group.members.size() * nc, 0.f);
            if (!attributes->matte) shader.Shade(batch, Ci.data(), Oi.data());
            for (size_t j = 0; j < group.members.size(); ++j) {
                const int r = layers.HitAt(group.members[j]).ray;
                // A matte object's opacity is the surface's Os, not a shader's output.
                const float* opacity =
                    attributes->matte ? layers.PointAt(group.members[j]).Os.data() : &Oi[j * nc];
                if (CompositeLayer(nc, &Ci[j * nc], opacity, attributes->matte,
                                   &colours[size_t(r) * nc],
                                   &transmittance[size_t(r) * nc]) < kNegligibleTransmittance)
                    layers.Stop(r);
            }
        });
}

class ShaderShading : public SurfaceShading {
  public:
    ShaderShading(const Frame& frame, const RayScene& scene, const Camera& camera,
                  Diagnostics& diagnostics)
        : shaders_(frame, diagnostics),
          scene_(scene),
          camera_(camera),
          fallback_(MakeDefaultSurfaceShading(frame.options.colorComponents)) {}

    std::unique_ptr<ShadingWorker> MakeWorker() const override {
        return std::make_unique<ShaderWorker>(shaders_, scene_, camera_, textures_, *fallback_);
    }

    // A global, or a non-string parameter of a surface shader of the frame (the first found).
    bool DescribeOutput(ShaderOutput* output) const override {
        const int ncomps = shaders_.GetFrame().options.colorComponents;
        struct Global {
            const char* name;
            int width;  // 0: a colour
        };
        static const Global kGlobals[] = {{"P", 3},    {"N", 3},    {"Ng", 3}, {"I", 3},
                                          {"dPdu", 3}, {"dPdv", 3}, {"u", 1},  {"v", 1},
                                          {"s", 1},    {"t", 1},    {"du", 1}, {"dv", 1},
                                          {"Cs", 0},   {"Os", 0},   {"Ci", 0}, {"Oi", 0}};
        for (const Global& global : kGlobals) {
            if (output->name != global.name) continue;
            output->isColor = global.width == 0;
            output->width = output->isColor ? ncomps : global.width;
            return true;
        }
        for (const SceneShape& shape : shaders_.GetFrame().shapes) {
            const ShaderGroup* group = shaders_.Group(shape.attributes.get());
            const sl::ShaderParam* param = group && group->surface
                                               ? group->surface->Master().FindParam(output->name)
                                               : nullptr;
            if (!param || param->type.base == sl::BaseType::String) continue;
            output->width = param->type.Width(ncomps) * std::max(1, param->type.arrayLength);
            output->isColor = param->type.base == sl::BaseType::Color;
            return true;
        }
        return false;
    }

    bool FinishFrame(Diagnostics& diagnostics) override {
        return textures_.pointClouds.WriteBaked(diagnostics);
    }

  private:
    FrameShaders shaders_;
    const RayScene& scene_;
    const Camera& camera_;
    mutable ShadingFiles textures_;  // thread-safe
    std::unique_ptr<SurfaceShading> fallback_;
};

}  // namespace

std::unique_ptr<SurfaceShading> MakeShaderShading(const Frame& frame, const RayScene& scene,
                                                  const Camera& camera, Diagnostics& diagnostics) {
    return std::make_unique<ShaderShading>(frame, scene, camera, diagnostics);
}

}  // namespace gonio
