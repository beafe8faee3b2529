#include "renderer/pathtrace/path_bsdf.h"

#include <algorithm>

#include "base/math.h"

namespace gonio {

void VertexBsdf::Begin(const PathMaterial& material, const ShadingFrame& frame, const float* Cs,
                       int ncomps, const Imath::V3f& wo) {
    material_ = &material;
    frame_ = frame;
    Cs_ = Cs;
    ncomps_ = ncomps;
    wo_ = wo;
    localWo_ = frame.ToLocal(wo);
    if (material.splat) {
        material.splat->sampler->Prepare(localWo_, &mixture_);
        grdValues_.resize(size_t(material.splat->file->splats->NumComponents()));
    }
}

void VertexBsdf::SplatValue(const Imath::V3f& localWi, float* f, double* pdf) const {
    const SplatSurface& splat = *material_->splat;
    *pdf = splat.sampler->Pdf(mixture_, localWi, grdValues_.data());
    const int n = int(grdValues_.size());
    float mean = 0;
    for (float v : grdValues_) mean += v / n;
    // The grid's components become the colour's as brdf() makes them (brdfsim EvalPlanes):
    // copied when the counts agree, else one grey value.
    for (int c = 0; c < ncomps_; ++c)
        f[c] = splat.scale * Cs_[c] * (n == ncomps_ ? grdValues_[c] : mean);
}

void VertexBsdf::PhongValue(float specular, float* f) const {
    const std::vector<float>& tint = material_->specularColor;
    for (int c = 0; c < ncomps_; ++c)
        f[c] = material_->phong.kd * Cs_[c] / kPiF +
               specular * (tint.empty() ? 1.0f : tint[size_t(c)]);
}

double VertexBsdf::Eval(const Imath::V3f& wi, float* f) const {
    const Imath::V3f& n = frame_.n;
    if (material_->splat) {
        double pdf = 0;
        SplatValue(frame_.ToLocal(wi), f, &pdf);
        return pdf;
    }
    const MicroBrdf& phong = material_->phong;
    // MicroBrdf fixes its first direction and samples the second: here wo, then wi.
    const MicroBrdf::Value value = phong.Evaluate(n, wo_, wi);
    if (n.dot(wi) > 0)
        PhongValue(value.specular, f);
    else
        std::fill(f, f + ncomps_, 0.0f);
    return value.pdf;
}

bool VertexBsdf::Sample(float u0, float u1, float u2, uint64_t seed, Imath::V3f* wi, float* f,
                        double* pdf) const {
    if (material_->splat) {
        Imath::V3f local;
        if (!material_->splat->sampler->Sample(mixture_, u0, seed, &local)) return false;
        *wi = frame_.ToWorld(local).normalized();
        SplatValue(local, f, pdf);
        return *pdf > 0;
    }
    const MicroBrdf& phong = material_->phong;
    if (!(phong.kd + phong.ks > 0)) return false;
    const MicroBrdf::Sampled sampled = phong.Sample(frame_.n, wo_, u0, u1, u2);
    *wi = sampled.wo;
    // The specular lobe reaches below the surface at grazing angles: those samples are lost.
    if (!(frame_.n.dot(*wi) > 0) || !(sampled.value.pdf > 0)) return false;
    PhongValue(sampled.value.specular, f);
    *pdf = sampled.value.pdf;
    return true;
}

}  // namespace gonio
