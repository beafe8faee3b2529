#include "renderer/shading/area_light_samples.h"

#include <algorithm>

#include "base/hash.h"
#include "renderer/raytrace/transforms.h"

namespace gonio {
namespace {

float RadicalInverse2(uint32_t k) {
    k = (k << 16) | (k >> 16);
    k = ((k & 0x00ff00ffu) << 8) | ((k & 0xff00ff00u) >> 8);
    k = ((k & 0x0f0f0f0fu) << 4) | ((k & 0xf0f0f0f0u) >> 4);
    k = ((k & 0x33333333u) << 2) | ((k & 0xccccccccu) >> 2);
    k = ((k & 0x55555555u) << 1) | ((k & 0xaaaaaaaau) >> 1);
    return float(k) * 2.3283064365386963e-10f;
}

float RadicalInverse3(uint32_t k) {
    float inverse = 0, digit = 1.f / 3;
    for (; k > 0; k /= 3, digit /= 3) inverse += float(k % 3) * digit;
    return inverse;
}

// x + shift wrapped into [0, 1).
float Shift(float x, float shift) {
    const float y = x + shift >= 1 ? x + shift - 1 : x + shift;
    return std::min(y, 0x1.fffffep-1f);
}

}  // namespace

void AreaLightSamplePoints(const AreaLightGeometry& geometry, int k, int count,
                           const uint64_t* seeds, int n, const Imath::M44f& currentFromWorld,
                           AreaLightPoints* out) {
    out->P.resize(3 * size_t(n));
    out->N.resize(3 * size_t(n));
    out->weight.resize(size_t(n));
    const M44f worldFromCurrent = currentFromWorld.inverse();
    const float h0 = RadicalInverse3(uint32_t(k)), h1 = (k + 0.5f) / count,
                h2 = RadicalInverse2(uint32_t(k));
    for (int i = 0; i < n; ++i) {
        uint64_t state = seeds ? HashCombine(seeds[i], 0xa4ea11947u) : 0;
        const float s0 = seeds ? ToUnitFloat(SplitMix64(state)) : 0.f;
        const float s1 = seeds ? ToUnitFloat(SplitMix64(state)) : 0.f;
        const float s2 = seeds ? ToUnitFloat(SplitMix64(state)) : 0.f;
        const AreaLightSample s = geometry.Sample(Shift(h0, s0), Shift(h1, s1), Shift(h2, s2));
        const V3f P = TransformPoint(currentFromWorld, s.P);
        const V3f N = Normalized(TransformNormal(worldFromCurrent, s.N));
        for (int c = 0; c < 3; ++c)
            out->P[c * size_t(n) + i] = P[c], out->N[c * size_t(n) + i] = N[c];
        out->weight[i] = s.pdfArea > 0 ? 1 / (s.pdfArea * count) : 0;
    }
}

}  // namespace gonio
