// The built-in drivers against OpenImageIO's writers (through the plugin): the same spec and
// pixels written both ways must read back as the same pixels, windows, channels and metadata
// (all but the date, which is the time of writing).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <tiffio.h>
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

// Each strip's bytes as stored (compressed).
std::vector<std::vector<unsigned char>> RawStrips(const std::string& file) {
    std::vector<std::vector<unsigned char>> strips;
    TIFF* tif = TIFFOpen(file.c_str(), "r");
    EXPECT_TRUE(tif) << file;
    if (!tif) return strips;
    uint64_t* sizes = nullptr;
    EXPECT_TRUE(TIFFGetField(tif, TIFFTAG_STRIPBYTECOUNTS, &sizes));
    for (uint32_t s = 0; sizes && s < TIFFNumberOfStrips(tif); ++s) {
        std::vector<unsigned char> bytes(size_t(sizes[s]));
        EXPECT_EQ(TIFFReadRawStrip(tif, s, bytes.data(), tmsize_t(bytes.size())),
                  tmsize_t(bytes.size()));
        strips.push_back(bytes);
    }
    TIFFClose(tif);
    return strips;
}

// The same pixels through libtiff's own deflate codec, tagged as the driver tags them.
void WriteWithLibtiff(const std::string& file, const std::vector<uint16_t>& codes, int width,
                      int height, int channels, int bits, int quality) {
    TIFF* tif = TIFFOpen(file.c_str(), "w");
    ASSERT_TRUE(tif);
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, uint32_t(width));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, uint32_t(height));
    TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, uint32_t(32));
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, uint16_t(channels));
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, uint16_t(bits));
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
    TIFFSetField(tif, TIFFTAG_ZIPQUALITY, quality);
    const size_t rowSamples = size_t(width) * channels;
    for (int y = 0, strip = 0; y < height; y += 32, ++strip) {
        const int rows = std::min(32, height - y);
        std::vector<unsigned char> bytes;
        for (size_t i = size_t(y) * rowSamples; i < size_t(y + rows) * rowSamples; ++i) {
            if (bits == 16) {
                const unsigned char* b = reinterpret_cast<const unsigned char*>(&codes[i]);
                bytes.insert(bytes.end(), b, b + 2);
            } else {
                bytes.push_back((unsigned char)codes[i]);
            }
        }
        ASSERT_GE(TIFFWriteEncodedStrip(tif, uint32_t(strip), bytes.data(), tmsize_t(bytes.size())),
                  0);
    }
    TIFFClose(tif);
}

TEST(TiffDriver, DeflateStripsAreLibtiffsOwnAtEveryQuality) {
    // The driver predicts and compresses deflate strips itself, all at once: they must be the
    // bytes libtiff's codec makes, for 8 and 16 bits, whole strips and the last part one.
    const int width = 53, height = 100, channels = 3;
    const fs::path dir = fs::temp_directory_path() / ("gonio_strips_" + std::to_string(getpid()));
    fs::create_directories(dir);
    for (const int bits : {8, 16}) {
        const float one = bits == 8 ? 255.0f : 65535.0f;
        std::vector<float> pixels(size_t(width) * height * channels);
        std::vector<uint16_t> codes(pixels.size());
        for (size_t i = 0; i < pixels.size(); ++i) {
            // Smooth ramps with some noise: what a predictor and deflate meet in renders.
            codes[i] = uint16_t(((i / 3) % 97) * (one / 96) * 0.9f + (i * 7919 % 13));
            pixels[i] = codes[i] / one;
        }
        for (int quality = 1; quality <= 9; ++quality) {
            ImageFileSpec spec;
            spec.width = width, spec.height = height;
            spec.channelNames = {"R", "G", "B"};
            spec.fileType = bits == 8 ? PixelType::UInt8 : PixelType::UInt16;
            spec.compression = "zip:" + std::to_string(quality);
            const std::string ours = (dir / "ours.tif").string();
            const std::string theirs = (dir / "theirs.tif").string();
            ASSERT_EQ(WriteImageFile("tiff", ours, spec, {PixelType::Float, pixels.data()}), "");
            WriteWithLibtiff(theirs, codes, width, height, channels, bits, quality);
            const auto a = RawStrips(ours), b = RawStrips(theirs);
            ASSERT_EQ(a.size(), 4u);
            EXPECT_EQ(a, b) << bits << " bits, quality " << quality;
        }
    }
    fs::remove_all(dir);
}

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
