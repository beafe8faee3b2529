// The built-in drivers against OpenImageIO's writers (through the plugin): the same spec and
// pixels written both ways must read back as the same pixels, windows, channels and metadata
// (all but the date, which is the time of writing).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>

#include "imageio/image_formats.h"
#include "imageio/oiio_plugin.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

struct Case {
    std::string format, extension;
    PixelType fileType;
    std::vector<std::string> channels;
    int alpha = -1, z = -1;
    std::string compression;
};

// For test names: the case as it reads, not as bytes.
void PrintTo(const Case& c, std::ostream* os) {
    *os << c.format << " ." << c.extension << " " << c.channels.size() << " channels";
    if (!c.compression.empty()) *os << " " << c.compression;
}

// Distinct values in and beyond [0, 1], with alpha from 0 (where PNG must not divide) to 1.
std::vector<float> TestPixels(int width, int height, int channels) {
    std::vector<float> pixels(size_t(width) * height * channels);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 37) / 29.0f - 0.1f;
    for (size_t p = 0; channels == 4 && p < pixels.size() / 4; ++p)
        pixels[p * 4 + 3] = float(p % 5) / 4.0f;
    return pixels;
}

ImageFileSpec SpecOf(const Case& c) {
    ImageFileSpec spec;
    spec.width = 7, spec.height = 40;  // more rows than a TIFF strip
    spec.x = 3, spec.y = 5, spec.fullWidth = 16, spec.fullHeight = 48;
    spec.channelNames = c.channels;
    spec.alphaChannel = c.alpha, spec.zChannel = c.z;
    spec.fileType = c.fileType;
    spec.compression = c.compression;
    spec.attributes = {{"Software", "gonio"}, {"ImageDescription", "a test"}};
    return spec;
}

struct ReadBack {
    OIIO::ImageSpec spec;
    std::vector<float> pixels;
};

ReadBack Read(const std::string& file) {
    ReadBack back;
    auto in = OIIO::ImageInput::open(file);
    EXPECT_TRUE(in) << file << ": " << OIIO::geterror();
    if (!in) return back;
    back.spec = in->spec();
    back.pixels.resize(back.spec.image_pixels() * back.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::FLOAT, back.pixels.data()));
    return back;
}

// Every attribute as text, but the date of writing.
std::map<std::string, std::string> Metadata(const OIIO::ImageSpec& spec) {
    std::map<std::string, std::string> metadata;
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (p.name() != "DateTime") metadata[p.name().string()] = p.get_string();
    return metadata;
}

class BuiltInDriver : public ::testing::TestWithParam<Case> {};

TEST_P(BuiltInDriver, WritesWhatOpenImageIOWrites) {
    const Case& c = GetParam();
    const ImageFileSpec spec = SpecOf(c);
    const std::vector<float> pixels = TestPixels(spec.width, spec.height, spec.Channels());
    const fs::path dir = fs::temp_directory_path() / ("gonio_driver_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string ours = (dir / ("ours." + c.extension)).string();
    const std::string theirs = (dir / ("theirs." + c.extension)).string();
    const PixelBuffer buffer{PixelType::Float, pixels.data()};
    ASSERT_EQ(BuiltInFormatForExtension(c.extension), c.format);
    ASSERT_EQ(WriteImageFile(c.format, ours, spec, buffer), "");
    ASSERT_EQ(LoadOiioPlugin("the test").WriteImage(c.format, theirs, spec, buffer), "");
    const ReadBack a = Read(ours), b = Read(theirs);
    fs::remove_all(dir);
    EXPECT_EQ(a.spec.format, b.spec.format);
    EXPECT_EQ(a.spec.channelnames, b.spec.channelnames);
    EXPECT_EQ(a.spec.alpha_channel, b.spec.alpha_channel);
    EXPECT_EQ(a.spec.z_channel, b.spec.z_channel);
    EXPECT_EQ(std::vector<int>({a.spec.x, a.spec.y, a.spec.full_width, a.spec.full_height}),
              std::vector<int>({b.spec.x, b.spec.y, b.spec.full_width, b.spec.full_height}));
    EXPECT_EQ(Metadata(a.spec), Metadata(b.spec));
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    for (size_t i = 0; i < a.pixels.size(); ++i)
        ASSERT_EQ(a.pixels[i], b.pixels[i]) << "sample " << i;
}

const std::vector<std::string> kRgba = {"R", "G", "B", "A"};

INSTANTIATE_TEST_SUITE_P(
    Formats, BuiltInDriver,
    ::testing::Values(Case{"tiff", "tif", PixelType::UInt8, kRgba, 3},
                      Case{"tiff", "tif", PixelType::UInt16, {"R", "G", "B"}},
                      Case{"tiff", "tiff", PixelType::Float, {"R", "G", "B", "A", "Z"}, 3, 4},
                      Case{"tiff", "tx", PixelType::UInt8, {"Y"}, -1, -1, "lzw"},
                      Case{"tiff", "tif", PixelType::Float, {"Z"}, -1, 0, "none"},
                      Case{"png", "png", PixelType::UInt8, kRgba, 3},
                      Case{"png", "png", PixelType::UInt16, kRgba, 3, -1, "rle"},
                      Case{"png", "png", PixelType::UInt16, {"A", "Z"}, 0, 1},
                      Case{"openexr", "exr", PixelType::Float, {"R", "G", "B", "A", "Z"}, 3, 4},
                      Case{"openexr", "exr", PixelType::Half, kRgba, 3, -1, "piz"},
                      Case{"openexr", "exr", PixelType::Float, {"N.x", "N.y"}, -1, -1, "dwaa"},
                      Case{"zfile", "zfile", PixelType::Float, {"Z"}, -1, 0},
                      Case{"zfile", "zfile", PixelType::Float, {"Z"}, -1, 0, "zip"}),
    [](const ::testing::TestParamInfo<Case>& info) {
        return info.param.format + "_" + std::to_string(info.index);
    });

TEST(ImageFormats, OnlyUnknownExtensionsAskOpenImageIO) {
    EXPECT_EQ(BuiltInFormatForExtension("TIF"), "tiff");
    EXPECT_EQ(BuiltInFormatForExtension("exr"), "openexr");
    EXPECT_EQ(BuiltInFormatForExtension("jpg"), "");
    EXPECT_EQ(FormatForFileName("photo.jpg"), "jpeg");
    EXPECT_EQ(FormatForFileName("frame.0001"), "");
    EXPECT_EQ(FormatForFileName("no_extension"), "");
}

}  // namespace
}  // namespace gonio
