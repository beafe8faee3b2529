#pragma once
// The micro BRDF of the photon tracer (DESIGN.md "Radiometry of the photon tracer"): normalised
// Phong, f_m = kd·Cs/π + ks·(n+2)/(2π)·cosⁿα, α the angle between ω_o and the mirror direction,
// importance-sampled by picking the lobe with probability kd/(kd+ks) (thesis eqs. 3.16-3.17).

#include <Imath/ImathVec.h>

#include "base/diagnostics.h"
#include "renderer/scene/attributes.h"
#include "shaderlang/shading_system.h"

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

// kd, ks and the exponent of a primitive: its surface shader instance's Kd, Ks and exponent (or
// 1/roughness), as the RIB sets them or as the shader declares them by default (a parameter
// the shader lacks is 0), then `Attribute "brdflight"`. A shader with neither Kd nor Ks is
// reported once and taken as matte (Kd 1).
MicroBrdf MicroBrdfFromShader(const sl::ShaderInstance& surface, const Attributes& attributes,
                              Diagnostics& diagnostics);

// A unit vector from spherical angles about the frame (t, b, n).
Imath::V3f FromLocal(const Imath::V3f& n, float cosTheta, float phi);

}  // namespace gonio
