// ΔE2000 of two images: an image against itself, a pure lightness step (whose CIEDE2000 is
// ΔL / S_L, Sharma et al. 2005 eq. 17 and 20, with no chroma or hue terms), the statistics, and
// the map's colours.

#include "spectral/image_difference.h"

#include <gtest/gtest.h>

#include <cmath>

#include "spectral/spectral_error.h"

namespace gonio::spectral {
namespace {

TEST(ImageDifference, AnImageAgainstItselfIsZero) {
    const std::vector<Rgb> image = {Rgb(0.2, 0.5, 0.1), Rgb(1, 1, 1), Rgb(0, 0, 0)};
    const ImageDifference d = CompareImages(image, image, SrgbWhite());
    EXPECT_EQ(d.mean, 0);
    EXPECT_EQ(d.max, 0);
}

// Grey 1 against grey 0.5 relative to D65 at Y = 1: L* 100 against 116 · 0.5^(1/3) − 16.
TEST(ImageDifference, ALightnessStepIsDeltaLOverSl) {
    const double l2 = 116 * std::cbrt(0.5) - 16, mean = (100 + l2) / 2;
    const double sl =
        1 + 0.015 * (mean - 50) * (mean - 50) / std::sqrt(20 + (mean - 50) * (mean - 50));
    const std::vector<Rgb> reference(4, Rgb(1, 1, 1));
    std::vector<Rgb> image = reference;
    image[3] = Rgb(0.5, 0.5, 0.5);
    const ImageDifference d = CompareImages(reference, image, SrgbWhite());
    EXPECT_NEAR(d.max, (100 - l2) / sl, 1e-6);
    EXPECT_NEAR(d.mean, d.max / 4, 1e-9);
    EXPECT_EQ(d.p99, 0) << "the 99th percentile of 4 values is the 3rd";
    EXPECT_EQ(d.perPixel.size(), 4u);
}

TEST(ImageDifference, TheWhiteHasTheLightsChromaticityAndTheBrightestLuminance) {
    const std::vector<Rgb> reference = {Rgb(0.1, 0.1, 0.1), Rgb(0.4, 0.4, 0.4)};
    const Xyz white = BrightestPixelWhite(reference, Rgb(2, 1, 0.5));
    EXPECT_NEAR(white.y(), LinearSrgbToXyz(Rgb(0.4, 0.4, 0.4)).y(), 1e-12);
    const Eigen::Vector2d xy = Chromaticity(white),
                          want = Chromaticity(LinearSrgbToXyz(Rgb(2, 1, 0.5)));
    EXPECT_NEAR(xy.x(), want.x(), 1e-12);
    EXPECT_NEAR(xy.y(), want.y(), 1e-12);
}

TEST(ImageDifference, ImagesOfDifferentSizesAreAnError) {
    EXPECT_THROW(CompareImages({Rgb(1, 1, 1)}, {}, SrgbWhite()), SpectralError);
    EXPECT_THROW(BrightestPixelWhite({Rgb(1, 1, 1)}, Rgb(0, 0, 0)), SpectralError);
}

TEST(ImageDifference, TheMapRunsFromBlackThroughRedAndYellowToWhite) {
    EXPECT_EQ(DifferenceColour(0, 5), Rgb(0, 0, 0));
    EXPECT_EQ(DifferenceColour(5.0 / 3, 5), Rgb(1, 0, 0));
    EXPECT_EQ(DifferenceColour(10.0 / 3, 5), Rgb(1, 1, 0));
    EXPECT_EQ(DifferenceColour(7, 5), Rgb(1, 1, 1));
}

}  // namespace
}  // namespace gonio::spectral
