// Relighting exactness (thesis §6.2.1): ribs/tcs_e.rib rendered under the equal-energy light E
// and relit with a light l must be the same scene rendered under l directly (same samples: the
// pattern does not depend on colour), to float precision.

#include "viewer/relight.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "spectral/named_spectra.h"
#include "tests/support/render_rib.h"
#include "viewer/reflectance_image.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

std::string ReadFile(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void Replace(std::string& text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
}

// ribs/tcs_e.rib lit by `light` instead of E, written to a scratch EXR (its path returned).
std::string RenderChart(const std::string& light) {
    std::string rib = ReadFile(fs::path(GONIO_SOURCE_DIR) / "ribs" / "tcs_e.rib");
    const fs::path dir = fs::temp_directory_path() / "gonio_viewer_relight";
    fs::create_directories(dir);
    const std::string image = (dir / (light + ".exr")).string();
    Replace(rib, "Display \"tcs_e.exr\"", "Display \"" + image + "\"");
    Replace(rib, "Display \"+tcs_e.png\" \"png\" \"rgba\"\n", "");
    Replace(rib, "\"lightcolor\" [\"E\"]", "\"lightcolor\" [\"" + light + "\"]");
    const test::RibRenderResult rendered = test::RenderRibString(rib, "tcs.rib");
    EXPECT_EQ(rendered.errors, 0) << rendered.messages;
    return image;
}

// l / e at the image's wavelengths, as the renderer samples a "lightcolor": the relighting light
// that turns the E render into the `light` render.
Eigen::VectorXd RelativeLight(const std::string& light, const std::vector<double>& nm) {
    const spectral::Spectrum l = spectral::NamedSpectrum(light), e = spectral::NamedSpectrum("E");
    Eigen::VectorXd values(nm.size());
    for (size_t i = 0; i < nm.size(); ++i)
        values[i] = double(float(l.Evaluate(nm[i]))) / double(float(e.Evaluate(nm[i])));
    return values;
}

// max |a − b| / |b| over the values of b above 1e-4 of its largest (the black background's
// zeros have no relative difference), and |a − b| / max|b| elsewhere.
double MaxRelativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
    float largest = 0;
    for (float v : b) largest = std::max(largest, std::abs(v));
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double scale = std::max(double(std::abs(b[i])), 1e-4 * largest);
        worst = std::max(worst, std::abs(double(a[i]) - double(b[i])) / scale);
    }
    return worst;
}

class Relighting : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        reflectance_ = new viewer::ReflectanceImage(viewer::ReadReflectanceImage(RenderChart("E")));
    }
    static void TearDownTestSuite() { delete reflectance_; }
    static const viewer::ReflectanceImage* reflectance_;
};
const viewer::ReflectanceImage* Relighting::reflectance_ = nullptr;

TEST_F(Relighting, TheReflectanceImageRelitIsTheDirectRender) {
    const viewer::ReflectanceImage& r = *reflectance_;
    ASSERT_EQ(r.SampleCount(), 81);
    const Eigen::Matrix3Xd cie =
        viewer::ConversionMatrix(viewer::RgbConversion::Cie, r.wavelengths);
    for (const std::string light : {"F11", "F2", "A", "D65"}) {
        const viewer::ReflectanceImage direct = viewer::ReadReflectanceImage(RenderChart(light));
        ASSERT_EQ(direct.wavelengths, r.wavelengths);
        const Eigen::VectorXd l = RelativeLight(light, r.wavelengths);
        const std::vector<float> relit = viewer::Relight(r, l, cie);
        const double rgbDifference = MaxRelativeDifference(relit, direct.previewRgb);
        RecordProperty("maxRelativeDifferenceRgb" + light, std::to_string(rgbDifference));
        EXPECT_LE(rgbDifference, 1e-5) << light;
        std::vector<float> relitSpectra(r.spectra.size());
        for (size_t p = 0; p < r.spectra.size(); ++p)
            relitSpectra[p] = float(r.spectra[p] * l[p % 81]);
        EXPECT_LE(MaxRelativeDifference(relitSpectra, direct.spectra), 1e-5) << light;
    }
}

TEST_F(Relighting, TheEqualEnergyLightGivesBackTheRendersPreview) {
    const viewer::ReflectanceImage& r = *reflectance_;
    const Eigen::Matrix3Xd cie =
        viewer::ConversionMatrix(viewer::RgbConversion::Cie, r.wavelengths);
    const std::vector<float> relit = viewer::Relight(r, Eigen::VectorXd::Ones(81), cie);
    EXPECT_LE(MaxRelativeDifference(relit, r.previewRgb), 1e-5);
}

TEST_F(Relighting, AnotherLightChangesTheImage) {
    const viewer::ReflectanceImage& r = *reflectance_;
    const Eigen::Matrix3Xd cie =
        viewer::ConversionMatrix(viewer::RgbConversion::Cie, r.wavelengths);
    const std::vector<float> relit = viewer::Relight(r, RelativeLight("F11", r.wavelengths), cie);
    EXPECT_GT(MaxRelativeDifference(relit, r.previewRgb), 0.05);  // the check above can fail
}

TEST(RgbConversion, BoxAveragesThirdsOfTheSamples) {
    std::vector<double> nm;
    for (int i = 0; i < 81; ++i) nm.push_back(380 + 5 * i);
    const Eigen::Matrix3Xd box = viewer::ConversionMatrix(viewer::RgbConversion::Box, nm);
    const Eigen::Vector3d grey = box * Eigen::VectorXd::Constant(81, 0.25);
    EXPECT_NEAR((grey - Eigen::Vector3d::Constant(0.25)).norm(), 0, 1e-15);
    Eigen::VectorXd blue = Eigen::VectorXd::Zero(81);
    blue.head(27).setOnes();  // 380-510 nm
    EXPECT_NEAR((box * blue - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
    for (int c = 0; c < 3; ++c) EXPECT_EQ((box.row(c).array() > 0).count(), 27);
    EXPECT_THROW(viewer::ParseRgbConversion("xyz"), viewer::ViewerError);
}

}  // namespace
}  // namespace gonio
