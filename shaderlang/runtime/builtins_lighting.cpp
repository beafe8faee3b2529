// Lighting built-ins (RISpec §15.6): ambient, diffuse, specular, specularbrdf, phong, trace.
//
// They sum over ShadingContext::Lights() as the spec's reference code sums over an
// illuminance(P, N, PI/2) loop: a non-ambient light counts at a point when its illuminate/solar
// reached the point and normalize(L) lies within 90° of N (N·L ≥ 0, the cone test Aqsis does).
// A light from all directions (solar() without an axis) counts with L = N.
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

// Reads the triples (or floats) of an argument without a varying test per access: a uniform
// argument has step 0. The lighting kernels run per light and per point, so their accessors
// are the inner loop of every lit shader.
struct TripleReader {
    const float *x, *y, *z;
    int step;
    explicit TripleReader(const FloatArg& a)
        : x(a.data),
          y(a.data + (a.varying ? a.n : 1)),
          z(a.data + (a.varying ? 2 * a.n : 2)),
          step(a.varying ? 1 : 0) {}
    V3 operator()(int p) const { return V3(x[p * step], y[p * step], z[p * step]); }
};

struct FloatReader {
    const float* data;
    int step;
    explicit FloatReader(const FloatArg& a) : data(a.data), step(a.varying ? 1 : 0) {}
    float operator()(int p) const { return data[p * step]; }
};

void ClearResult(const BuiltinCall& call) {
    if (call.result.varying && !call.active) {
        std::fill_n(call.result.data, size_t(call.result.width) * call.n, 0.0f);
        return;
    }
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < call.result.width; ++c) call.result.At(c, p) = 0.0f;
    });
}

// max(0, N·H)^exponent, H = normalize(ln + view); inlined into the specular() loop.
inline float SpecularLobeWithExponent(const V3& ln, const V3& normal, const V3& view,
                                      float exponent) {
    V3 h = Normalized(ln + view);
    return std::pow(std::max(0.0f, Dot(normal, h)), exponent);
}

inline float SpecularLobe(const V3& ln, const V3& normal, const V3& view, float roughness) {
    return SpecularLobeWithExponent(ln, normal, view, kSpecularExponentScale / roughness);
}

// Sums weight(p, normalize(L), N) · Cl over the non-ambient lights that reach each point with
// N·normalize(L) ≥ 0 (the cone test Aqsis does). normalize(L) is computed a chunk of points at a
// time (NormalizeChunk vectorises it), the rest point by point.
template <typename Weight>
void SumOverLights(const BuiltinCall& call, const FloatArg& normalArg, Weight weight) {
    ClearResult(call);
    if (!call.context) return;
    const int n = call.n, width = call.result.width;
    // As ForEachPoint: a fully uniform call computes point 0 only, whatever the mask says.
    const bool varying = IsVaryingCall(call);
    const int points = varying ? n : 1;
    const TripleReader normals(normalArg);
    float* out = call.result.data;
    const int outStep = call.result.varying ? 1 : 0, outPlane = call.result.varying ? n : 1;
    for (const LightResult& light : call.context->Lights()) {
        if (light.ambient) continue;
        const float *Lx = light.L.data(), *Ly = Lx + n, *Lz = Ly + n;
        const float* Cl = light.Cl.data();
        const uint8_t* lit = light.lit.empty() ? nullptr : light.lit.data();
        // Light from all directions (solar() without an axis) arrives along N itself, as it
        // would along an illuminance loop's axis (see OpIllumNext).
        const uint8_t* all =
            light.fromAllDirections.empty() ? nullptr : light.fromAllDirections.data();
        for (int start = 0; start < points; start += kChunk) {
            const int count = std::min(kChunk, points - start);
            float lx[kChunk], ly[kChunk], lz[kChunk];
            for (int i = 0; i < count; ++i) {
                const int p = start + i;
                const V3 l = all && all[p] ? normals(p) : V3(Lx[p], Ly[p], Lz[p]);
                lx[i] = l.x, ly[i] = l.y, lz[i] = l.z;
            }
            NormalizeChunk(lx, ly, lz, count, lx, ly, lz);
            for (int i = 0; i < count; ++i) {
                const int p = start + i;
                if ((varying && !call.IsActive(p)) || (lit && !lit[p])) continue;
                const V3 ln(lx[i], ly[i], lz[i]), normal = normals(p);
                if (Dot(ln, normal) < 0.0f) continue;
                const float w = weight(p, ln, normal);
                for (int c = 0; c < width; ++c)
                    out[c * outPlane + p * outStep] += w * Cl[c * n + p];
            }
        }
    }
}

void AmbientKernel(const BuiltinCall& call) {
    ClearResult(call);
    if (!call.context) return;
    for (const LightResult& light : call.context->Lights()) {
        if (!light.ambient) continue;
        ForEachPoint(call, [&](int p) {
            for (int c = 0; c < call.result.width; ++c)
                call.result.At(c, p) += light.Cl[c * call.n + p];
        });
    }
}

// diffuse(N) = Σ Cl · (normalize(L) · N).
void DiffuseKernel(const BuiltinCall& call) {
    SumOverLights(call, call.args[0],
                  [](int, const V3& ln, const V3& normal) { return Dot(ln, normal); });
}

// specular(N, V, roughness) = Σ Cl · specularbrdf(normalize(L), N, V, roughness).
void SpecularKernel(const BuiltinCall& call) {
    const TripleReader view(call.args[1]);
    const FloatReader roughness(call.args[2]);
    // A uniform roughness (the usual case) gives one exponent for the whole call.
    if (!call.args[2].varying) {
        const float exponent = kSpecularExponentScale / roughness(0);
        SumOverLights(call, call.args[0], [&](int p, const V3& ln, const V3& normal) {
            return SpecularLobeWithExponent(ln, normal, view(p), exponent);
        });
        return;
    }
    SumOverLights(call, call.args[0], [&](int p, const V3& ln, const V3& normal) {
        return SpecularLobe(ln, normal, view(p), roughness(p));
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
    return SpecularLobe(ln, normal, view, roughness);
}

void AddLightingBuiltins(BuiltinList* list) {
    const unsigned lighting = kUsesLights | kVaryingResult | kReadsGlobals;
    list->Add("ambient", "c", "", AmbientKernel, lighting);
    list->Add("diffuse", "c", "n", DiffuseKernel, lighting);
    list->Add("specular", "c", "nvf", SpecularKernel, lighting);
    list->Add("specularbrdf", "c", "vnvf", SpecularBrdfKernel);
    list->Add("phong", "c", "nvf", PhongKernel, lighting);
    list->Add("trace", "c", "pv", TraceKernel, kVaryingResult | kTracesRays);
}

}  // namespace gonio::sl::builtins
