// ShadingPointSharing: which camera-sample hits share one shaded point under a ShadingRate.

#include "renderer/frame/shading_points.h"

#include <gtest/gtest.h>

#include <deque>

namespace gonio {
namespace {

// Hits on a plane z = 10 seen head-on by a perspective camera whose pixel is 0.01 wide at
// distance 1 (0.1 at the plane).
class SharingTest : public ::testing::Test {
  protected:
    const SceneShape planeShape_{}, otherShape_{};
    ShadingPointSharing sharing_{0.f, 0.01f};
    std::deque<SurfacePoint> points_;  // stable addresses
    std::vector<ShadingPointHit> hits_;
    std::vector<int> shaded_, shadedBy_;

    void AddHit(float x, float y, const SceneShape* shape, Imath::V3f N = {0, 0, -1},
                float z = 10) {
        SurfacePoint& p = points_.emplace_back();
        p.shape = shape;
        p.P = {x * 0.1f, y * 0.1f, z};
        p.N = p.Ng = N.normalized();
        hits_.push_back({x, y, z, {0, 0, 1}, &p});
    }
    void Cluster(float rate) { sharing_.Cluster(hits_, rate, &shaded_, &shadedBy_); }
};

TEST_F(SharingTest, OneShadedPointPerPixelAtRateOne) {
    // 4x4 samples in each of two pixels.
    for (int px = 0; px < 2; ++px)
        for (int s = 0; s < 16; ++s)
            AddHit(px + (s % 4 + 0.5f) / 4, (s / 4 + 0.5f) / 4, &planeShape_);
    Cluster(1);
    // The samples nearest each pixel's centre are 5, 6, 9 and 10; the first of them is shaded.
    ASSERT_EQ(shaded_, (std::vector<int>{5, 21}));
    for (int i = 0; i < 32; ++i) EXPECT_EQ(shadedBy_[i], i < 16 ? 0 : 1) << i;
}

TEST_F(SharingTest, TwoSurfacesInAPixelEachShadeTheirSampleNearestTheCentre) {
    // 4x4 samples, the left two columns on one shape, the right two on another: of the four
    // samples nearest the centre (5, 6, 9, 10), 5 is the left's and 6 the right's first.
    for (int s = 0; s < 16; ++s)
        AddHit((s % 4 + 0.5f) / 4, (s / 4 + 0.5f) / 4, s % 4 < 2 ? &otherShape_ : &planeShape_);
    Cluster(1);
    ASSERT_EQ(shaded_, (std::vector<int>{5, 6}));
    for (int s = 0; s < 16; ++s) EXPECT_EQ(shadedBy_[s], s % 4 < 2 ? 0 : 1) << s;
}

TEST_F(SharingTest, LargerRatesShareAcrossPixels) {
    for (int py = 0; py < 4; ++py)
        for (int px = 0; px < 4; ++px) AddHit(px + 0.5f, py + 0.5f, &planeShape_);
    Cluster(4);  // 2x2-pixel cells
    EXPECT_EQ(shaded_.size(), 4u);
    Cluster(16);
    EXPECT_EQ(shaded_.size(), 1u);
    Cluster(0.25f);  // half-pixel cells: one sample in each, nothing shared
    EXPECT_EQ(shaded_.size(), 16u);
}

TEST_F(SharingTest, DifferentShapesCreasesAndDepthsAreNotShared) {
    AddHit(0.1f, 0.1f, &planeShape_);
    AddHit(0.2f, 0.1f, &otherShape_);                  // another shape
    AddHit(0.3f, 0.1f, &planeShape_, {1, 0, -0.5f});   // normal 63 degrees off: a crease
    AddHit(0.4f, 0.1f, &planeShape_, {0, 0, -1}, 20);  // the same shape much further away
    AddHit(0.5f, 0.1f, &planeShape_, {0, 0, 1});       // the back of the sheet
    AddHit(0.6f, 0.1f, &planeShape_, {0.1f, 0, -1});   // close enough: shared
    Cluster(1);
    // Hit 0, the furthest from the pixel's centre, is the only one that takes another's
    // shading: hit 5's, the fifth shaded.
    EXPECT_EQ(shaded_, (std::vector<int>{1, 2, 3, 4, 5}));
    EXPECT_EQ(shadedBy_[0], 4);
}

TEST_F(SharingTest, ARateOfOneSampleShadesEverySample) {
    EXPECT_FALSE(ShadingPointSharing::Shares(1.f / 16, 4, 4));
    EXPECT_TRUE(ShadingPointSharing::Shares(1.f / 8, 4, 4));
    EXPECT_FALSE(ShadingPointSharing::Shares(1, 1, 1));
    EXPECT_TRUE(ShadingPointSharing::Shares(1, 2, 1));
}

}  // namespace
}  // namespace gonio
