#pragma once
// The micro BRDF of the photon tracer (DESIGN.md "Radiometry of the photon tracer"): normalised
// Phong, f_m = kd·Cs/π + ks·(n+2)/(2π)·cosⁿα, α the angle between ω_o and the mirror direction,
// importance-sampled by picking the lobe with probability kd/(kd+ks) (thesis eqs. 3.16-3.17).
// With `leaf` set it is instead the leaf optics of leaf_optics.h (cuticle, diffuse reflection,
// diffuse transmission through the blade), selected by Attribute "brdflight" "string model".

#include <Imath/ImathVec.h>

#include <memory>

#include "base/diagnostics.h"
#include "renderer/scene/attributes.h"
#include "shaderlang/shading_system.h"

namespace gonio {

class LeafOptics;

struct MicroBrdf {
    float kd = 1, ks = 0, exponent = 10;
    // The leaf model (shared: every shape of one attribute state holds the same tables); null
    // for the Phong model, whose fields above it ignores.
    std::shared_ptr<const LeafOptics> leaf = nullptr;

    // The specular lobe value ks·(n+2)/(2π)·cosⁿα (1/sr; the diffuse one is kd·Cs/π) and the
    // lobe-mixture pdf per steradian of ωo (all unit, n the side's normal, wi towards the
    // light), sharing one cosⁿα. Directions below the surface keep their pdf: the sampler may
    // pick them and the tracer absorbs those photons, which is what makes the normalised Phong
    // lose energy at grazing incidence.
    // For the leaf model `specular` is the cuticle lobe, `diffuse` the colourless diffuse
    // factor that Component multiplies by ρ_k or τ_k, and `transmitted` says ωo is on the far
    // side of the blade (n·ωo < 0); the Phong model leaves them at 0 and false.
    struct Value {
        float specular, pdf;
        float diffuse = 0;
        bool transmitted = false;
    };
    Value Evaluate(const Imath::V3f& n, const Imath::V3f& wi, const Imath::V3f& wo) const;

    struct Sampled {
        Imath::V3f wo;
        Value value;  // Evaluate(n, wi, wo), to rounding
    };
    // Draws ωo from uniform numbers u0 (lobe), u1, u2 (direction), with its value and pdf.
    Sampled Sample(const Imath::V3f& n, const Imath::V3f& wi, float u0, float u1, float u2) const;

    // f for colour component k (1/sr) at a sampled or evaluated value; cs is the surface colour
    // there (Phong: kd·cs/π + specular; the leaf has its own ρ_k, τ_k and ignores cs).
    float Component(const Value& value, int k, float cs) const;
    // Whether ωo on the far side of the surface is light going on (the leaf) rather than a
    // photon scattered into the surface and absorbed (Phong).
    bool Transmits() const { return leaf != nullptr; }

  private:
    // The Value for a known cosⁿα.
    Value ValueWithLobe(const Imath::V3f& n, const Imath::V3f& wo, float lobe) const;
};

// kd, ks and the exponent of a primitive: its surface shader instance's Kd, Ks and exponent (or
// 1/roughness), as the RIB sets them or as the shader declares them by default (a parameter
// the shader lacks is 0), then `Attribute "brdflight"`. A shader with neither Kd nor Ks is
// reported once and taken as matte (Kd 1). `Attribute "brdflight" "string model" "leaf"` makes
// it the leaf model instead, from that attribute's eta, roughness, reflectance and
// transmittance (docs/brdflight.md); a value out of range, or another model, is an error at
// its parameter and leaves the Phong model.
MicroBrdf MicroBrdfFromShader(const sl::ShaderInstance& surface, const Attributes& attributes,
                              Diagnostics& diagnostics);

// A unit vector from spherical angles about the frame (t, b, n).
Imath::V3f FromLocal(const Imath::V3f& n, float cosTheta, float phi);
// The tangents t, b of that frame (t × b = n, unit n).
void OrthonormalBasis(const Imath::V3f& n, Imath::V3f* t, Imath::V3f* b);

}  // namespace gonio
