// noise, pnoise and cellnoise (RISpec §15.1) over 1-4 dimensional inputs, returning float,
// color, point or vector.
//
// noise is Perlin's gradient noise in the form Aqsis 1.8 uses (its references are the
// conformance suite's): Perlin's "improved noise" (SIGGRAPH 2002: the quintic fade
// 6t⁵-15t⁴+10t³ and his permutation table) with Gustavson's gradient sets for 1, 2 and 4
// dimensions, rescaled per dimension to the range of classic RenderMan noise (×0.188, 0.507,
// 0.936, 0.87) and mapped to [0, 1] as 0.5·(1 + n). At every integer lattice point the value is
// exactly 0.5. Vector-valued noise evaluates the same function at offset inputs, with the
// offsets Aqsis uses, so the components are decorrelated yet match Aqsis.
//
// pnoise wraps the lattice with period round(p) (at least 1). Unlike Aqsis, the wrap is a true
// modulo for negative coordinates too, so pnoise is periodic everywhere.
//
// cellnoise is our own: a hash of the integer cell, uniform in [0, 1), constant inside each
// cell. The conformance scenes do not use it, so it need not match Aqsis's table-based one.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "shaderlang/runtime/builtins_util.h"

namespace gonio::sl::builtins {

namespace {

// Ken Perlin's permutation of 0..255 (improved noise reference implementation), twice, so that
// nested lookups perm[i + perm[j]] never need a wrap.
const uint8_t kPermutation[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

inline int Perm(int i) { return kPermutation[i & 255]; }

// The gradient · offset products. 1D: gradients ±1..±8. 2D: 8 directions (±1, ±2). 3D:
// Perlin's 12 edge directions (with 4 repeats). 4D: 32 directions with one zero component.
float Gradient(int hash, const float* f, int dims) {
    switch (dims) {
        case 1: {
            int h = hash & 15;
            float g = 1.0f + (h & 7);
            return (h & 8) ? -g * f[0] : g * f[0];
        }
        case 2: {
            int h = hash & 7;
            float u = h < 4 ? f[0] : f[1];
            float v = h < 4 ? f[1] : f[0];
            return ((h & 1) ? -u : u) + ((h & 2) ? -2.0f * v : 2.0f * v);
        }
        case 3: {
            int h = hash & 15;
            float u = h < 8 ? f[0] : f[1];
            float v = h < 4 ? f[1] : (h == 12 || h == 14) ? f[0] : f[2];
            return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
        }
        default: {
            int h = hash & 31;
            float u = h < 24 ? f[0] : f[1];
            float v = h < 16 ? f[1] : f[2];
            float w = h < 8 ? f[2] : f[3];
            return ((h & 1) ? -u : u) + ((h & 2) ? -v : v) + ((h & 4) ? -w : w);
        }
    }
}

inline float Fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// The per-dimension rescaling to classic RenderMan noise's range (Gustavson, as in Aqsis).
constexpr float kNoiseScale[5] = {0.0f, 0.188f, 0.507f, 0.936f, 0.87f};

inline int PositiveMod(int a, int b) {
    int r = a % b;
    return r < 0 ? r + b : r;
}

// Signed gradient noise in about [-1, 1]; periods (nullable) wrap the lattice.
float SignedNoise(const float* x, int dims, const int* periods) {
    int cell[4];
    float frac[4], fade[4];
    for (int d = 0; d < dims; ++d) {
        float fl = std::floor(x[d]);
        cell[d] = static_cast<int>(fl);
        frac[d] = x[d] - fl;
        fade[d] = Fade(frac[d]);
    }
    float sum = 0.0f;
    for (int corner = 0; corner < (1 << dims); ++corner) {
        float weight = 1.0f, offset[4];
        int hash = 0;
        for (int d = dims - 1; d >= 0; --d) {
            int bit = (corner >> d) & 1;
            int index = cell[d] + bit;
            if (periods) index = PositiveMod(index, periods[d]);
            hash = Perm(index + hash);
            offset[d] = frac[d] - bit;
            weight *= bit ? fade[d] : 1.0f - fade[d];
        }
        sum += weight * Gradient(hash, offset, dims);
    }
    return kNoiseScale[dims] * sum;
}

float UnsignedNoise(const float* x, int dims, const int* periods) {
    return 0.5f * (1.0f + SignedNoise(x, dims, periods));
}

// Offsets for the second and third components of vector noise (Aqsis's values); further colour
// components (ColorSamples > 3) continue with multiples of the second offset.
const float kComponentOffsets[3][4] = {
    {0.0f, 0.0f, 0.0f, 0.0f}, {19.34f, 7.66f, 3.23f, 2.77f}, {5.47f, 17.85f, 11.04f, 13.19f}};

float ComponentOffset(int component, int d) {
    if (component < 3) return kComponentOffsets[component][d];
    return kComponentOffsets[1][d] * static_cast<float>(component);
}

// A 32-bit integer hash (the "lowbias32" finaliser of Wellons' hash prospector).
uint32_t Mix32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

float CellNoise(const float* x, int dims, int component) {
    uint32_t h = Mix32(0x9e3779b9U * static_cast<uint32_t>(component + 1));
    for (int d = 0; d < dims; ++d) {
        h = Mix32(h ^ static_cast<uint32_t>(static_cast<int32_t>(std::floor(x[d]))));
    }
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

enum class NoiseKind { Perlin, Periodic, Cell };

// Gathers the input coordinates of point p from arguments [first, last): floats give one
// coordinate, point-like arguments three. Returns the dimension count.
int GatherCoordinates(const BuiltinCall& call, int first, int last, int p, float* x) {
    int dims = 0;
    for (int a = first; a < last; ++a) {
        for (int c = 0; c < call.args[a].width && dims < 4; ++c) x[dims++] = call.args[a].At(c, p);
    }
    return dims;
}

template <NoiseKind Kind>
void NoiseKernel(const BuiltinCall& call) {
    const int w = call.result.width;
    // pnoise's arguments are the position followed by as many period arguments.
    const int positionArgs = Kind == NoiseKind::Periodic ? call.argCount / 2 : call.argCount;
    ForEachPoint(call, [&](int p) {
        float x[4], periodValues[4];
        int periods[4];
        const int dims = GatherCoordinates(call, 0, positionArgs, p, x);
        if (Kind == NoiseKind::Periodic) {
            GatherCoordinates(call, positionArgs, call.argCount, p, periodValues);
            for (int d = 0; d < dims; ++d) {
                periods[d] = std::max(1, static_cast<int>(std::floor(periodValues[d] + 0.5f)));
            }
        }
        for (int c = 0; c < w; ++c) {
            float value;
            if (Kind == NoiseKind::Cell) {
                value = CellNoise(x, dims, c);
            } else {
                float shifted[4];
                for (int d = 0; d < dims; ++d) shifted[d] = x[d] + ComponentOffset(c, d);
                value =
                    UnsignedNoise(shifted, dims, Kind == NoiseKind::Periodic ? periods : nullptr);
            }
            call.result.At(c, p) = value;
        }
    });
}

}  // namespace

void AddNoiseBuiltins(BuiltinList* list) {
    for (const char* t : {"f", "c", "p", "v"}) {
        for (const char* args : {"f", "ff", "p", "pf"}) {
            list->Add("noise", t, args, NoiseKernel<NoiseKind::Perlin>);
            list->Add("cellnoise", t, args, NoiseKernel<NoiseKind::Cell>);
        }
        for (const char* args : {"ff", "ffff", "pp", "pfpf"}) {
            list->Add("pnoise", t, args, NoiseKernel<NoiseKind::Periodic>);
        }
    }
}

}  // namespace gonio::sl::builtins
