#include "renderer/photon/leaf_optics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "base/math.h"
#include "renderer/photon/micro_brdf.h"

namespace gonio {
namespace {

using Imath::V3f;

// E(μ) at 65 evenly spaced μ, each by a 96 × 96 midpoint rule over the visible normals: the
// integrand F G₂/G₁ is continuous and bounded by 1, so both the rule and the linear
// interpolation between nodes stay near 1e-4 (tests/photon/leaf_optics_test.cpp measures it).
constexpr int kAlbedoNodes = 65;
constexpr int kAlbedoSide = 96;
constexpr float kMinCosine = 1e-4f;  // μ below this is taken as this (Λ grows without bound)

float Mean(const std::vector<float>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0f) / float(v.size());
}

}  // namespace

LeafOptics::LeafOptics(const LeafParams& params)
    : params_(params),
      meanReflectance_(Mean(params.reflectance)),
      meanTransmittance_(Mean(params.transmittance)) {
    albedo_.resize(kAlbedoNodes);
    for (int j = 0; j < kAlbedoNodes; ++j)
        albedo_[j] = IntegrateAlbedo(float(j) / (kAlbedoNodes - 1));
    // Ē = 2∫E(μ)μ dμ of the interpolant: Simpson's rule is exact on each (quadratic) segment.
    double mean = 0;
    const double h = 1.0 / (kAlbedoNodes - 1);
    for (int j = 0; j + 1 < kAlbedoNodes; ++j) {
        const double a = j * h, b = a + h;
        mean += h / 6 *
                (albedo_[j] * a + 4 * 0.5 * (albedo_[j] + albedo_[j + 1]) * (a + b) / 2 +
                 albedo_[j + 1] * b);
    }
    meanAlbedo_ = static_cast<float>(2 * mean);
}

float LeafOptics::Fresnel(float c) const {
    // Walter et al. 2007, eq. 22 (unpolarised dielectric, light arriving from the air side).
    const float eta = params_.eta;
    const float g2 = eta * eta - 1 + c * c;
    if (g2 <= 0) return 1;
    const float g = std::sqrt(g2);
    const float a = (g - c) / (g + c);
    const float b = (c * (g + c) - 1) / (c * (g - c) + 1);
    return 0.5f * a * a * (1 + b * b);
}

float LeafOptics::Ggx(float cosThetaH) const {
    if (cosThetaH <= 0) return 0;
    const float a2 = params_.roughness * params_.roughness;
    const float d = cosThetaH * cosThetaH * (a2 - 1) + 1;
    return a2 / (kPiF * d * d);  // Walter et al. 2007, eq. 33
}

float LeafOptics::Lambda(float cosTheta) const {
    const float c = std::max(cosTheta, kMinCosine);
    const float tan2 = (1 - c * c) / (c * c);
    const float a2 = params_.roughness * params_.roughness;
    return 0.5f * (std::sqrt(1 + a2 * tan2) - 1);  // Heitz 2014, eq. 72 for GGX
}

float LeafOptics::CuticleLobe(const V3f& wi, const V3f& wo) const {
    if (wi.z <= 0 || wo.z <= 0) return 0;
    const V3f h = (wi + wo).normalized();
    const float g2 = 1 / (1 + Lambda(wi.z) + Lambda(wo.z));  // height-correlated Smith
    return Fresnel(wi.dot(h)) * Ggx(h.z) * g2 / (4 * wi.z * wo.z);
}

V3f LeafOptics::SampleVisibleNormal(const V3f& wi, float u1, float u2) const {
    // Heitz 2018, listing 1: stretch to the hemisphere configuration, sample the projected
    // disk (its far half squeezed by the visible fraction), unstretch.
    const float alpha = params_.roughness;
    const V3f vh = V3f(alpha * wi.x, alpha * wi.y, wi.z).normalized();
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const V3f t1 = lensq > 0 ? V3f(-vh.y, vh.x, 0) / std::sqrt(lensq) : V3f(1, 0, 0);
    const V3f t2 = vh.cross(t1);
    const float r = std::sqrt(u1), phi = 2 * kPiF * u2;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1 + vh.z);
    const float p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * r * std::sin(phi);
    const V3f nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2)) * vh;
    return V3f(alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)).normalized();
}

float LeafOptics::IntegrateAlbedo(float mu) const {
    // E(μ) = E_{h ~ visible normals}[F(ωi·h) G₂/G₁(ωi) 1(ωo up)]: f_s μo over the pdf
    // G₁ D / (4 μi) of the reflected direction.
    const float c = std::max(mu, kMinCosine);
    const V3f wi(std::sqrt(1 - c * c), 0, c);
    const float g1 = 1 / (1 + Lambda(c));
    double sum = 0;
    for (int i = 0; i < kAlbedoSide; ++i) {
        for (int j = 0; j < kAlbedoSide; ++j) {
            const V3f h =
                SampleVisibleNormal(wi, (i + 0.5f) / kAlbedoSide, (j + 0.5f) / kAlbedoSide);
            const V3f wo = 2 * wi.dot(h) * h - wi;
            if (wo.z <= 0) continue;
            sum += Fresnel(wi.dot(h)) / (1 + Lambda(c) + Lambda(wo.z)) / g1;
        }
    }
    return static_cast<float>(sum / (kAlbedoSide * kAlbedoSide));
}

float LeafOptics::CuticleAlbedo(float mu) const {
    const float x = std::clamp(mu, 0.0f, 1.0f) * (kAlbedoNodes - 1);
    const int j = std::min(static_cast<int>(x), kAlbedoNodes - 2);
    return albedo_[j] + (x - j) * (albedo_[j + 1] - albedo_[j]);
}

LeafOptics::Value LeafOptics::Evaluate(const V3f& n, const V3f& wi, const V3f& wo) const {
    const float mui = n.dot(wi), muo = n.dot(wo);
    if (mui <= 0 || muo == 0) return {};
    const float ei = CuticleAlbedo(mui);
    const float ws = ei, wr = (1 - ei) * meanReflectance_, wt = (1 - ei) * meanTransmittance_;
    const float total = ws + wr + wt;
    // Lobe probabilities; a black blade without cuticle samples the cosine (and absorbs).
    const float ps = total > 0 ? ws / total : 0, pr = total > 0 ? wr / total : 1;
    const float pt = total > 0 ? wt / total : 0;
    Value v;
    v.transmitted = muo < 0;
    v.diffuse = (1 - ei) * (1 - CuticleAlbedo(std::abs(muo))) / (kPiF * (1 - meanAlbedo_));
    v.pdf = (v.transmitted ? pt : pr) * std::abs(muo) / kPiF;
    const V3f sum = wi + wo;
    const float length = sum.length();
    if (ps > 0 && length > 0) {
        const V3f h = sum / length;
        const float cosH = n.dot(h);
        // Any ωo, above or below, is the mirror image of ωi about h = (ωi+ωo)/|ωi+ωo|: the
        // visible-normal density G₁ max(0, ωi·h) D / μi over the Jacobian 4 ωi·h.
        v.pdf += ps * Ggx(cosH) / ((1 + Lambda(mui)) * 4 * mui);
        if (!v.transmitted) {
            v.specular =
                Fresnel(wi.dot(h)) * Ggx(cosH) / (1 + Lambda(mui) + Lambda(muo)) / (4 * mui * muo);
        }
    }
    return v;
}

LeafOptics::Sampled LeafOptics::Sample(const V3f& n, const V3f& wi, float u0, float u1,
                                       float u2) const {
    const float mui = n.dot(wi);
    const float ei = CuticleAlbedo(mui);
    const float ws = ei, wr = (1 - ei) * meanReflectance_, wt = (1 - ei) * meanTransmittance_;
    const float pick = u0 * (ws + wr + wt);
    V3f wo;
    if (pick < ws) {
        V3f t, s;
        OrthonormalBasis(n, &t, &s);
        const V3f local(wi.dot(t), wi.dot(s), mui);
        const V3f h = SampleVisibleNormal(local, u1, u2);
        const V3f hw = h.x * t + h.y * s + h.z * n;
        wo = 2 * wi.dot(hw) * hw - wi;
    } else {
        // cosine-weighted on the lit side, or through the blade onto the far side
        wo = FromLocal(pick < ws + wr || wt <= 0 ? n : -n, std::sqrt(1 - u1), 2 * kPiF * u2);
    }
    return {wo, Evaluate(n, wi, wo)};
}

}  // namespace gonio
