// The shading language in the render loop: a batch of points that share an attribute state is
// laid out component-major in current (camera) space and run through its displacement, surface
// and atmosphere shaders; the lights are run once per batch by the RenderContext.

#include <algorithm>

#include "image/texture_lookup.h"
#include "render/camera.h"
#include "render/ray_scene.h"
#include "shading/frame_shaders.h"
#include "shading/render_context.h"
#include "shading/surface_shading.h"

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

class ShaderWorker : public ShadingWorker {
  public:
    ShaderWorker(const FrameShaders& shaders, const RayScene& scene, const Camera& camera,
                 TextureLookup& textures, const SurfaceShading& fallback)
        : shaders_(shaders),
          scene_(scene),
          context_(shaders, scene, camera, textures, lightExecutor_),
          fallback_(fallback.MakeWorker()),
          ncomps_(shaders.GetFrame().options.colorComponents) {}

    void Shade(const ShadingBatch& batch, float* Ci, float* Oi) override;

  private:
    void ShadeChunk(const ShaderGroup& group, const ShadingBatch& chunk, float* Ci, float* Oi);
    void FillGlobals(const ShaderGroup& group, const ShadingBatch& chunk);
    void CopyOut(const sl::ShaderExecutor& executor, const char* name, int n, float* pointMajor);

    const FrameShaders& shaders_;
    const RayScene& scene_;
    sl::ShaderExecutor surfaceExecutor_, lightExecutor_, volumeExecutor_;
    RenderContext context_;
    std::unique_ptr<ShadingWorker> fallback_;
    int ncomps_;
    sl::ShaderGlobals globals_;
    Planes P_, N_, Ng_, I_, dPdu_, dPdv_, u_, v_, s_, t_, Cs_, Os_, du_, dv_;
    std::vector<Planes> primvars_;
    std::vector<float> scratch_;
};

void ShaderWorker::Shade(const ShadingBatch& batch, float* Ci, float* Oi) {
    const ShaderGroup* group = shaders_.Group(batch.attributes);
    if (!group || !group->surface) {
        fallback_->Shade(batch, Ci, Oi);
        return;
    }
    const int count = static_cast<int>(batch.points.size());
    for (int first = 0; first < count; first += kMaxBatch) {
        const int last = std::min(count, first + kMaxBatch);
        ShadingBatch chunk;
        chunk.attributes = batch.attributes;
        chunk.points.assign(batch.points.begin() + first, batch.points.begin() + last);
        chunk.incident.assign(batch.incident.begin() + first, batch.incident.begin() + last);
        chunk.depth.assign(batch.depth.begin() + first, batch.depth.begin() + last);
        ShadeChunk(*group, chunk, Ci + size_t(first) * ncomps_, Oi + size_t(first) * ncomps_);
    }
}

void ShaderWorker::FillGlobals(const ShaderGroup& group, const ShadingBatch& chunk) {
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

void ShaderWorker::CopyOut(const sl::ShaderExecutor& executor, const char* name, int n,
                           float* pointMajor) {
    const sl::FloatArg out = executor.Output(name);
    if (!out.data) return;
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < ncomps_; ++c) pointMajor[i * ncomps_ + c] = out.At(c, i);
}

void ShaderWorker::ShadeChunk(const ShaderGroup& group, const ShadingBatch& chunk, float* Ci,
                              float* Oi) {
    const int n = static_cast<int>(chunk.points.size());
    FillGlobals(group, chunk);
    context_.Begin(chunk, globals_.P, group.surfaceRequest);

    if (group.displacement && volumeExecutor_.Run(*group.displacement, globals_, context_)) {
        // A ray tracer keeps the geometry: displacement changes the shading normal only.
        const sl::FloatArg N = volumeExecutor_.Output("N");
        if (N.data)
            for (int i = 0; i < n; ++i) N_.Set(i, V3f(N.At(0, i), N.At(1, i), N.At(2, i)));
    }
    surfaceExecutor_.Run(*group.surface, globals_, context_);
    CopyOut(surfaceExecutor_, "Ci", n, Ci);
    CopyOut(surfaceExecutor_, "Oi", n, Oi);

    if (group.atmosphere) {
        // The atmosphere shader sees the surface's result as its input Ci, Oi.
        scratch_.assign(size_t(2) * ncomps_ * n, 0.f);
        float* ci = scratch_.data();
        float* oi = ci + size_t(ncomps_) * n;
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < ncomps_; ++c) {
                ci[size_t(c) * n + i] = Ci[i * ncomps_ + c];
                oi[size_t(c) * n + i] = Oi[i * ncomps_ + c];
            }
        globals_.Ci = ci, globals_.Oi = oi;
        if (volumeExecutor_.Run(*group.atmosphere, globals_, context_)) {
            CopyOut(volumeExecutor_, "Ci", n, Ci);
            CopyOut(volumeExecutor_, "Oi", n, Oi);
        }
    }
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

  private:
    FrameShaders shaders_;
    const RayScene& scene_;
    const Camera& camera_;
    mutable TextureLookup textures_;  // thread-safe
    std::unique_ptr<SurfaceShading> fallback_;
};

}  // namespace

std::unique_ptr<SurfaceShading> MakeShaderShading(const Frame& frame, const RayScene& scene,
                                                  const Camera& camera, Diagnostics& diagnostics) {
    return std::make_unique<ShaderShading>(frame, scene, camera, diagnostics);
}

}  // namespace gonio
