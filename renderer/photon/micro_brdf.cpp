#include "renderer/photon/micro_brdf.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "base/math.h"
#include "renderer/photon/leaf_optics.h"

namespace gonio {
namespace {

using Imath::V3f;

V3f Mirror(const V3f& n, const V3f& wi) { return 2 * n.dot(wi) * n - wi; }

// The first value of a numeric parameter of the instance; false if it has none.
bool FindNumber(const sl::ShaderInstance& surface, const char* name, float* value) {
    const std::vector<float> values = surface.FloatParameter(name);
    if (values.empty()) return false;
    *value = values[0];
    return true;
}

// The leaf model's value in the Phong model's terms.
MicroBrdf::Value FromLeaf(const LeafOptics::Value& v) {
    return {v.specular, v.pdf, v.diffuse, v.transmitted};
}

// The values of `name` (one, or one per colour component); `fallback` if it is absent.
std::vector<float> Colour(const ParamDict& params, const char* name,
                          const std::vector<float>& fallback) {
    const TypedParam* p = params.Find(name);
    if (!p || p->numbers.empty()) return fallback;
    return std::vector<float>(p->numbers.begin(), p->numbers.end());
}

// The leaf optics of `Attribute "brdflight" "string model" "leaf"`; null (after an error at
// the parameter) when a value is out of range.
std::shared_ptr<const LeafOptics> ReadLeaf(const ParamDict& params, Diagnostics& diagnostics) {
    LeafParams p;
    p.eta = params.GetFloat("eta", p.eta);
    p.roughness = params.GetFloat("roughness", p.roughness);
    p.reflectance = Colour(params, "reflectance", p.reflectance);
    p.transmittance = Colour(params, "transmittance", p.transmittance);
    auto fail = [&](const char* name, const std::string& expected) {
        diagnostics.Error(params.Location(name), std::string("Attribute \"brdflight\" \"") + name +
                                                     "\": expected " + expected);
        return nullptr;
    };
    if (!(p.eta >= 1 && p.eta <= 3)) return fail("eta", "a refractive index in [1, 3]");
    if (!(p.roughness >= 0.01f && p.roughness <= 1))
        return fail("roughness", "a GGX roughness in [0.01, 1]");
    for (size_t k = 0; k < std::max(p.reflectance.size(), p.transmittance.size()); ++k) {
        const float r = p.reflectance[std::min(k, p.reflectance.size() - 1)];
        const float t = p.transmittance[std::min(k, p.transmittance.size() - 1)];
        if (!(r >= 0 && t >= 0 && r + t <= 1)) {
            return fail(params.Has("transmittance") ? "transmittance" : "reflectance",
                        "reflectance and transmittance >= 0 with reflectance + transmittance "
                        "<= 1 in every colour component (got " +
                            std::to_string(r) + " + " + std::to_string(t) + ")");
        }
    }
    return std::make_shared<const LeafOptics>(p);
}

}  // namespace

void OrthonormalBasis(const V3f& n, V3f* t, V3f* s) {
    // Duff et al. 2017, "Building an orthonormal basis, revisited": branchless and continuous.
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    *t = V3f(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    *s = V3f(b, sign + n.y * n.y * a, -n.y);
}

V3f FromLocal(const V3f& n, float cosTheta, float phi) {
    V3f t, s;
    OrthonormalBasis(n, &t, &s);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return (t * std::cos(phi) + s * std::sin(phi)) * sinTheta + n * cosTheta;
}

MicroBrdf::Value MicroBrdf::Evaluate(const V3f& n, const V3f& wi, const V3f& wo) const {
    if (leaf) return FromLeaf(leaf->Evaluate(n, wi, wo));
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
    if (leaf) {
        const LeafOptics::Sampled s = leaf->Sample(n, wi, u0, u1, u2);
        return {s.wo, FromLeaf(s.value)};
    }
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

float MicroBrdf::Component(const Value& value, int k, float cs) const {
    if (!leaf) return kd * cs / kPiF + value.specular;
    return value.specular +
           value.diffuse * (value.transmitted ? leaf->Transmittance(k) : leaf->Reflectance(k));
}

MicroBrdf MicroBrdfFromShader(const sl::ShaderInstance& surface, const Attributes& attributes,
                              Diagnostics& diagnostics) {
    MicroBrdf brdf;
    const bool hasKd = FindNumber(surface, "Kd", &brdf.kd);
    const bool hasKs = FindNumber(surface, "Ks", &brdf.ks);
    if (!hasKd && !hasKs) {
        diagnostics.WarningOnce("brdflight shader " + surface.Master().Name(),
                                attributes.surface.loc,
                                "BRDFLight: surface shader \"" + surface.Master().Name() +
                                    "\" has neither Kd nor Ks; its micro BRDF is matte's (Kd 1)");
        brdf.kd = 1, brdf.ks = 0;
    } else {
        if (!hasKd) brdf.kd = 0;
        if (!hasKs) brdf.ks = 0;
    }
    float roughness = 0;
    // DESIGN.md: the Phong exponent is 1/roughness unless the shader names it.
    if (FindNumber(surface, "roughness", &roughness))
        brdf.exponent = roughness > 0 ? 1 / roughness : 1e4f;
    FindNumber(surface, "exponent", &brdf.exponent);
    if (auto it = attributes.user.find("brdflight"); it != attributes.user.end()) {
        brdf.kd = it->second.GetFloat("kd", brdf.kd);
        brdf.ks = it->second.GetFloat("ks", brdf.ks);
        brdf.exponent = it->second.GetFloat("exponent", brdf.exponent);
        const std::string model = it->second.GetString("model", "phong");
        if (model == "leaf") {
            brdf.leaf = ReadLeaf(it->second, diagnostics);
        } else if (model != "phong") {
            diagnostics.Error(it->second.Location("model"),
                              "Attribute \"brdflight\" \"model\": expected \"phong\" or "
                              "\"leaf\", got \"" +
                                  model + "\"");
        }
    }
    if (brdf.kd < 0 || brdf.ks < 0 || brdf.exponent < 0) {
        diagnostics.WarningOnce("brdflight negative", attributes.surface.loc,
                                "BRDFLight: negative kd, ks or exponent clamped to 0");
        brdf.kd = std::max(0.0f, brdf.kd);
        brdf.ks = std::max(0.0f, brdf.ks);
        brdf.exponent = std::max(0.0f, brdf.exponent);
    }
    return brdf;
}

}  // namespace gonio
