// Option "spectral" end to end: a matte card facing the camera and a distant light shining
// along the view (N·L = 1), so that every pixel is exactly Cs·Cl (matte.sl with Kd 1). Rendered
// in process and read back, each pixel is compared with what the CIE colorimetry of spectral/
// says the product spectrum looks like.

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "spectral/colorimetry.h"
#include "spectral/named_spectra.h"
#include "tests/support/render_rib.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;
using spectral::Rgb;
using spectral::Xyz;

struct Rendered {
    std::string messages;
    int errors = 0;
    Rgb pixel = Rgb::Zero();  // the centre pixel
};

// Renders `options` + the card scene with `surface` (Color or Attribute lines) and `light`,
// into `image` (a scratch file when empty) with the Display mode `mode`.
Rendered Render(const std::string& options, const std::string& surface, const std::string& light,
                const std::string& mode = "rgba", std::string image = "") {
    const fs::path dir = fs::temp_directory_path() / "gonio_spectral_render";
    fs::create_directories(dir);
    const bool keep = !image.empty();
    if (!keep) image = (dir / "card.exr").string();
    const std::string rib =
        options + "\nFormat 4 4 1\nPixelSamples 1 1\nPixelFilter \"box\" 1 1\n" + "Display \"" +
        image + "\" \"openexr\" \"" + mode + "\"\n" +
        "Projection \"orthographic\"\nTranslate 0 0 5\nWorldBegin\n" + light + "\n" + surface +
        "\nSurface \"matte\" \"Kd\" 1\n"
        "Polygon \"P\" [-2 -2 0  2 -2 0  2 2 0  -2 2 0]\nWorldEnd\n";
    Rendered result;
    const test::RibRenderResult rendered = test::RenderRibString(rib, "card.rib");
    result.errors = rendered.errors;
    result.messages = rendered.messages;
    auto in = OIIO::ImageInput::open(image);
    if (!in) return result;
    std::vector<float> pixels(4 * 4 * 4);
    in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, pixels.data());
    const float* centre = &pixels[(2 * 4 + 2) * 4];
    result.pixel = Rgb(centre[0], centre[1], centre[2]);
    if (!keep) fs::remove(image);
    return result;
}

const char* const kSampled = "Option \"spectral\" \"basis\" \"sampled\"";
const char* const kBands = "Option \"spectral\" \"basis\" \"bands\" \"bands\" 16";
const char* const kSvd = "Option \"spectral\" \"basis\" \"svd\" \"vectors\" 6";
const char* const kLightAlongView =
    "LightSource \"distantlight\" 1 \"from\" [0 0 -1] \"to\" [0 0 0]";

// The XYZ of a display RGB, back in the scene's (equal-energy) white.
Xyz SceneXyz(const Rgb& rgb, const spectral::SampledObserver& observer) {
    const Xyz white = observer.cmf.rowwise().sum() / observer.cmf.row(1).sum();
    return spectral::BradfordAdapt(spectral::LinearSrgbToXyz(rgb), spectral::SrgbWhite(), white);
}

// A white card under a white light is the same picture in RGB, in 81 samples, in 16 bands and
// in 6 svd vectors, whether the light's colour is left at its default, given as RGB (uplifted) or
// as the spectrum E.
TEST(SpectralRender, NeutralSceneRendersAsInRgb) {
    const Rendered rgb = Render("", "", kLightAlongView);
    ASSERT_EQ(rgb.errors, 0) << rgb.messages;
    EXPECT_NEAR(rgb.pixel[0], 1.0, 1e-5);
    for (const char* light : {kLightAlongView,
                              "LightSource \"distantlight\" 1 \"from\" [0 0 -1] \"to\" [0 0 0] "
                              "\"lightcolor\" [1 1 1]",
                              "LightSource \"distantlight\" 1 \"from\" [0 0 -1] \"to\" [0 0 0] "
                              "\"lightcolor\" [\"E\"]"}) {
        for (const char* basis : {kSampled, kBands, kSvd}) {
            const Rendered spectral = Render(basis, "Color [1 1 1]", light);
            ASSERT_EQ(spectral.errors, 0) << spectral.messages;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(spectral.pixel[c], rgb.pixel[c], 2e-5) << basis << " " << light;
        }
    }
}

// The colour a render's centre pixel should have: Σ intensity · light ∘ TCS09, by the colour
// tables.
Xyz ProductXyz(const std::vector<std::pair<double, const char*>>& lights,
               const spectral::SampledObserver& observer) {
    const Eigen::VectorXd surface =
        spectral::SampleSpectrum(spectral::NamedSpectrum("TCS09"), spectral::ReferenceGrid());
    Eigen::VectorXd reflected = Eigen::VectorXd::Zero(surface.size());
    for (const auto& [intensity, name] : lights)
        reflected += intensity * spectral::SampleSpectrum(spectral::NamedSpectrum(name),
                                                          spectral::ReferenceGrid())
                                     .cwiseProduct(surface);
    return spectral::Tristimulus(reflected, observer) / observer.cmf.row(1).sum();
}

void ExpectColour(const Rendered& r, const Xyz& want, const spectral::SampledObserver& observer,
                  const std::string& label) {
    ASSERT_EQ(r.errors, 0) << r.messages;
    const Xyz got = SceneXyz(r.pixel, observer);
    // The float pipeline and the space's white correction (at most 1e-4 a channel) bound these.
    EXPECT_NEAR(got.y(), want.y(), 2e-4 * want.y() + 1e-6) << label;
    const Eigen::Vector2d xy = spectral::Chromaticity(got), wantXy = spectral::Chromaticity(want);
    EXPECT_NEAR(xy.x(), wantXy.x(), 3e-4) << label;
    EXPECT_NEAR(xy.y(), wantXy.y(), 3e-4) << label;
}

// TCS09 (a strong red) under F11 (a three-band fluorescent lamp): the pixel is the product
// spectrum's colour, whose chromaticity and luminance the colour tables give independently.
// So it is in the svd basis: the card is the frame's one surface, and 2 vectors (its l∘r and
// the light's own spectrum) hold it exactly.
TEST(SpectralRender, ASurfaceSpectrumUnderALightSpectrumHasTheProductsColour) {
    const spectral::SampledObserver observer =
        spectral::SampleObserver(spectral::NamedObserver("CIE1931"), spectral::ReferenceGrid());
    const Xyz want = ProductXyz({{1.0, "F11"}}, observer);
    for (const char* basis : {kSampled, "Option \"spectral\" \"basis\" \"svd\" \"vectors\" 2"})
        ExpectColour(Render(basis, "Attribute \"spectral\" \"color\" [\"TCS09\"]",
                            std::string(kLightAlongView) + " \"lightcolor\" [\"F11\"]"),
                     want, observer, basis);
}

// Lights of different spectra each get their own svd block (thesis §6.1.3's per-light images,
// added at display); two lights of one spectrum at different strengths share one.
TEST(SpectralRender, SvdAddsTheImagesOfEachLightSpectrum) {
    const spectral::SampledObserver observer =
        spectral::SampleObserver(spectral::NamedObserver("CIE1931"), spectral::ReferenceGrid());
    const std::string lights =
        "LightSource \"distantlight\" 1 \"from\" [0 0 -1] \"to\" [0 0 0] \"intensity\" 0.5 "
        "\"lightcolor\" [\"F11\"]\n"
        "LightSource \"distantlight\" 2 \"from\" [0 0 -1] \"to\" [0 0 0] \"intensity\" 0.25 "
        "\"lightcolor\" [\"A\"]\n"
        "LightSource \"distantlight\" 3 \"from\" [0 0 -1] \"to\" [0 0 0] \"intensity\" 0.5 "
        "\"lightcolor\" [\"A\"]\n"
        "LightSource \"distantlight\" 4 \"from\" [0 0 -1] \"to\" [0 0 0] \"intensity\" 0.1";
    const Xyz want = ProductXyz({{0.5, "F11"}, {0.75, "A"}, {0.1, "E"}}, observer);
    for (const char* basis : {kSampled, "Option \"spectral\" \"basis\" \"svd\" \"vectors\" 2"})
        ExpectColour(Render(basis, "Attribute \"spectral\" \"color\" [\"TCS09\"]", lights), want,
                     observer, basis);
    // One vector cannot hold both the light and its reflection: the test can fail.
    const Rendered one = Render("Option \"spectral\" \"basis\" \"svd\" \"vectors\" 1",
                                "Attribute \"spectral\" \"color\" [\"TCS09\"]", lights);
    EXPECT_GT((SceneXyz(one.pixel, observer) - want).norm(), 0.01 * want.norm());
}

// What the RGB renderer gets wrong: the same scene with both spectra reduced to RGB first.
TEST(SpectralRender, RgbOfTheSameSceneDiffers) {
    const Rendered sampled = Render(kSampled, "Attribute \"spectral\" \"color\" [\"TCS09\"]",
                                    std::string(kLightAlongView) + " \"lightcolor\" [\"F11\"]");
    // Each spectrum's own RGB, as an RGB scene would give them: the light's display RGB and
    // the surface's under the equal-energy white (its colour as reflectance).
    const Rendered light =
        Render(kSampled, "", std::string(kLightAlongView) + " \"lightcolor\" [\"F11\"]");
    const Rendered surface =
        Render(kSampled, "Attribute \"spectral\" \"color\" [\"TCS09\"]", kLightAlongView);
    const Rgb rgbProduct = light.pixel.cwiseProduct(surface.pixel);
    const spectral::SampledObserver observer =
        spectral::SampleObserver(spectral::NamedObserver("CIE1931"), spectral::ReferenceGrid());
    const Xyz white = SceneXyz(light.pixel, observer);
    const double de =
        spectral::Ciede2000(spectral::XyzToLab(SceneXyz(sampled.pixel, observer), white),
                            spectral::XyzToLab(SceneXyz(rgbProduct, observer), white));
    RecordProperty("rgb_vs_sampled_de2000", std::to_string(de));
    EXPECT_GT(de, 2.0) << "TCS09 under F11: RGB products should miss the spectral answer";
    // "basis" "rgb" reduces each spectrum to exactly that RGB and multiplies: the RGB renderer.
    const Rendered rgb = Render("Option \"spectral\" \"basis\" \"rgb\"",
                                "Attribute \"spectral\" \"color\" [\"TCS09\"]",
                                std::string(kLightAlongView) + " \"lightcolor\" [\"F11\"]");
    ASSERT_EQ(rgb.errors, 0) << rgb.messages;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(rgb.pixel[c], rgbProduct[c], 1e-5 + 1e-4 * rgbProduct[c]);
}

// Display mode "spectral": the layout of Fichet et al. 2021: the RGB preview, alpha, and one
// emissive channel "S0.<λ>nm" per sample (comma for the decimal point), each holding the
// product of the two spectra at its wavelength.
TEST(SpectralRender, SpectralDisplayWritesEverySample) {
    const std::string image = (fs::temp_directory_path() / "gonio_spectral_card.exr").string();
    const Rendered r =
        Render(kSampled, "Attribute \"spectral\" \"color\" [\"TCS09\"]",
               std::string(kLightAlongView) + " \"lightcolor\" [\"F11\"]", "spectral", image);
    ASSERT_EQ(r.errors, 0) << r.messages;
    auto in = OIIO::ImageInput::open(image);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    ASSERT_EQ(spec.nchannels, 4 + 81);
    EXPECT_EQ(spec.channelnames[0], "R");
    EXPECT_EQ(spec.channelnames[3], "A");
    EXPECT_EQ(spec.channelnames[4], "S0.380,00nm");
    EXPECT_EQ(spec.channelnames[4 + 34], "S0.550,00nm");
    EXPECT_EQ(spec.get_string_attribute("spectralLayoutVersion"), "1.0");
    std::vector<float> pixels(size_t(4 * 4 * spec.nchannels));
    in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
    in->close();
    const float* centre = &pixels[size_t(2 * 4 + 2) * spec.nchannels];
    const spectral::Spectrum f11 = spectral::NamedSpectrum("F11");
    const spectral::Spectrum tcs09 = spectral::NamedSpectrum("TCS09");
    for (int k : {0, 34, 80}) {
        const double nm = 380 + 5 * k;
        EXPECT_NEAR(centre[4 + k], f11.Evaluate(nm) * tcs09.Evaluate(nm), 1e-6) << nm;
    }
    EXPECT_FLOAT_EQ(centre[0], float(r.pixel[0])) << "the preview is the rgba image";
    fs::remove(image);
    // Without Option "spectral" there is nothing to write: a located error, no file.
    const Rendered rgb = Render("", "", kLightAlongView, "spectral", image);
    EXPECT_EQ(rgb.errors, 1);
    EXPECT_NE(rgb.messages.find("needs Option \"spectral\""), std::string::npos) << rgb.messages;
    EXPECT_FALSE(fs::exists(image));
}

TEST(SpectralRender, BadSpectraAreLocatedErrors) {
    Rendered r = Render(kSampled, "Attribute \"spectral\" \"color\" [\"NOSUCH\"]", kLightAlongView);
    EXPECT_EQ(r.errors, 1);
    EXPECT_NE(r.messages.find("card.rib:"), std::string::npos) << r.messages;
    EXPECT_NE(r.messages.find("NOSUCH"), std::string::npos) << r.messages;
    r = Render("", "Attribute \"spectral\" \"color\" [\"TCS09\"]", kLightAlongView);
    EXPECT_EQ(r.errors, 1);
    EXPECT_NE(r.messages.find("needs Option \"spectral\""), std::string::npos) << r.messages;
    r = Render("Option \"spectral\" \"basis\" \"sampled\" \"range\" [300 900]", "",
               kLightAlongView);
    EXPECT_GE(r.errors, 1) << "the observer's tables stop at 830 nm";
    r = Render("Option \"spectral\" \"basis\" \"wavelets\"", "", kLightAlongView);
    EXPECT_EQ(r.errors, 1);
    EXPECT_NE(r.messages.find("basis \"wavelets\""), std::string::npos) << r.messages;
}

}  // namespace
}  // namespace gonio
