#include "renderer/photon/micro_brdf.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/math.h"

namespace gonio {
namespace {

using Imath::V3f;

V3f Mirror(const V3f& n, const V3f& wi) { return 2 * n.dot(wi) * n - wi; }

// The last word of a parameter token: "uniform float Kd" and "Kd" both name Kd.
std::string ParamName(const std::string& token) {
    const size_t space = token.find_last_of(' ');
    return space == std::string::npos ? token : token.substr(space + 1);
}

bool FindNumber(const ParamList& params, const char* name, float* value) {
    for (const Param& p : params) {
        if (!p.isString && !p.numbers.empty() && ParamName(p.token) == name) {
            *value = static_cast<float>(p.numbers[0]);
            return true;
        }
    }
    return false;
}

struct ShaderDefaults {
    const char* name;
    float kd, ks, roughness;
};

// The declared defaults of the RISpec standard surface shaders (RISpec Appendix A).
constexpr ShaderDefaults kStandardSurfaces[] = {
    {"matte", 1.0f, 0.0f, 0.1f},          {"plastic", 0.5f, 0.5f, 0.1f},
    {"paintedplastic", 0.5f, 0.5f, 0.1f}, {"metal", 0.0f, 1.0f, 0.1f},
    {"shinymetal", 0.0f, 1.0f, 0.1f},
};

}  // namespace

V3f FromLocal(const V3f& n, float cosTheta, float phi) {
    // Duff et al. 2017, "Building an orthonormal basis, revisited": branchless and continuous.
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    const V3f t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const V3f s(b, sign + n.y * n.y * a, -n.y);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return (t * std::cos(phi) + s * std::sin(phi)) * sinTheta + n * cosTheta;
}

MicroBrdf::Value MicroBrdf::Evaluate(const V3f& n, const V3f& wi, const V3f& wo) const {
    const float cosAlpha = Mirror(n, wi).dot(wo);
    return ValueWithLobe(n, wo, ks > 0 && cosAlpha > 0 ? std::pow(cosAlpha, exponent) : 0.0f);
}

MicroBrdf::Value MicroBrdf::ValueWithLobe(const V3f& n, const V3f& wo, float lobe) const {
    const float total = kd + ks;
    if (total <= 0) return {0, 0};
    const float cosTheta = std::max(0.0f, n.dot(wo));
    // thesis eq. 3.16 for the specular lobe, cos θ/π for the diffuse one
    return {ks * (exponent + 2) / (2 * kPiF) * lobe,
            kd / total * cosTheta / kPiF + ks / total * (exponent + 1) / (2 * kPiF) * lobe};
}

MicroBrdf::Sampled MicroBrdf::Sample(const V3f& n, const V3f& wi, float u0, float u1,
                                     float u2) const {
    const float phi = 2 * kPiF * u2;
    if (u0 * (kd + ks) < kd) {  // cosine-weighted
        const V3f wo = FromLocal(n, std::sqrt(1 - u1), phi);
        return {wo, Evaluate(n, wi, wo)};
    }
    // thesis eq. 3.17: θ = arccos((1 − r₁)^(1/(n+1))) around the mirror direction. The lobe
    // there, cosⁿα = (1 − r₁)^(n/(n+1)), is (1 − r₁)/cos α: no second pow.
    const float cosAlpha = std::pow(1 - u1, 1 / (exponent + 1));
    const V3f wo = FromLocal(Mirror(n, wi), cosAlpha, phi);
    return {wo, ValueWithLobe(n, wo, cosAlpha > 0 ? (1 - u1) / cosAlpha : 0.0f)};
}

MicroBrdf MicroBrdfFromAttributes(const Attributes& attributes, Diagnostics& diagnostics) {
    const ShaderInstance& surface = attributes.surface;
    ShaderDefaults defaults = kStandardSurfaces[0];
    if (surface.IsSet()) {
        const auto* known =
            std::find_if(std::begin(kStandardSurfaces), std::end(kStandardSurfaces),
                         [&](const ShaderDefaults& d) { return surface.name == d.name; });
        if (known != std::end(kStandardSurfaces)) {
            defaults = *known;
        } else {
            diagnostics.WarningOnce("brdflight shader " + surface.name, surface.loc,
                                    "BRDFLight: surface shader \"" + surface.name +
                                        "\" is not a standard one; its micro BRDF is read from "
                                        "Kd, Ks, roughness or exponent with matte's defaults");
        }
    }
    MicroBrdf brdf;
    brdf.kd = defaults.kd;
    brdf.ks = defaults.ks;
    float roughness = defaults.roughness;
    FindNumber(surface.params, "Kd", &brdf.kd);
    FindNumber(surface.params, "Ks", &brdf.ks);
    FindNumber(surface.params, "roughness", &roughness);
    // DESIGN.md: the Phong exponent is 1/roughness unless the shader names it.
    brdf.exponent = roughness > 0 ? 1 / roughness : 1e4f;
    FindNumber(surface.params, "exponent", &brdf.exponent);
    if (auto it = attributes.user.find("brdflight"); it != attributes.user.end()) {
        FindNumber(it->second, "kd", &brdf.kd);
        FindNumber(it->second, "ks", &brdf.ks);
        FindNumber(it->second, "exponent", &brdf.exponent);
    }
    if (brdf.kd < 0 || brdf.ks < 0 || brdf.exponent < 0) {
        diagnostics.WarningOnce("brdflight negative", surface.loc,
                                "BRDFLight: negative kd, ks or exponent clamped to 0");
        brdf.kd = std::max(0.0f, brdf.kd);
        brdf.ks = std::max(0.0f, brdf.ks);
        brdf.exponent = std::max(0.0f, brdf.exponent);
    }
    return brdf;
}

}  // namespace gonio
