// The colour space of spectral renders: what ColorSamples' matrices become for n samples.

#include "spectral/render_color_space.h"

#include <gtest/gtest.h>

#include "spectral/colorimetry.h"
#include "spectral/named_spectra.h"
#include "spectral/spectral_error.h"

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

// Bands: the components and the display of a sampled spectrum (k rows of n, then k rows of 3).
std::vector<double> Components(const RenderColorSpace& bands, const Eigen::VectorXd& s) {
    const size_t n = size_t(s.size()), k = bands.fromSamples.size() / n;
    std::vector<double> c(k, 0.0);
    for (size_t b = 0; b < k; ++b)
        for (size_t i = 0; i < n; ++i) c[b] += bands.fromSamples[b * n + i] * s[Eigen::Index(i)];
    return c;
}

Rgb ComponentsRgb(const RenderColorSpace& bands, const std::vector<double>& c) {
    Rgb rgb = Rgb::Zero();
    for (size_t b = 0; b < c.size(); ++b)
        for (int ch = 0; ch < 3; ++ch) rgb[ch] += c[b] * bands.toRgb[3 * b + ch];
    return rgb;
}

Eigen::VectorXd Sampled(const char* name) {
    const std::vector<double> v = NamedSpectrum(name).Sample(ReferenceGrid());
    return Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
}

const std::vector<int> kEdges = {0, 6, 14, 20, 27, 33, 40, 47, 55, 62, 70, 81};

// F11's narrow lines make a light-weighted band the only way a box band can keep the light
// itself exact: its display through 11 bands is its display through the 81 samples.
TEST(BandColorSpace, TheLightItselfDisplaysExactly) {
    const Eigen::VectorXd f11 = Sampled("F11");
    const RenderColorSpace bands = BandColorSpace(ReferenceGrid(), kEdges, f11);
    EXPECT_EQ(bands.toRgb.size(), 3u * 11);
    EXPECT_EQ(bands.fromRgb.size(), 3u * 11);
    const std::vector<double> samples(f11.data(), f11.data() + f11.size());
    const Rgb want = ToRgb(samples), got = ComponentsRgb(bands, Components(bands, f11));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-4 * want.maxCoeff()) << c;
}

// A reflectance constant within each band, lit by the light: the product of the components
// displays as the product of the spectra (the one-bounce term is exact for such surfaces).
TEST(BandColorSpace, ABandwiseConstantReflectanceUnderTheLightIsExact) {
    const Eigen::VectorXd f11 = Sampled("F11");
    const RenderColorSpace bands = BandColorSpace(ReferenceGrid(), kEdges, f11);
    Eigen::VectorXd r(81);
    for (size_t b = 0; b + 1 < kEdges.size(); ++b)
        r.segment(kEdges[b], kEdges[b + 1] - kEdges[b]).setConstant(0.1 + 0.08 * double(b));
    const std::vector<double> cl = Components(bands, f11), cr = Components(bands, r);
    std::vector<double> product(cl.size());
    for (size_t b = 0; b < cl.size(); ++b) product[b] = cl[b] * cr[b];
    const Eigen::VectorXd exact = f11.cwiseProduct(r);
    const Rgb want = ToRgb(std::vector<double>(exact.data(), exact.data() + 81));
    const Rgb got = ComponentsRgb(bands, product);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-4 * want.maxCoeff()) << c;
}

// Under an equal-energy light the bands are plain means: constant spectra stay grey and RGB's
// uplift keeps grey flat, so a neutral scene renders as in "sampled" and "rgb".
TEST(BandColorSpace, UnderAConstantLightGreyStaysGrey) {
    const RenderColorSpace bands =
        BandColorSpace(ReferenceGrid(), kEdges, Eigen::VectorXd::Constant(81, 2.0));
    const Rgb grey = ComponentsRgb(bands, Components(bands, Eigen::VectorXd::Constant(81, 0.7)));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(grey[c], 0.7, 1e-5);
    for (size_t b = 0; b < 11; ++b)
        EXPECT_NEAR(bands.fromRgb[b] + bands.fromRgb[11 + b] + bands.fromRgb[22 + b], 1.0, 1e-5);
}

TEST(BandColorSpace, RejectsEdgesThatDoNotPartitionTheSamples) {
    const Eigen::VectorXd e = Eigen::VectorXd::Ones(81);
    EXPECT_THROW(BandColorSpace(ReferenceGrid(), {0, 40, 40, 81}, e), SpectralError);
    EXPECT_THROW(BandColorSpace(ReferenceGrid(), {0, 40, 80}, e), SpectralError);
    EXPECT_THROW(BandColorSpace(ReferenceGrid(), {0, 81}, Eigen::VectorXd::Ones(80)),
                 SpectralError);
}

std::vector<Eigen::VectorXd> TestColours(int count) {
    std::vector<Eigen::VectorXd> surfaces;
    for (int j = 1; j <= count; ++j) {
        const std::string name = std::string(j < 10 ? "TCS0" : "TCS") + std::to_string(j);
        surfaces.push_back(Sampled(name.c_str()));
    }
    return surfaces;
}

// The basis is turned so that white under the light has every coordinate 1.
TEST(LightSvdBasis, WhiteUnderTheLightHasCoordinatesOne) {
    const Eigen::VectorXd f11 = Sampled("F11");
    for (int k : {1, 3, 6, 20}) {
        const Eigen::MatrixXd basis = LightSvdBasis(f11, TestColours(8), k);
        ASSERT_EQ(basis.cols(), k);
        // B·1 is the light's projection onto the span: what is left is orthogonal to it, and
        // nothing once the span holds every product (8 surfaces and white: 9 vectors).
        const Eigen::VectorXd rest = f11 - basis * Eigen::VectorXd::Ones(k);
        EXPECT_LT((basis.transpose() * rest).norm(), 1e-9 * f11.norm() * basis.norm()) << k;
        if (k >= 9) EXPECT_LT(rest.norm(), 1e-9 * f11.norm()) << k;
        // A scaled rotation of orthonormal vectors: its columns stay orthogonal and equally long.
        const Eigen::MatrixXd gram = basis.transpose() * basis;
        EXPECT_LT((gram - gram(0, 0) * Eigen::MatrixXd::Identity(k, k)).norm(), 1e-9 * gram(0, 0));
    }
    EXPECT_THROW(LightSvdBasis(f11, TestColours(2), 0), SpectralError);
    EXPECT_THROW(LightSvdBasis(f11, TestColours(2), 82), SpectralError);
}

// Thesis §6.1.3 done exactly for direct light: each light spectrum its own block, a light its
// block's components 1, a reflectance the coordinates of its product with each block's light.
// The component-wise product then displays as the spectral product, light by light, and a
// white surface as the light.
TEST(SvdColorSpace, LightTimesReflectanceIsTheProjectedProduct) {
    const std::vector<Eigen::VectorXd> surfaces = TestColours(8);
    const Eigen::VectorXd f11 = Sampled("F11"), a = Sampled("A");
    // 9 vectors hold the 8 products and the light: exact; 4 only project them.
    for (int k : {9, 4}) {
        const RenderColorSpace space = SvdColorSpace(
            ReferenceGrid(),
            {{f11, LightSvdBasis(f11, surfaces, k)}, {a, LightSvdBasis(a, surfaces, k)}});
        ASSERT_EQ(space.toRgb.size(), size_t(3 * 2 * k));
        ASSERT_EQ(space.fromRgb.size(), size_t(3 * 2 * k));
        const std::vector<double> white = Components(space, Eigen::VectorXd::Ones(81));
        for (double c : white) EXPECT_NEAR(c, 1.0, 1e-6);
        for (int light = 0; light < 2; ++light) {
            std::vector<double> mask(size_t(2 * k), 0.0);
            for (int c = 0; c < k; ++c) mask[size_t(light * k + c)] = 1.0;
            const Eigen::VectorXd& l = light == 0 ? f11 : a;
            double worst = 0;
            for (const Eigen::VectorXd& r : surfaces) {
                std::vector<double> product = Components(space, r);
                for (size_t c = 0; c < product.size(); ++c) product[c] *= mask[c];
                const Eigen::VectorXd exact = l.cwiseProduct(r);
                const Rgb want = ToRgb(std::vector<double>(exact.data(), exact.data() + 81));
                worst =
                    std::max(worst, (ComponentsRgb(space, product) - want).norm() / want.norm());
            }
            if (k == 9)
                EXPECT_LT(worst, 1e-5) << light;
            else
                EXPECT_GT(worst, 1e-3) << light << ": 4 vectors should not hold 9 spectra";
        }
    }
}

}  // namespace
}  // namespace gonio::spectral
