// SampleRandom: a pixel sample's stream is fixed by (seed, pixel, sample) alone, and values a
// caller does not need can be skipped without changing the ones after them (the camera does
// not draw its lens position without DepthOfField).
#include <gtest/gtest.h>

#include "base/random.h"

namespace gonio {
namespace {

TEST(SampleRandom, SkippingLeavesTheLaterValuesAsTheyWere) {
    SampleRandom read(42, 3, 7, 5), skipped(42, 3, 7, 5);
    for (int i = 0; i < 2; ++i) read.Next();
    skipped.Skip(2);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(skipped.Next(), read.Next()) << "value " << i;
}

TEST(SampleRandom, ThePixelHashGivesTheSameStream) {
    SampleRandom direct(9, -2, 11, 3), fromHash(SampleRandom::PixelHash(9, -2, 11), 3);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(direct.Next(), fromHash.Next());
    EXPECT_EQ(direct.Seed(), fromHash.Seed());
}

TEST(SampleRandom, OtherSamplesAndPixelsGiveOtherValues) {
    const float first = SampleRandom(1, 0, 0, 0).Next();
    EXPECT_NE(SampleRandom(1, 0, 0, 1).Next(), first);
    EXPECT_NE(SampleRandom(1, 1, 0, 0).Next(), first);
    EXPECT_NE(SampleRandom(2, 0, 0, 0).Next(), first);
}

}  // namespace
}  // namespace gonio
