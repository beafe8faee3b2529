// Lighting built-ins (RISpec §15.6): ambient, diffuse, specular, specularbrdf, phong, trace.
//
// They sum over ShadingContext::Lights() as the spec's reference code sums over an
// illuminance(P, N, PI/2) loop: a non-ambient light counts at a point when its illuminate/solar
// reached the point and normalize(L) lies within 90° of N (N·L ≥ 0, the cone test Aqsis does).
// L is normalised per light; N and V are used as given, as in the spec's code.
//
// The specular exponent is 8/roughness, as in Aqsis 1.8 (which emulates BMRT's prmanspecular):
// the conformance references were rendered by Aqsis, and the spec leaves it to the renderer
// (its example uses 1/roughness, Pixie 10/roughness).

#include "shaderlang/runtime/builtins_lighting.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

V3 LightDirection(const LightResult& light, int n, int p) {
    return Normalized(V3(light.L[p], light.L[n + p], light.L[2 * n + p]));
}

// Whether a non-ambient light reaches point p within the hemisphere around N.
bool LitInHemisphere(const LightResult& light, int p, const V3& ln, const V3& normal) {
    if (light.ambient) return false;
    if (!light.lit.empty() && !light.lit[p]) return false;
    return Dot(ln, normal) >= 0.0f;
}

void ClearResult(const BuiltinCall& call, int p) {
    for (int c = 0; c < call.result.width; ++c) call.result.At(c, p) = 0.0f;
}

// Adds weight · Cl of `light` at point p to the result.
void AccumulateCl(const BuiltinCall& call, const LightResult& light, int p, float weight) {
    const int n = call.n;
    for (int c = 0; c < call.result.width; ++c)
        call.result.At(c, p) += weight * light.Cl[c * n + p];
}

// Sums weight(light, p, Ln) · Cl over the lights that reach each point within 90° of N.
template <typename Weight>
void SumOverLights(const BuiltinCall& call, const FloatArg& normalArg, Weight weight) {
    ForEachPoint(call, [&](int p) { ClearResult(call, p); });
    if (!call.context) return;
    const std::vector<LightResult>& lights = call.context->Lights();
    for (const LightResult& light : lights) {
        if (light.ambient) continue;
        ForEachPoint(call, [&](int p) {
            V3 ln = LightDirection(light, call.n, p);
            V3 normal = Triple(normalArg, p);
            if (LitInHemisphere(light, p, ln, normal)) {
                AccumulateCl(call, light, p, weight(p, ln, normal));
            }
        });
    }
}

void AmbientKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) { ClearResult(call, p); });
    if (!call.context) return;
    for (const LightResult& light : call.context->Lights()) {
        if (!light.ambient) continue;
        ForEachPoint(call, [&](int p) { AccumulateCl(call, light, p, 1.0f); });
    }
}

// diffuse(N) = Σ Cl · (normalize(L) · N).
void DiffuseKernel(const BuiltinCall& call) {
    SumOverLights(call, call.args[0],
                  [](int, const V3& ln, const V3& normal) { return Dot(ln, normal); });
}

// specular(N, V, roughness) = Σ Cl · specularbrdf(normalize(L), N, V, roughness).
void SpecularKernel(const BuiltinCall& call) {
    SumOverLights(call, call.args[0], [&](int p, const V3& ln, const V3& normal) {
        return SpecularBrdf(ln, normal, Triple(call.args[1], p), Float(call.args[2], p));
    });
}

void SpecularBrdfKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        float value = SpecularBrdf(Normalized(Triple(call.args[0], p)), Triple(call.args[1], p),
                                   Triple(call.args[2], p), Float(call.args[3], p));
        for (int c = 0; c < call.result.width; ++c) call.result.At(c, p) = value;
    });
}

// phong(N, V, size) = Σ Cl · max(0, R · normalize(L))^size, R = reflect(-normalize(V),
// normalize(N)).
void PhongKernel(const BuiltinCall& call) {
    SumOverLights(call, call.args[0], [&](int p, const V3& ln, const V3& normal) {
        V3 n = Normalized(normal);
        V3 i = -Normalized(Triple(call.args[1], p));
        V3 r = i - 2.0f * Dot(i, n) * n;
        return std::pow(std::max(0.0f, Dot(r, ln)), Float(call.args[2], p));
    });
}

// trace(P, R): the renderer traces the rays of the active points as one batch.
void TraceKernel(const BuiltinCall& call) {
    const int n = call.n;
    std::vector<float> origins(3 * n), directions(3 * n), colour(call.result.width * n, 0.0f);
    for (int p = 0; p < n; ++p) {
        for (int c = 0; c < 3; ++c) {
            origins[c * n + p] = call.args[0].At(c, p);
            directions[c * n + p] = call.args[1].At(c, p);
        }
    }
    if (call.context)
        call.context->Trace(origins.data(), directions.data(), call.active, colour.data());
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < call.result.width; ++c) call.result.At(c, p) = colour[c * n + p];
    });
}

}  // namespace

float SpecularBrdf(const V3& ln, const V3& normal, const V3& view, float roughness) {
    V3 h = Normalized(ln + view);
    return std::pow(std::max(0.0f, Dot(normal, h)), kSpecularExponentScale / roughness);
}

void AddLightingBuiltins(BuiltinList* list) {
    const unsigned lighting = kUsesLights | kVaryingResult | kReadsGlobals;
    list->Add("ambient", "c", "", AmbientKernel, lighting);
    list->Add("diffuse", "c", "n", DiffuseKernel, lighting);
    list->Add("specular", "c", "nvf", SpecularKernel, lighting);
    list->Add("specularbrdf", "c", "vnvf", SpecularBrdfKernel);
    list->Add("phong", "c", "nvf", PhongKernel, lighting);
    list->Add("trace", "c", "pv", TraceKernel, kVaryingResult);
}

}  // namespace gonio::sl::builtins
