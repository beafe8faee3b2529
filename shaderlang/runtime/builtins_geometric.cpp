// Geometric built-ins (RISpec §15.2): components, lengths and distances, ptlined, rotate,
// faceforward, reflect, refract, fresnel, depth, and the space transforms (transform,
// vtransform, ntransform) through ShadingContext::CurrentFromSpace.

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/runtime/globals_view.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

// ---- components ----------------------------------------------------------------------------

template <int Axis>
void CompKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) { call.result.At(0, p) = call.args[0].At(Axis, p); });
}

// setxcomp(output P, x): writes one component of its first (output) argument.
template <int Axis>
void SetCompKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) { call.args[0].At(Axis, p) = Float(call.args[1], p); });
}

// ---- lengths -------------------------------------------------------------------------------

void LengthKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) { call.result.At(0, p) = Triple(call.args[0], p).length(); });
}

// True when a kernel may compute every point of the batch plane by plane: no mask (so no point
// is left untouched) and every operand varying.
bool AllPointsVarying(const BuiltinCall& call, std::initializer_list<FloatArg> operands) {
    if (call.active || !call.result.varying) return false;
    for (const FloatArg& a : operands) {
        if (!a.varying) return false;
    }
    return true;
}

// normalize() over whole planes, a chunk of points at a time.
void NormalizePlanes(const FloatArg& in, const FloatArg& out) {
    const int n = in.n;
    for (int start = 0; start < n; start += kChunk) {
        const float* x = in.data + start;
        float* o = out.data + start;
        NormalizeChunk(x, x + n, x + 2 * n, std::min(kChunk, n - start), o, o + n, o + 2 * n);
    }
}

void NormalizeKernel(const BuiltinCall& call) {
    if (AllPointsVarying(call, {call.args[0]})) return NormalizePlanes(call.args[0], call.result);
    ForEachPoint(call,
                 [&](int p) { SetTriple(call.result, p, Normalized(Triple(call.args[0], p))); });
}

void DistanceKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        call.result.At(0, p) = (Triple(call.args[0], p) - Triple(call.args[1], p)).length();
    });
}

// ptlined(P0, P1, Q): the distance from Q to the segment P0-P1 (RISpec argument order).
void PtlinedKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        V3 p0 = Triple(call.args[0], p), p1 = Triple(call.args[1], p);
        V3 q = Triple(call.args[2], p);
        V3 d = p1 - p0;
        float len2 = Dot(d, d);
        float t = len2 > 0.0f ? std::clamp(Dot(q - p0, d) / len2, 0.0f, 1.0f) : 0.0f;
        call.result.At(0, p) = (q - (p0 + t * d)).length();
    });
}

// rotate(Q, angle, P0, P1): Q rotated by angle (radians, right-handed) about the axis P0→P1.
void RotateKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        V3 q = Triple(call.args[0], p);
        float angle = Float(call.args[1], p);
        V3 p0 = Triple(call.args[2], p), p1 = Triple(call.args[3], p);
        V3 axis = Normalized(p1 - p0);
        V3 r = q - p0;
        // Rodrigues' rotation formula.
        float c = std::cos(angle), s = std::sin(angle);
        V3 rotated = r * c + axis.cross(r) * s + axis * (Dot(axis, r) * (1.0f - c));
        SetTriple(call.result, p, p0 + rotated);
    });
}

// ---- shading geometry ----------------------------------------------------------------------

// faceforward() over whole planes, bit for bit the per-point code below, a chunk of points at a
// time in loops the compiler vectorises: the signs, then a select per plane (few pointers per
// loop, so the aliasing checks stay within what the vectoriser versions for).
void FaceforwardPlanes(const FloatArg& nArg, const FloatArg& iArg, const FloatArg& nrefArg,
                       const FloatArg& out) {
    const int n = nArg.n;
    for (int start = 0; start < n; start += kChunk) {
        const int count = std::min(kChunk, n - start);
        const float *ix = iArg.data + start, *iy = ix + n, *iz = iy + n;
        const float *rx = nrefArg.data + start, *ry = rx + n, *rz = ry + n;
        float sign[kChunk];
        for (int p = 0; p < count; ++p) {
            const bool flip = (-ix[p]) * rx[p] + (-iy[p]) * ry[p] + (-iz[p]) * rz[p] < 0.0f;
            sign[p] = flip ? -1.0f : 1.0f;
        }
        for (int c = 0; c < 3; ++c) {
            const float* in = nArg.data + size_t(c) * n + start;
            float* o = out.data + size_t(c) * n + start;
            for (int p = 0; p < count; ++p) o[p] = sign[p] < 0.0f ? -in[p] : in[p];
        }
    }
}

// faceforward(N, I [, Nref]): N flipped, if need be, to point against I as seen from Nref
// (the global Ng when Nref is absent).
void FaceforwardKernel(const BuiltinCall& call) {
    const FloatArg nrefArg = call.argCount >= 3 ? call.args[2]
                             : call.globals     ? call.globals->Get("Ng")
                                                : FloatArg{};
    if (nrefArg.data && AllPointsVarying(call, {call.args[0], call.args[1], nrefArg}))
        return FaceforwardPlanes(call.args[0], call.args[1], nrefArg, call.result);
    ForEachPoint(call, [&](int p) {
        V3 n = Triple(call.args[0], p), i = Triple(call.args[1], p);
        V3 nref = nrefArg.data ? Triple(nrefArg, p) : n;
        SetTriple(call.result, p, Dot(-i, nref) < 0.0f ? -n : n);
    });
}

V3 Reflect(const V3& i, const V3& n) { return i - 2.0f * Dot(i, n) * n; }

// Refraction with eta = n(incident side) / n(other side); 0 on total internal reflection.
V3 Refract(const V3& i, const V3& n, float eta) {
    float idotn = Dot(i, n);
    float k = 1.0f - eta * eta * (1.0f - idotn * idotn);
    return k < 0.0f ? V3(0.0f) : eta * i - (eta * idotn + std::sqrt(k)) * n;
}

void ReflectKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        SetTriple(call.result, p, Reflect(Triple(call.args[0], p), Triple(call.args[1], p)));
    });
}

void RefractKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        SetTriple(
            call.result, p,
            Refract(Triple(call.args[0], p), Triple(call.args[1], p), Float(call.args[2], p)));
    });
}

// The unpolarised Fresnel reflectance of a dielectric (Born & Wolf §1.5): the mean of the s and
// p reflectances for relative index m = 1/eta; 1 under total internal reflection.
float FresnelKr(const V3& i, const V3& n, float eta) {
    float c = std::fabs(Dot(Normalized(i), Normalized(n)));
    float m = 1.0f / eta;
    float g2 = m * m - 1.0f + c * c;
    if (g2 < 0.0f) return 1.0f;
    float g = std::sqrt(g2);
    float rs = (c - g) / (c + g);
    float rp = (m * m * c - g) / (m * m * c + g);
    return 0.5f * (rs * rs + rp * rp);
}

// fresnel(I, N, eta, output Kr, output Kt [, output R, output T]); Kt = 1 - Kr.
void FresnelKernel(const BuiltinCall& call) {
    const bool directions = call.argCount >= 7;
    ForEachPoint(call, [&](int p) {
        V3 i = Triple(call.args[0], p), n = Triple(call.args[1], p);
        float eta = Float(call.args[2], p);
        float kr = FresnelKr(i, n, eta);
        call.args[3].At(0, p) = kr;
        call.args[4].At(0, p) = 1.0f - kr;
        if (directions) {
            SetTriple(call.args[5], p, Reflect(i, n));
            SetTriple(call.args[6], p, Refract(i, n, eta));
        }
    });
}

// depth(P): camera-space z mapped to 0 at the near and 1 at the far clipping plane.
void DepthKernel(const BuiltinCall& call) {
    float nearZ = 0.0f, farZ = 1.0f;
    std::vector<float> clipping;
    std::string unused;
    if (call.context &&
        call.context->Option("Clipping", TypeSpec{BaseType::Float, 2}, &clipping, &unused) &&
        clipping.size() >= 2 && clipping[1] > clipping[0]) {
        nearZ = clipping[0];
        farZ = clipping[1];
    }
    ForEachPoint(call, [&](int p) {
        call.result.At(0, p) = (call.args[0].At(2, p) - nearZ) / (farZ - nearZ);
    });
}

// ---- transforms ----------------------------------------------------------------------------

enum class TransformRule { Point, Vector, Normal };

V3 ApplyTransform(const M44& m, const V3& x, TransformRule rule) {
    V3 out;
    switch (rule) {
        case TransformRule::Point:
            m.multVecMatrix(x, out);
            break;
        case TransformRule::Vector:
            m.multDirMatrix(x, out);
            break;
        // Normals go by the inverse transpose so they stay perpendicular to surfaces.
        case TransformRule::Normal:
            m.inverse().transposed().multDirMatrix(x, out);
            break;
    }
    return out;
}

bool LookUpSpace(const BuiltinCall& call, const std::string& space, int p, M44* m) {
    if (call.context && call.context->CurrentFromSpace(space, p, m)) return true;
    if (call.context) {
        call.context->RuntimeWarning("space:" + space,
                                     "unknown coordinate system \"" + space + "\"");
    }
    return false;
}

// The matrix a transform call applies at point p, from its leading arguments:
//   (to, x)            current → to
//   (from, to, x)      from → to
//   (matrix, x)        x · matrix
//   (from, matrix, x)  from → current, then · matrix
bool TransformMatrix(const BuiltinCall& call, int p, M44* m) {
    const BaseType first = call.argTypes[0].base;
    const bool two = call.argCount == 3;
    if (!two) {
        if (first == BaseType::Matrix) {
            *m = Matrix(call.args[0], p);
            return true;
        }
        M44 currentFromTo;
        if (!LookUpSpace(call, call.strings[0].data[0], p, &currentFromTo)) return false;
        *m = currentFromTo.inverse();
        return true;
    }
    M44 currentFromFrom;
    if (!LookUpSpace(call, call.strings[0].data[0], p, &currentFromFrom)) return false;
    if (call.argTypes[1].base == BaseType::Matrix) {
        *m = currentFromFrom * Matrix(call.args[1], p);
        return true;
    }
    M44 currentFromTo;
    if (!LookUpSpace(call, call.strings[1].data[0], p, &currentFromTo)) return false;
    *m = currentFromFrom * currentFromTo.inverse();
    return true;
}

template <TransformRule Rule>
void TransformKernel(const BuiltinCall& call) {
    const FloatArg& x = call.args[call.argCount - 1];
    ForEachPoint(call, [&](int p) {
        M44 m;
        V3 v = Triple(x, p);
        SetTriple(call.result, p, TransformMatrix(call, p, &m) ? ApplyTransform(m, v, Rule) : v);
    });
}

void AddTransformRows(BuiltinList* list, const char* name, const char* t, BuiltinKernel kernel) {
    // A named space is the renderer's: a constant point is transformed at run time, not folded.
    for (const char* prefix : {"s", "ss", "m", "sm"})
        list->Add(name, t, prefix + std::string(t), kernel,
                  prefix[0] == 's' ? kUsesSpaces : kBuiltinNone);
}

}  // namespace

void AddGeometricBuiltins(BuiltinList* list) {
    for (const char* t : kPointLikeCodes) {
        const std::string T(1, static_cast<char>(t[0] - 'a' + 'A'));
        list->Add("xcomp", "f", t, CompKernel<0>);
        list->Add("ycomp", "f", t, CompKernel<1>);
        list->Add("zcomp", "f", t, CompKernel<2>);
        list->Add("setxcomp", "x", T + "f", SetCompKernel<0>);
        list->Add("setycomp", "x", T + "f", SetCompKernel<1>);
        list->Add("setzcomp", "x", T + "f", SetCompKernel<2>);
        list->Add("length", "f", t, LengthKernel);
    }
    list->Add("normalize", "v", "v", NormalizeKernel);
    list->Add("normalize", "n", "n", NormalizeKernel);
    list->Add("normalize", "v", "p", NormalizeKernel);
    list->Add("distance", "f", "pp", DistanceKernel);
    list->Add("ptlined", "f", "ppp", PtlinedKernel);
    for (const char* t : kPointLikeCodes)
        list->Add("rotate", t, std::string(t) + "fpp", RotateKernel);

    list->Add("faceforward", "n", "nv", FaceforwardKernel, kReadsGlobals);
    list->Add("faceforward", "v", "vv", FaceforwardKernel, kReadsGlobals);
    list->Add("faceforward", "n", "nvn", FaceforwardKernel);
    list->Add("faceforward", "v", "vvv", FaceforwardKernel);
    list->Add("reflect", "v", "vn", ReflectKernel);
    list->Add("reflect", "v", "vv", ReflectKernel);
    list->Add("refract", "v", "vnf", RefractKernel);
    list->Add("refract", "v", "vvf", RefractKernel);
    list->Add("fresnel", "x", "vnfFF", FresnelKernel);
    list->Add("fresnel", "x", "vnfFFVV", FresnelKernel);
    list->Add("depth", "f", "p", DepthKernel);

    AddTransformRows(list, "transform", "p", TransformKernel<TransformRule::Point>);
    AddTransformRows(list, "vtransform", "v", TransformKernel<TransformRule::Vector>);
    AddTransformRows(list, "ntransform", "n", TransformKernel<TransformRule::Normal>);
}

}  // namespace gonio::sl::builtins
