// The colour space of spectral renders: what ColorSamples' matrices become for n samples.

#include "spectral/render_color_space.h"

#include <gtest/gtest.h>

#include "spectral/colorimetry.h"
#include "spectral/named_spectra.h"

namespace gonio::spectral {
namespace {

const RenderColorSpace& Space() {
    static const RenderColorSpace space = SampledColorSpace(ReferenceGrid());
    return space;
}

Rgb ToRgb(const std::vector<double>& samples) {
    const RenderColorSpace& s = Space();
    Rgb rgb = Rgb::Zero();
    for (size_t i = 0; i < samples.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[c] += samples[i] * s.toRgb[3 * i + c];
    return rgb;
}

TEST(RenderColorSpace, HasOneComponentPerSample) {
    EXPECT_EQ(Space().toRgb.size(), 3u * 81);
    EXPECT_EQ(Space().fromRgb.size(), 3u * 81);
}

// The scene's white is the equal-energy spectrum: a constant c displays as grey c.
TEST(RenderColorSpace, AConstantSpectrumIsGrey) {
    const Rgb rgb = ToRgb(std::vector<double>(81, 0.7));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 0.7, 1e-5);
}

// Every RGB becomes a spectrum of that RGB, and grey becomes a constant spectrum, so that a
// scene written in RGB renders the same under a white light.
TEST(RenderColorSpace, TheUpliftRoundTripsAndKeepsGreyFlat) {
    const RenderColorSpace& s = Space();
    for (int k = 0; k < 3; ++k) {
        std::vector<double> spectrum(81);
        for (int i = 0; i < 81; ++i) spectrum[i] = s.fromRgb[size_t(k) * 81 + i];
        const Rgb rgb = ToRgb(spectrum);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], c == k ? 1.0 : 0.0, 1e-5) << k << c;
    }
    for (int i = 0; i < 81; ++i)
        EXPECT_NEAR(s.fromRgb[i] + s.fromRgb[81 + i] + s.fromRgb[162 + i], 1.0, 1e-5) << i;
}

// The display RGB of a light sampled into the space has the light's own chromaticity, computed
// from the CIE tables by the colorimetry that reproduces the CIE white points. To 3e-4: the
// space scales each channel by up to 1e-4 so that its white is exactly grey (the sRGB matrix
// has four decimals), which moves chromaticities by about as much.
TEST(RenderColorSpace, ALightKeepsItsChromaticity) {
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), ReferenceGrid());
    const Xyz white = observer.cmf.rowwise().sum();
    for (const char* name : {"F11", "A", "D65"}) {
        const Spectrum light = NamedSpectrum(name);
        const std::vector<double> samples = light.Sample(ReferenceGrid());
        const Xyz viaSpace = BradfordAdapt(LinearSrgbToXyz(ToRgb(samples)), SrgbWhite(), white);
        const Eigen::Vector2d want = Chromaticity(EmissiveXyz(light, observer));
        const Eigen::Vector2d got = Chromaticity(viaSpace);
        EXPECT_NEAR(got.x(), want.x(), 3e-4) << name;
        EXPECT_NEAR(got.y(), want.y(), 3e-4) << name;
    }
}

}  // namespace
}  // namespace gonio::spectral
