#pragma once
// Leaf optics for the photon tracer (issue 18; the thesis's future work, §7.2): a thin blade with
// a waxy dielectric cuticle over a diffusely scattering, partly transparent interior.
//
//   f_s(ωi, ωo) = F(ωi·h) D(h) G₂(ωi, ωo) / (4 μi μo)        cuticle, ωo on the side of ωi
//   f_d(ωi, ωo) = (1 − E(μi)) (1 − E(|μo|)) / (π (1 − Ē))      times ρ_k (same side) or τ_k
//
// F is the unpolarised Fresnel reflectance of a dielectric of index η (Walter et al. 2007,
// eq. 22), D and G₂ the GGX distribution and height-correlated Smith shadowing of roughness α
// (Walter et al. 2007, eqs. 33-34; Heitz 2014, "Understanding the masking-shadowing function",
// eq. 99). E(μ) = ∫ f_s μo dωo is the cuticle's directional albedo and Ē = 2∫E(μ)μ dμ its
// hemispherical mean: the diffuse part gets the energy the cuticle does not reflect, coupled as
// in Kelemen & Szirmay-Kalos 2001 ("A microfacet based coupled specular-matte BRDF model"),
// which keeps f reciprocal and makes the albedos exact:
//   r(μi) = E(μi) + (1 − E(μi)) ρ,   t(μi) = (1 − E(μi)) τ,   a = (1 − E(μi)) (1 − ρ − τ).
// A blade with ρ + τ = 1 absorbs nothing at any incidence (the white furnace), and η = 1 (no
// cuticle, E ≡ 0) is the bi-Lambertian leaf of radiative transfer (Ross 1981).
//
// Sampling picks the cuticle, diffuse reflection or diffuse transmission with probabilities
// E(μi) : (1−E)ρ̄ : (1−E)τ̄ (ρ̄, τ̄ the means over the colour components), then draws h from the
// GGX distribution of visible normals (Heitz 2018, "Sampling the GGX distribution of visible
// normals", JCGT 7(4)) and reflects, or draws a cosine-weighted direction on the lit or the far
// side. The pdf is that whole mixture, so a reflected cuticle direction below the blade counts
// as a transmission sample and nothing is lost.

#include <Imath/ImathVec.h>

#include <vector>

namespace gonio {

struct LeafParams {
    float eta = 1.45f;                       // cuticle wax (Vanderbilt & Grant 1985: 1.4-1.5)
    float roughness = 0.3f;                  // GGX α of the cuticle
    std::vector<float> reflectance{0.5f};    // ρ_k of the interior, per colour component
    std::vector<float> transmittance{0.3f};  // τ_k; one value serves every component
};

class LeafOptics {
  public:
    explicit LeafOptics(const LeafParams& params);

    // f = specular + diffuse·(transmitted ? τ_k : ρ_k) (1/sr) and the mixture pdf per steradian
    // of ωo. n is the normal on the side of ωi (unit vectors, wi towards the light).
    struct Value {
        float specular = 0, diffuse = 0, pdf = 0;
        bool transmitted = false;
    };
    Value Evaluate(const Imath::V3f& n, const Imath::V3f& wi, const Imath::V3f& wo) const;

    struct Sampled {
        Imath::V3f wo;
        Value value;
    };
    Sampled Sample(const Imath::V3f& n, const Imath::V3f& wi, float u0, float u1, float u2) const;

    float Reflectance(int component) const { return Pick(params_.reflectance, component); }
    float Transmittance(int component) const { return Pick(params_.transmittance, component); }
    // E(μ), the cuticle's directional albedo (tabulated, linear in μ), and Ē.
    float CuticleAlbedo(float mu) const;
    float MeanCuticleAlbedo() const { return meanAlbedo_; }
    const LeafParams& Params() const { return params_; }

    // The cuticle lobe alone, for the table and the tests: F D G₂ / (4 μi μo) in the local frame
    // of the normal (z up), both directions above it.
    float CuticleLobe(const Imath::V3f& wi, const Imath::V3f& wo) const;

  private:
    static float Pick(const std::vector<float>& v, int k) {
        return v[static_cast<size_t>(k) < v.size() ? k : v.size() - 1];
    }
    float Fresnel(float cosine) const;
    float Ggx(float cosThetaH) const;
    float Lambda(float cosTheta) const;
    // A GGX normal visible from wi (local frame, wi.z > 0) from two uniform numbers.
    Imath::V3f SampleVisibleNormal(const Imath::V3f& wi, float u1, float u2) const;
    // The cuticle's directional albedo by quadrature over the visible normals.
    float IntegrateAlbedo(float mu) const;

    LeafParams params_;
    float meanReflectance_ = 0, meanTransmittance_ = 0;
    std::vector<float> albedo_;  // E at μ = j/(size−1)
    float meanAlbedo_ = 0;
};

}  // namespace gonio
