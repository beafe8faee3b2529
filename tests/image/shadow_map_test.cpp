// Percentage-closer filtering (renderer/image/shadow_map.h) against the filter region's
// geometry: across a straight depth edge the fraction in shadow is the fraction of the region
// behind the edge, to within one column of strata; the region is the footprint's image in the
// map plus the blur; the default bias removes a tilted plane's self-shadowing that a zero bias
// leaves.
#include "renderer/image/shadow_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gonio {
namespace {

constexpr int kSize = 64;
constexpr float kInf = std::numeric_limits<float>::infinity();

// An orthographic map seeing world x, y in [-1, 1]² along +z: s = (x + 1) / 2, t = (1 − y) / 2.
// Texels left of the middle hold depth 1, the others nothing.
ShadowMap EdgeMap() {
    std::vector<float> depth(kSize * kSize, kInf);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize / 2; ++x) depth[y * kSize + x] = 1;
    return ShadowMap(kSize, kSize, depth, Imath::M44f(), Imath::M44f());
}

// The part of a region of width `region` centred on s that lies left of s = 0.5.
float FractionLeftOfEdge(float s, float region) {
    return std::clamp((0.5f - (s - region / 2)) / region, 0.f, 1.f);
}

Imath::V3f AtS(float s) { return Imath::V3f(2 * s - 1, 0.1f, 5); }

TEST(ShadowMap, BlurredEdgeGivesTheFractionOfTheRegionBehindIt) {
    const ShadowMap map = EdgeMap();
    ShadowFilter filter;
    filter.samples = 256;  // 16 × 16 strata
    filter.sblur = filter.tblur = 0.25f;
    filter.bias = 0;
    for (float offset : {-0.3f, -0.125f, -0.1f, -0.05f, -0.01f, 0.f, 0.03f, 0.1f, 0.125f, 0.2f}) {
        const float s = 0.5f + offset;
        const float want = FractionLeftOfEdge(s, 0.25f);
        for (uint64_t seed : {1u, 2u, 3u}) {
            const float got = map.Occlusion(AtS(s), 0, filter, seed);
            // Only the column of strata the edge crosses can differ from the exact fraction.
            EXPECT_NEAR(got, want, 1.0f / 16) << "s " << s << " seed " << seed;
            if (want == 0 || want == 1) {
                EXPECT_EQ(got, want) << "s " << s;
            }
        }
    }
}

TEST(ShadowMap, JitterIsDeterministicAndUnbiased) {
    const ShadowMap map = EdgeMap();
    ShadowFilter filter;
    filter.samples = 16;
    filter.sblur = filter.tblur = 0.25f;
    filter.bias = 0;
    const float s = 0.53f, want = FractionLeftOfEdge(s, 0.25f);
    EXPECT_EQ(map.Occlusion(AtS(s), 0, filter, 7), map.Occlusion(AtS(s), 0, filter, 7));
    double sum = 0;
    const int seeds = 4000;
    for (int seed = 0; seed < seeds; ++seed) sum += map.Occlusion(AtS(s), 0, filter, seed);
    EXPECT_NEAR(sum / seeds, want, 0.005);
}

TEST(ShadowMap, FootprintTimesWidthSetsTheRegion) {
    const ShadowMap map = EdgeMap();
    ShadowFilter filter;
    filter.samples = 256;
    filter.bias = 0;
    // A footprint 0.25 wide in world units is 0.125 of the map (which spans 2 units); width 2
    // doubles it to 0.25.
    filter.swidth = filter.twidth = 2;
    for (float offset : {-0.2f, -0.1f, -0.05f, 0.f, 0.06f, 0.12f, 0.2f}) {
        const float s = 0.5f + offset;
        EXPECT_NEAR(map.Occlusion(AtS(s), 0.25f, filter, 5), FractionLeftOfEdge(s, 0.25f),
                    1.0f / 16)
            << "s " << s;
    }
}

TEST(ShadowMap, NoFilterStillCoversOneTexel) {
    const ShadowMap map = EdgeMap();
    ShadowFilter filter;
    filter.samples = 1024;
    filter.bias = 0;
    const float texel = 1.0f / kSize;
    // Half a texel left of the edge: half of a one-texel region lies behind it.
    EXPECT_NEAR(map.Occlusion(AtS(0.5f - texel / 2), 0, filter, 3), 1.0f, 1.0f / 32);
    EXPECT_NEAR(map.Occlusion(AtS(0.5f), 0, filter, 3), 0.5f, 1.0f / 32);
    EXPECT_EQ(map.Occlusion(AtS(0.5f + 2 * texel), 0, filter, 3), 0.0f);
}

TEST(ShadowMap, PerspectiveMapProjectsThroughItsCamera) {
    // A perspective map with a 90° field of view: screen x = x / z. An occluder at depth 2 fills
    // the left half.
    std::vector<float> depth(kSize * kSize, kInf);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize / 2; ++x) depth[y * kSize + x] = 2;
    const Imath::M44f perspective(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, -1, 0);
    const ShadowMap map(kSize, kSize, depth, Imath::M44f(), perspective);
    ShadowFilter filter;
    filter.bias = 0.01f;
    EXPECT_EQ(map.Occlusion(Imath::V3f(-1, 0.5f, 4), 0, filter, 1), 1.0f);     // s = 0.375
    EXPECT_EQ(map.Occlusion(Imath::V3f(1, 0.5f, 4), 0, filter, 1), 0.0f);      // s = 0.625
    EXPECT_EQ(map.Occlusion(Imath::V3f(-1, 0.5f, 1.5f), 0, filter, 1), 0.0f);  // in front
    EXPECT_EQ(map.Occlusion(Imath::V3f(-1, 0.5f, -4), 0, filter, 1), 0.0f);    // behind it
    EXPECT_EQ(map.Occlusion(Imath::V3f(-9, 0.5f, 4), 0, filter, 1), 0.0f);     // off the map
}

TEST(ShadowMap, DefaultBiasRemovesSelfShadowingOfATiltedPlane) {
    // A plane at 45° to the map's view, z = 5 + x, each texel holding the nearest depth it
    // covers (as a min-filtered depth render does).
    std::vector<float> depth(kSize * kSize);
    const float texel = 2.0f / kSize;  // world units
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) depth[y * kSize + x] = 5 + (-1 + x * texel);
    const ShadowMap map(kSize, kSize, depth, Imath::M44f(), Imath::M44f());
    ShadowFilter unbiased, biased;
    unbiased.bias = 0;
    int acne = 0, shadowed = 0;
    for (int i = 0; i < 200; ++i) {
        const float x = -0.9f + 1.8f * (i + 0.37f) / 200;
        const Imath::V3f P(x, 0.3f, 5 + x);
        acne += map.Occlusion(P, 0, unbiased, i) > 0;
        shadowed += map.Occlusion(P, 0, biased, i) > 0;
    }
    EXPECT_GT(acne, 100) << "a zero bias should shadow the plane by itself";
    EXPECT_EQ(shadowed, 0);
}

}  // namespace
}  // namespace gonio
