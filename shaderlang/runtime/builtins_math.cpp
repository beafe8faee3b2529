// Mathematical built-ins (RISpec §15.1): trigonometry, powers, rounding, min/max/clamp/mix,
// step/smoothstep/filterstep, spline and random. Noise lives in builtins_noise.cpp.

#include <algorithm>
#include <cmath>

#include "base/math.h"
#include "shaderlang/runtime/builtins_derivatives.h"
#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

// ---- float -> float ------------------------------------------------------------------------

template <float (*Op)(float)>
void UnaryKernel(const BuiltinCall& call) {
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) call.result.At(c, p) = Op(Comp(call.args[0], c, p));
    });
}

template <float (*Op)(float, float)>
void BinaryKernel(const BuiltinCall& call) {
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) {
            call.result.At(c, p) = Op(Comp(call.args[0], c, p), Comp(call.args[1], c, p));
        }
    });
}

float Radians(float x) { return x * (kPiF / 180.0f); }
float Degrees(float x) { return x * (180.0f / kPiF); }
float Sin(float x) { return std::sin(x); }
float Cos(float x) { return std::cos(x); }
float Tan(float x) { return std::tan(x); }
// asin/acos clamp their argument: a normalised dot product may stray past ±1 by rounding.
float Asin(float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }
float Acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }
float Atan(float x) { return std::atan(x); }
float Atan2(float y, float x) { return std::atan2(y, x); }
float Exp(float x) { return std::exp(x); }
float Sqrt(float x) { return std::sqrt(x); }
float InverseSqrt(float x) { return 1.0f / std::sqrt(x); }
float Log(float x) { return std::log(x); }
float LogBase(float x, float base) { return std::log(x) / std::log(base); }
float Pow(float x, float y) { return std::pow(x, y); }
// RSL mod is the mathematical modulo: the result has the sign of the divisor (mod(-1,3) = 2).
float Mod(float a, float b) { return b != 0.0f ? a - b * std::floor(a / b) : 0.0f; }
float Abs(float x) { return std::fabs(x); }
float Sign(float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); }
float Floor(float x) { return std::floor(x); }
float Ceil(float x) { return std::ceil(x); }
float Round(float x) { return std::round(x); }
float Step(float edge, float x) { return x < edge ? 0.0f : 1.0f; }

// ---- min, max, clamp, mix, smoothstep ------------------------------------------------------

template <bool IsMax>
void MinMaxKernel(const BuiltinCall& call) {
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) {
            float v = Comp(call.args[0], c, p);
            for (int a = 1; a < call.argCount; ++a) {
                float x = Comp(call.args[a], c, p);
                v = IsMax ? std::max(v, x) : std::min(v, x);
            }
            call.result.At(c, p) = v;
        }
    });
}

void ClampKernel(const BuiltinCall& call) {
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) {
            float v = Comp(call.args[0], c, p);
            v = std::max(v, Comp(call.args[1], c, p));
            call.result.At(c, p) = std::min(v, Comp(call.args[2], c, p));
        }
    });
}

void MixKernel(const BuiltinCall& call) {
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) {
            float a = Comp(call.args[0], c, p), b = Comp(call.args[1], c, p);
            float t = Comp(call.args[2], c, p);
            call.result.At(c, p) = (1.0f - t) * a + t * b;
        }
    });
}

float Smoothstep(float lo, float hi, float x) {
    if (x < lo) return 0.0f;
    if (x >= hi) return 1.0f;
    float t = (x - lo) / (hi - lo);
    return t * t * (3.0f - 2.0f * t);
}

void SmoothstepKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        call.result.At(0, p) =
            Smoothstep(Float(call.args[0], p), Float(call.args[1], p), Float(call.args[2], p));
    });
}

// ---- filterstep ----------------------------------------------------------------------------

// The integral of a box filter of width w centred at x over step(edge, ·): the fraction of
// [x - w/2, x + w/2] beyond the edge. With w = 0 it is step itself.
float BoxFilteredStep(float edge, float x, float w) {
    if (w <= 0.0f) return Step(edge, x);
    return std::clamp((x + 0.5f * w - edge) / w, 0.0f, 1.0f);
}

// filterstep(edge, s1 [, s2] [, "width", w ...]): the step from edge, box-filtered over the
// footprint of s (the interval [s1, s2] when s2 is given, else |Δu s| + |Δv s|, s's change
// over one grid step along u and v). "width"/"swidth" scale the footprint; "filter" is accepted,
// but every filter is evaluated as a box (documented in docs/shading-language.md).
void FilterstepKernel(const BuiltinCall& call) {
    int next = 2;
    const bool hasS2 = call.argCount > 2 && call.argTypes[2].base == BaseType::Float;
    if (hasS2) next = 3;
    float widthScale = 1.0f;
    for (int a = next; a + 1 < call.argCount; a += 2) {
        if (call.argTypes[a].base != BaseType::String || !call.strings[a].data) continue;
        const std::string& name = call.strings[a].data[0];
        if ((name == "width" || name == "swidth") && call.argTypes[a + 1].base == BaseType::Float) {
            widthScale = Float(call.args[a + 1], 0);
        }
    }
    const Stencil su = UStencil(call), sv = VStencil(call);
    ForEachPoint(call, [&](int p) {
        float edge = Float(call.args[0], p);
        float s1 = Float(call.args[1], p);
        float x = s1, w = 0.0f;
        if (hasS2) {
            float s2 = Float(call.args[2], p);
            x = 0.5f * (s1 + s2);
            w = std::fabs(s2 - s1);
        } else {
            w = std::fabs(Delta(su, call.args[1], 0, p)) + std::fabs(Delta(sv, call.args[1], 0, p));
        }
        call.result.At(0, p) = BoxFilteredStep(edge, x, w * widthScale);
    });
}

// ---- spline --------------------------------------------------------------------------------

// The basis matrices (rows: coefficients of t³, t², t, 1) and the knot step of each basis, as in
// RISpec §15.1 (the same bases as RiBasis, §5.5).
struct SplineBasis {
    float m[4][4];
    int step;
};

const SplineBasis kCatmullRom = {{{-0.5f, 1.5f, -1.5f, 0.5f},
                                  {1.0f, -2.5f, 2.0f, -0.5f},
                                  {-0.5f, 0.0f, 0.5f, 0.0f},
                                  {0.0f, 1.0f, 0.0f, 0.0f}},
                                 1};
const SplineBasis kBezier = {{{-1.0f, 3.0f, -3.0f, 1.0f},
                              {3.0f, -6.0f, 3.0f, 0.0f},
                              {-3.0f, 3.0f, 0.0f, 0.0f},
                              {1.0f, 0.0f, 0.0f, 0.0f}},
                             3};
const SplineBasis kBSpline = {{{-1.0f / 6, 3.0f / 6, -3.0f / 6, 1.0f / 6},
                               {3.0f / 6, -6.0f / 6, 3.0f / 6, 0.0f},
                               {-3.0f / 6, 0.0f, 3.0f / 6, 0.0f},
                               {1.0f / 6, 4.0f / 6, 1.0f / 6, 0.0f}},
                              1};
// Hermite knots come in (point, tangent) pairs: P0 T0 P1 T1.
const SplineBasis kHermite = {{{2.0f, 1.0f, -2.0f, 1.0f},
                               {-3.0f, -2.0f, 3.0f, -1.0f},
                               {0.0f, 1.0f, 0.0f, 0.0f},
                               {1.0f, 0.0f, 0.0f, 0.0f}},
                              2};

const SplineBasis* FindBasis(const std::string& name) {
    if (name == "catmull-rom") return &kCatmullRom;
    if (name == "bezier") return &kBezier;
    if (name == "bspline" || name == "b-spline") return &kBSpline;
    if (name == "hermite") return &kHermite;
    return nullptr;
}

// One spline evaluation over `count` knots of one component; knot(k) reads knot k.
template <typename Knot>
float EvaluateSpline(const SplineBasis* basis, int count, float x, Knot knot) {
    x = std::clamp(x, 0.0f, 1.0f);
    if (!basis) {  // "linear": piecewise linear through the interior knots 1 .. count-2
        int segments = count - 3;
        if (segments < 1) return knot(std::min(1, count - 1));
        float u = x * segments;
        int seg = std::min(static_cast<int>(u), segments - 1);
        float t = u - seg;
        return (1.0f - t) * knot(seg + 1) + t * knot(seg + 2);
    }
    int segments = (count - 4) / basis->step + 1;
    if (segments < 1) return 0.0f;
    float u = x * segments;
    int seg = std::min(static_cast<int>(u), segments - 1);
    float t = u - seg;
    int first = seg * basis->step;
    float tp[4] = {t * t * t, t * t, t, 1.0f};
    float v = 0.0f;
    for (int k = 0; k < 4; ++k) {
        float w = 0.0f;
        for (int r = 0; r < 4; ++r) w += tp[r] * basis->m[r][k];
        v += w * knot(first + k);
    }
    return v;
}

// spline([basis,] x, v1, ..., vn) and spline([basis,] x, array): the knots are the arguments
// after x, or the elements of one array argument.
void SplineKernel(const BuiltinCall& call) {
    int xIndex = call.argTypes[0].base == BaseType::String ? 1 : 0;
    const SplineBasis* basis = &kCatmullRom;
    if (xIndex == 1) {
        const std::string& name = call.strings[0].data[0];
        if (name == "linear") {
            basis = nullptr;
        } else {
            basis = FindBasis(name);
            if (!basis) {
                if (call.context) {
                    call.context->RuntimeWarning(
                        "spline:" + name,
                        "spline: unknown basis \"" + name + "\", using catmull-rom");
                }
                basis = &kCatmullRom;
            }
        }
    }
    const int w = call.result.width;
    const int firstKnot = xIndex + 1;
    const bool fromArray = call.argTypes[firstKnot].IsArray();
    const int count = fromArray ? call.argTypes[firstKnot].arrayLength : call.argCount - firstKnot;
    ForEachPoint(call, [&](int p) {
        float x = Float(call.args[xIndex], p);
        for (int c = 0; c < w; ++c) {
            auto knot = [&](int k) {
                return fromArray ? call.args[firstKnot].At(k * w + c, p)
                                 : Comp(call.args[firstKnot + k], c, p);
            };
            call.result.At(c, p) = EvaluateSpline(basis, count, x, knot);
        }
    });
}

// ---- random --------------------------------------------------------------------------------

// A float uniform in [0, 1) from the top 24 bits, which a float holds exactly.
float UnitFloat(uint64_t bits) { return float(bits >> 40) * (1.0f / 16777216.0f); }

// random(): uniform in [0, 1) per point and component, from the point's own stream in the
// context (seeded from its pixel and sample), so that a render does not depend on which thread
// shades which point. Without a context (kernel tests) each value hashes the point's index.
void RandomKernel(const BuiltinCall& call) {
    const int w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) {
            call.result.At(c, p) = UnitFloat(call.context ? call.context->NextRandomBits(p)
                                                          : MixBits(uint64_t(p) * w + c + 1));
        }
    });
}

// __uniform_random(): random() stored in a uniform variable (compiler/uniform_random.h). One
// value per component for the whole run, from the run's own stream; copied to every active
// point if the result is varying (a uniform value in a varying register).
void UniformRandomKernel(const BuiltinCall& call) {
    for (int c = 0; c < call.result.width; ++c) {
        const float value = UnitFloat(call.context ? call.context->NextUniformRandomBits()
                                                   : MixBits(uint64_t(c) + 1));
        ForEachPoint(call, [&](int p) { call.result.At(c, p) = value; });
    }
}

void AddUnary(BuiltinList* list, const char* name, BuiltinKernel kernel) {
    list->Add(name, "f", "f", kernel);
}

}  // namespace

void AddMathBuiltins(BuiltinList* list) {
    AddUnary(list, "radians", UnaryKernel<Radians>);
    AddUnary(list, "degrees", UnaryKernel<Degrees>);
    AddUnary(list, "sin", UnaryKernel<Sin>);
    AddUnary(list, "asin", UnaryKernel<Asin>);
    AddUnary(list, "cos", UnaryKernel<Cos>);
    AddUnary(list, "acos", UnaryKernel<Acos>);
    AddUnary(list, "tan", UnaryKernel<Tan>);
    AddUnary(list, "atan", UnaryKernel<Atan>);
    list->Add("atan", "f", "ff", BinaryKernel<Atan2>);
    list->Add("pow", "f", "ff", BinaryKernel<Pow>);
    AddUnary(list, "exp", UnaryKernel<Exp>);
    AddUnary(list, "sqrt", UnaryKernel<Sqrt>);
    AddUnary(list, "inversesqrt", UnaryKernel<InverseSqrt>);
    AddUnary(list, "log", UnaryKernel<Log>);
    list->Add("log", "f", "ff", BinaryKernel<LogBase>);
    list->Add("mod", "f", "ff", BinaryKernel<Mod>);
    AddUnary(list, "abs", UnaryKernel<Abs>);
    AddUnary(list, "sign", UnaryKernel<Sign>);
    AddUnary(list, "floor", UnaryKernel<Floor>);
    AddUnary(list, "ceil", UnaryKernel<Ceil>);
    AddUnary(list, "round", UnaryKernel<Round>);
    list->Add("step", "f", "ff", BinaryKernel<Step>);
    list->Add("smoothstep", "f", "fff", SmoothstepKernel);
    list->Add("filterstep", "f", "ff*", FilterstepKernel, kNeedsDerivatives);

    // min and max take 2 or more operands of one type (RISpec §15.1); rows for 2..8 operands.
    for (const char* t : kNumericCodes) {
        std::string args = t;
        for (int count = 2; count <= 8; ++count) {
            args += t;
            list->Add("min", t, args, MinMaxKernel<false>);
            list->Add("max", t, args, MinMaxKernel<true>);
        }
        list->Add("clamp", t, std::string(3, t[0]), ClampKernel);
        list->Add("mix", t, std::string(2, t[0]) + "f", MixKernel);
        if (t[0] != 'f') list->Add("mix", t, std::string(3, t[0]), MixKernel);  // EXT, Aqsis
    }

    // spline: 4..14 knots as separate arguments (the call holds at most 16), or one array.
    for (const char* t : {"f", "c", "p", "v"}) {
        std::string knots;
        for (int count = 1; count <= 14; ++count) {
            knots += t;
            if (count < 4) continue;
            list->Add("spline", t, "f" + knots, SplineKernel);
            if (count <= 13) list->Add("spline", t, "sf" + knots, SplineKernel);
        }
        list->Add("spline", t, std::string("f") + t + "[]", SplineKernel);
        list->Add("spline", t, std::string("sf") + t + "[]", SplineKernel);
    }

    for (const char* t : {"f", "c", "p"}) {
        list->Add("random", t, "", RandomKernel, kVaryingResult | kDrawsRandom);
        list->Add("__uniform_random", t, "", UniformRandomKernel, kDrawsRandom);
    }
}

}  // namespace gonio::sl::builtins
