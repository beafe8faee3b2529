#pragma once
// The micro BRDF of the photon tracer (DESIGN.md "Radiometry of the photon tracer"): normalised
// Phong, f_m = kd·Cs/π + ks·(n+2)/(2π)·cosⁿα, α the angle between ω_o and the mirror direction,
// importance-sampled by picking the lobe with probability kd/(kd+ks) (thesis eqs. 3.16-3.17).

#include <Imath/ImathVec.h>

#include "base/diagnostics.h"
#include "renderer/scene/attributes.h"

namespace gonio {

struct MicroBrdf {
    float kd = 1, ks = 0, exponent = 10;

    // The specular lobe value ks·(n+2)/(2π)·cosⁿα (1/sr; the diffuse one is kd·Cs/π) and the
    // lobe-mixture pdf per steradian of ωo (all unit, n the side's normal, wi towards the
    // light), sharing one cosⁿα. Directions below the surface keep their pdf: the sampler may
    // pick them and the tracer absorbs those photons, which is what makes the normalised Phong
    // lose energy at grazing incidence.
    struct Value {
        float specular, pdf;
    };
    Value Evaluate(const Imath::V3f& n, const Imath::V3f& wi, const Imath::V3f& wo) const;

    struct Sampled {
        Imath::V3f wo;
        Value value;  // Evaluate(n, wi, wo), to rounding
    };
    // Draws ωo from uniform numbers u0 (lobe), u1, u2 (direction), with its value and pdf.
    Sampled Sample(const Imath::V3f& n, const Imath::V3f& wi, float u0, float u1, float u2) const;

  private:
    // The Value for a known cosⁿα.
    Value ValueWithLobe(const Imath::V3f& n, const Imath::V3f& wo, float lobe) const;
};

// kd, ks and the exponent of a primitive from its surface shader instance (Kd, Ks, exponent or
// 1/roughness, with the standard shaders' declared defaults) and `Attribute "brdflight"`.
// Reports an unknown shader once and reads its Kd/Ks/roughness with matte's defaults.
MicroBrdf MicroBrdfFromAttributes(const Attributes& attributes, Diagnostics& diagnostics);

// A unit vector from spherical angles about the frame (t, b, n).
Imath::V3f FromLocal(const Imath::V3f& n, float cosTheta, float phi);

}  // namespace gonio
