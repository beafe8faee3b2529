// Reading reflectance images: the channel names of Fichet et al. 2021, and every file that is
// not one rejected with a message naming it.

#include "viewer/reflectance_image.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gonio::viewer {
namespace {

namespace fs = std::filesystem;

TEST(SpectralChannelName, ReadsCommaAndDotDecimals) {
    double nm = 0;
    EXPECT_TRUE(ParseSpectralChannelName("S0.552,50nm", &nm));
    EXPECT_DOUBLE_EQ(nm, 552.5);
    EXPECT_TRUE(ParseSpectralChannelName("S0.380nm", &nm));
    EXPECT_DOUBLE_EQ(nm, 380);
    EXPECT_TRUE(ParseSpectralChannelName("S0.400.25nm", &nm));
    EXPECT_DOUBLE_EQ(nm, 400.25);
    EXPECT_FALSE(ParseSpectralChannelName("R", &nm));
    EXPECT_FALSE(ParseSpectralChannelName("S1.550,00nm", &nm));  // polarised: not emissive S0
    EXPECT_FALSE(ParseSpectralChannelName("S0.550,00", &nm));
}

// Writes an EXR with the named float channels, every value `value`.
std::string WriteExr(const std::string& name, const std::vector<std::string>& channels,
                     float value) {
    const std::string path = (fs::temp_directory_path() / name).string();
    OIIO::ImageSpec spec(2, 2, int(channels.size()), OIIO::TypeDesc::FLOAT);
    spec.channelnames = channels;
    std::vector<float> pixels(4 * channels.size(), value);
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, spec) &&
                out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    return path;
}

void ExpectRejected(const std::string& path, const std::string& why) {
    try {
        ReadReflectanceImage(path);
        ADD_FAILURE() << path << " was accepted";
    } catch (const ViewerError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
}

TEST(ReadReflectanceImage, SortsTheChannelsByWavelength) {
    // The layout sorts channel names alphabetically in the file: 1000 nm before 500 nm.
    const std::string path =
        WriteExr("gonio_viewer_order.exr", {"S0.500,00nm", "S0.1000,00nm", "S0.700,00nm"}, 0.5f);
    const ReflectanceImage image = ReadReflectanceImage(path);
    EXPECT_EQ(image.wavelengths, (std::vector<double>{500, 700, 1000}));
    EXPECT_EQ(image.spectra.size(), 4u * 3);
    EXPECT_TRUE(image.previewRgb.empty());
}

TEST(ReadReflectanceImage, RejectsWhatIsNotOne) {
    ExpectRejected((fs::temp_directory_path() / "gonio_viewer_missing.exr").string(),
                   "cannot open");
    ExpectRejected(WriteExr("gonio_viewer_rgb.exr", {"R", "G", "B"}, 1), "no spectral channels");
    ExpectRejected(WriteExr("gonio_viewer_nan.exr", {"S0.400nm", "S0.500nm", "S0.600nm"}, NAN),
                   "not a finite number");
    const std::string truncated = (fs::temp_directory_path() / "gonio_viewer_bad.exr").string();
    std::ofstream(truncated) << "v/1\x01 not an EXR";
    ExpectRejected(truncated, "error");
}

// An image in a basis of two vectors whose header has the string attributes given.
std::string WriteBasisExr(const std::string& name,
                          const std::vector<std::pair<std::string, std::string>>& attributes) {
    const std::string path = (fs::temp_directory_path() / name).string();
    OIIO::ImageSpec spec(2, 2, 2, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"basis.00", "basis.01"};
    for (const auto& [key, value] : attributes) spec.attribute(key, value);
    std::vector<float> pixels(8, 0.5f);
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, spec) &&
                out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    return path;
}

TEST(ReadReflectanceImage, ReadsAnImageInABasis) {
    const ReflectanceImage image = ReadReflectanceImage(
        WriteBasisExr("gonio_viewer_basis.exr", {{"spectralBasisWavelengths", "400 500 600"},
                                                 {"spectralBasisVector.00", "1 0 0"},
                                                 {"spectralBasisVector.01", "0 0.5 2"}}));
    EXPECT_EQ(image.wavelengths, (std::vector<double>{400, 500, 600}));
    ASSERT_EQ(image.basis.cols(), 2);
    EXPECT_EQ(image.coefficients, std::vector<float>(8, 0.5f));
    EXPECT_EQ(image.spectra[0], 0.5f);  // basis · coefficients: 0.5, 0.25, 1
    EXPECT_EQ(image.spectra[1], 0.25f);
    EXPECT_EQ(image.spectra[2], 1.0f);
}

TEST(ReadReflectanceImage, RejectsABadBasisHeaderNamingTheFile) {
    ExpectRejected(WriteBasisExr("gonio_viewer_nobasis.exr", {}),
                   "a bad basis header: the header has no attribute \"spectralBasisWavelengths\"");
    ExpectRejected(
        WriteBasisExr("gonio_viewer_shortbasis.exr", {{"spectralBasisWavelengths", "400 500 600"},
                                                      {"spectralBasisVector.00", "1 0 0"}}),
        "\"spectralBasisVector.01\"");
    ExpectRejected(
        WriteBasisExr("gonio_viewer_textbasis.exr", {{"spectralBasisWavelengths", "400 500 600"},
                                                     {"spectralBasisVector.00", "1 0 0"},
                                                     {"spectralBasisVector.01", "0 one 0"}}),
        "\"one\", not a finite number");
}

}  // namespace
}  // namespace gonio::viewer
