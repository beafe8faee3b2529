#pragma once
// The BSDF of a path vertex, from the surface's shader (docs/path-tracing.md):
// * the normalised Phong of the photon tracer (renderer/photon/micro_brdf.h: Kd, Ks and
//   roughness or exponent of matte, plastic, ...), f = Kd·Cs/π + Ks·S·(n+2)/(2π)·cosⁿα with S
//   the shader's specularcolor, sampled by lobe and importance (thesis eqs. 3.16-3.17);
// * a splat BRDF, for surfaces whose shader calls brdf("x.grd", ...): f = Kb·Cs·f_grd, sampled
//   from the splats themselves (brdfsim/splat_sampler.h).
// Paths start at the camera, so the direction fixed at a vertex is the one towards the viewer
// (wo) and the sampled one goes towards the light (wi). Phong is reciprocal; the splat BRDF is
// evaluated as f_grd(ω' = wo → ω = wi), its arguments swapped by Helmholtz reciprocity, which
// the splat estimate keeps to within its noise (DESIGN.md "Reciprocity"): that is the argument
// order whose splat mixture the sampler draws from.

#include <Imath/ImathVec.h>

#include <memory>
#include <vector>

#include "brdfsim/grd_file.h"
#include "brdfsim/splat_sampler.h"
#include "renderer/photon/micro_brdf.h"

namespace gonio {

// Unit vectors: n the normal on the side of the viewer, x the direction of anisotropy.
struct ShadingFrame {
    Imath::V3f x, y, n;
    Imath::V3f ToLocal(const Imath::V3f& w) const { return {w.dot(x), w.dot(y), w.dot(n)}; }
    Imath::V3f ToWorld(const Imath::V3f& w) const { return x * w.x + y * w.y + n * w.z; }
};

// A brdf() surface: the file, its sampler, and how the shader orients the BRDF's x axis.
struct SplatSurface {
    std::shared_ptr<const GrdFile> file;
    std::shared_ptr<const SplatSampler> sampler;
    enum class Axis { kDPdu, kDPdv, kAcrossDPdu, kAcrossDPdv, kDirection };
    Axis axis = Axis::kDPdu;
    float angle = 0;       // radians about n, from the axis (grass.sl's "angle")
    Imath::V3f direction;  // world space, for kDirection
    float scale = 1;       // the shader's Kb
};

struct PathMaterial {
    MicroBrdf phong;
    // The shader's specularcolor, which tints the Phong lobe (plastic's Ks·specularcolor):
    // ncomps values, or empty for white.
    std::vector<float> specularColor;
    std::shared_ptr<const SplatSurface> splat;  // null: phong
};

// The BSDF at one vertex for one viewing direction. Reused from vertex to vertex (the splat
// mixture keeps its storage).
class VertexBsdf {
  public:
    // wo: unit, towards the viewer; Cs: ncomps values.
    void Begin(const PathMaterial& material, const ShadingFrame& frame, const float* Cs, int ncomps,
               const Imath::V3f& wo);
    // f(wo, wi) into ncomps floats; returns the pdf of Sample drawing wi (per steradian).
    double Eval(const Imath::V3f& wi, float* f) const;
    // Draws wi (unit, world) with f and pdf; false when the sample is lost (below the surface,
    // or nothing to reflect).
    bool Sample(float u0, float u1, float u2, uint64_t seed, Imath::V3f* wi, float* f,
                double* pdf) const;

  private:
    void SplatValue(const Imath::V3f& localWi, float* f, double* pdf) const;
    // The Phong value for one specular lobe value, above the surface.
    void PhongValue(float specular, float* f) const;

    const PathMaterial* material_ = nullptr;
    ShadingFrame frame_;
    const float* Cs_ = nullptr;
    int ncomps_ = 0;
    Imath::V3f wo_, localWo_;
    SplatMixture mixture_;
    mutable std::vector<float> grdValues_;
};

}  // namespace gonio
