// Writes images through WriteDisplay and reads them back with OpenImageIO (a test may include it).
#include "renderer/image/image_writer.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <tuple>
#include <vector>

#include "tests/support/captured_diagnostics.h"
#include "tests/support/test_folder.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kChannelNames = {"r", "g", "b", "a", "z", "N.x", "N.y", "N.z"};
const Quantization kNoDither{255, 0, 255, 0.0f};
const Quantization kFloat{0, 0, 0, 0.0f};

// A 5x3 image with distinct values per pixel and channel; z is infinite in the first column.
Image TestImage() {
    Image image;
    image.width = 5;
    image.height = 3;
    image.channels = int(kChannelNames.size());
    image.fullWidth = 5;
    image.fullHeight = 3;
    image.pixels.resize(size_t(image.width) * image.height * image.channels);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            float* p = image.At(x, y);
            p[0] = 0.1f * x;
            p[1] = 0.2f * y;
            p[2] = 0.05f * (x + y);
            p[3] = 0.5f + 0.1f * x;
            p[4] = x == 0 ? std::numeric_limits<float>::infinity() : 2.5f * x + y;
            p[5] = -0.5f;
            p[6] = 0.25f * y;
            p[7] = 3.0f;
        }
    }
    return image;
}

// A scratch folder per test case.
class TempDir : public test::TestFolder {
  public:
    TempDir() : TestFolder("gonio_image_test_") {}
};

using test::CapturedDiagnostics;

struct ReadBack {
    OIIO::ImageSpec spec;
    std::string format;
    std::vector<float> pixels;  // converted to float by OpenImageIO (integers normalised)
};

ReadBack Read(const std::string& file) {
    ReadBack result;
    auto in = OIIO::ImageInput::open(file);
    EXPECT_TRUE(in) << file << ": " << OIIO::geterror();
    if (!in) return result;
    result.spec = in->spec();
    result.format = in->format_name();
    result.pixels.resize(size_t(result.spec.width) * result.spec.height * result.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::FLOAT, result.pixels.data()))
        << in->geterror();
    return result;
}

DisplaySpec Display(const std::string& name, const std::string& type, const std::string& mode) {
    DisplaySpec display;
    display.name = name;
    display.type = type;
    display.mode = mode;
    display.loc.file = std::make_shared<const std::string>("scene.rib");
    display.loc.line = 3;
    return display;
}

TEST(ImagingPipeline, ExposureAppliesGainThenInverseGamma) {
    EXPECT_FLOAT_EQ(ApplyExposure(0.25f, {2.0f, 1.0f}), 0.5f);
    EXPECT_FLOAT_EQ(ApplyExposure(0.5f, {1.0f, 2.2f}), std::pow(0.5f, 1 / 2.2f));
    EXPECT_FLOAT_EQ(ApplyExposure(0.2f, {1.5f, 2.0f}), std::sqrt(0.3f));
    EXPECT_FLOAT_EQ(ApplyExposure(0.0f, {1.0f, 2.0f}), 0.0f);
    EXPECT_FLOAT_EQ(ApplyExposure(-0.5f, {2.0f, 2.0f}), -1.0f);  // no NaN from a negative
}

TEST(ImagingPipeline, QuantizeRoundsAndClamps) {
    EXPECT_EQ(QuantizeValue(0.5f, kNoDither, 0, 0, 0), 128);  // 127.5 rounds up
    EXPECT_EQ(QuantizeValue(0.2f, kNoDither, 0, 0, 0), 51);
    EXPECT_EQ(QuantizeValue(1.7f, kNoDither, 0, 0, 0), 255);
    EXPECT_EQ(QuantizeValue(-0.3f, kNoDither, 0, 0, 0), 0);
    EXPECT_EQ(QuantizeValue(std::numeric_limits<float>::infinity(), kNoDither, 0, 0, 0), 255);
    Quantization tenBit{1023, 16, 1000, 0.0f};
    EXPECT_EQ(QuantizeValue(0.0f, tenBit, 0, 0, 0), 16);
    EXPECT_EQ(QuantizeValue(1.0f, tenBit, 0, 0, 0), 1000);
    EXPECT_EQ(QuantizeValue(0.5f, tenBit, 0, 0, 0), 512);
    // RISpec's round: halves away from zero, on both sides of a range that reaches below 0.
    const Quantization signedRange{2, -1024, 3071, 0.0f};
    EXPECT_EQ(QuantizeValue(1.25f, signedRange, 0, 0, 0), 3);
    EXPECT_EQ(QuantizeValue(-1.25f, signedRange, 0, 0, 0), -3);
    EXPECT_EQ(QuantizeValue(-1.2f, signedRange, 0, 0, 0), -2);
    EXPECT_EQ(QuantizeValue(-1e9f, signedRange, 0, 0, 0), -1024);
}

TEST(ImagingPipeline, DitherStaysWithinItsAmplitudeAndIsFixedPerPixel) {
    Quantization q;  // RISpec default: 255 0 255 0.5
    int low = 0, high = 0;
    double sum = 0.0;
    const int n = 64;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            // 255 * 0.3 = 76.5; the dither of ±0.5 rounds to 76 or 77 only.
            int code = QuantizeValue(0.3f, q, x, y, 1);
            ASSERT_GE(code, 76);
            ASSERT_LE(code, 77);
            (code == 76 ? low : high)++;
            sum += code;
            EXPECT_EQ(code, QuantizeValue(0.3f, q, x, y, 1));
        }
    }
    EXPECT_GT(low, n * n / 4);  // both codes occur, in roughly equal numbers
    EXPECT_GT(high, n * n / 4);
    EXPECT_NEAR(sum / (n * n), 76.5, 0.05);
    // Amplitude 2: never more than 2 codes from the undithered value.
    Quantization wide{255, 0, 255, 2.0f};
    for (int x = 0; x < 500; ++x) {
        int code = QuantizeValue(0.5f, wide, x, 7, 0);
        EXPECT_GE(code, 125);
        EXPECT_LE(code, 130);
    }
}

TEST(DisplayChannels, ModesPickTheirChannels) {
    std::string error;
    EXPECT_EQ(SelectDisplayChannels("rgb", kChannelNames, error), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(SelectDisplayChannels("rgba", kChannelNames, error), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(SelectDisplayChannels("rgbaz", kChannelNames, error),
              (std::vector<int>{0, 1, 2, 3, 4}));
    EXPECT_EQ(SelectDisplayChannels("rgbz", kChannelNames, error), (std::vector<int>{0, 1, 2, 4}));
    EXPECT_EQ(SelectDisplayChannels("az", kChannelNames, error), (std::vector<int>{3, 4}));
    EXPECT_EQ(SelectDisplayChannels("z", kChannelNames, error), (std::vector<int>{4}));
    EXPECT_EQ(SelectDisplayChannels("N", kChannelNames, error), (std::vector<int>{5, 6, 7}));
    EXPECT_TRUE(SelectDisplayChannels("Ci", kChannelNames, error).empty());
    EXPECT_NE(error.find("Ci"), std::string::npos);
    EXPECT_TRUE(SelectDisplayChannels("rgbz", {"r", "g", "b", "a"}, error).empty());
    EXPECT_NE(error.find("\"z\""), std::string::npos) << error;
}

TEST(WriteDisplay, TiffRgbaEightBitReadsBack) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    Image image = TestImage();
    std::string file = dir.File("out.tif");
    ASSERT_TRUE(WriteDisplay(Display(file, "file", "rgba"), image, kChannelNames, Exposure{},
                             kNoDither, kFloat, diagnostics.Get()));
    ReadBack back = Read(file);
    EXPECT_EQ(back.format, "tiff");
    ASSERT_EQ(back.spec.nchannels, 4);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(back.spec.alpha_channel, 3);
    EXPECT_EQ(back.spec.channelnames[0], "R");
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c)
                EXPECT_FLOAT_EQ(back.pixels[(y * image.width + x) * 4 + c],
                                std::lround(double(image.At(x, y)[c]) * 255) / 255.0f);
    EXPECT_EQ(dir.Entries().size(), 1u);  // no temporary file left behind
    EXPECT_EQ(diagnostics.Get().ErrorCount(), 0);
}

TEST(WriteDisplay, ExposureIsAppliedToColourOnly) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    Image image = TestImage();
    std::string file = dir.File("exposed.tif");
    Exposure exposure{2.0f, 2.0f};
    ASSERT_TRUE(WriteDisplay(Display(file, "tiff", "rgba"), image, kChannelNames, exposure, kFloat,
                             kFloat, diagnostics.Get()));
    ReadBack back = Read(file);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::FLOAT);
    const float* in = image.At(3, 2);
    const float* out = &back.pixels[(2 * image.width + 3) * 4];
    EXPECT_FLOAT_EQ(out[0], std::sqrt(2.0f * in[0]));
    EXPECT_FLOAT_EQ(out[2], std::sqrt(2.0f * in[2]));
    EXPECT_FLOAT_EQ(out[3], in[3]);  // alpha untouched
}

TEST(WriteDisplay, SixteenBitWhenOneExceedsAByte) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    std::string file = dir.File("deep.tif");
    ASSERT_TRUE(WriteDisplay(Display(file, "tiff", "rgb"), TestImage(), kChannelNames, Exposure{},
                             Quantization{65535, 0, 65535, 0.0f}, kFloat, diagnostics.Get()));
    ReadBack back = Read(file);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::UINT16);
    EXPECT_NEAR(back.pixels[(1 * 5 + 4) * 3 + 0], 0.4f, 1.0f / 65535);
}

TEST(WriteDisplay, ExrIsFloatWithInfiniteDepth) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    Image image = TestImage();
    std::string file = dir.File("out.exr");
    // Default colour quantization: an EXR file still holds float data.
    ASSERT_TRUE(WriteDisplay(Display(file, "openexr", "rgbaz"), image, kChannelNames, Exposure{},
                             Quantization{}, kFloat, diagnostics.Get()));
    ReadBack back = Read(file);
    EXPECT_EQ(back.format, "openexr");
    ASSERT_EQ(back.spec.nchannels, 5);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(back.spec.z_channel, 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 5; ++c)
                EXPECT_EQ(back.pixels[(y * image.width + x) * 5 + c], image.At(x, y)[c]);
    EXPECT_TRUE(std::isinf(back.pixels[4]));
}

TEST(WriteDisplay, ExrHalfOnRequest) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    DisplaySpec display = Display(dir.File("half.exr"), "exr", "rgb");
    TypedParam pixelType;
    pixelType.decl.name = "exrpixeltype";
    pixelType.decl.type = ParamType::String;
    pixelType.strings = {"half"};
    display.params.Set(pixelType, {});
    ASSERT_TRUE(WriteDisplay(display, TestImage(), kChannelNames, Exposure{}, kFloat, kFloat,
                             diagnostics.Get()));
    EXPECT_EQ(Read(display.name).spec.format, OIIO::TypeDesc::HALF);
    EXPECT_EQ(diagnostics.Get().WarningCount(), 0);
}

TEST(WriteDisplay, ZModeWritesOneFloatChannel) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    std::string file = dir.File("depth.tif");
    ASSERT_TRUE(WriteDisplay(Display(file, "file", "z"), TestImage(), kChannelNames, Exposure{},
                             Quantization{}, DefaultDepthQuantization(), diagnostics.Get()));
    ReadBack back = Read(file);
    ASSERT_EQ(back.spec.nchannels, 1);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::FLOAT);
    EXPECT_TRUE(std::isinf(back.pixels[0]));
    EXPECT_FLOAT_EQ(back.pixels[2 * 5 + 3], 2.5f * 3 + 2);
    // TIFF keeps no channel names; OpenEXR does.
    std::string exr = dir.File("depth.exr");
    ASSERT_TRUE(WriteDisplay(Display(exr, "openexr", "z"), TestImage(), kChannelNames, Exposure{},
                             Quantization{}, DefaultDepthQuantization(), diagnostics.Get()));
    EXPECT_EQ(Read(exr).spec.channelnames, std::vector<std::string>{"Z"});
}

// PRMan's and Pixie's depth-map displays write their format whatever the file is called, and
// the camera's matrices with it; OpenImageIO reads them back as "worldtocamera" and
// "worldtoscreen".
TEST(WriteDisplay, ZfileAndShadowDisplaysRecordTheCamera) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    const std::vector<float> toCamera = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 5, 1};
    const std::vector<float> toScreen = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 1, 1, 0, 4, 5};
    for (const auto& [type, name, format] :
         {std::tuple{"zfile", "depth.tif", "zfile"}, std::tuple{"shadow", "light.sm", "tiff"}}) {
        DisplaySpec display = Display(dir.File(name), type, "z");
        display.worldToCamera = toCamera, display.worldToScreen = toScreen;
        // Quantize "z" asks for 8 bits: a depth map keeps floats all the same.
        ASSERT_TRUE(WriteDisplay(display, TestImage(), kChannelNames, Exposure{}, Quantization{},
                                 Quantization{}, diagnostics.Get()));
        ReadBack back = Read(display.name);
        EXPECT_EQ(back.format, format);
        ASSERT_EQ(back.spec.nchannels, 1);
        EXPECT_FLOAT_EQ(back.pixels[2 * 5 + 3], 2.5f * 3 + 2);
        float matrix[16];
        ASSERT_TRUE(back.spec.getattribute("worldtocamera", OIIO::TypeMatrix, matrix)) << type;
        EXPECT_EQ(std::vector<float>(matrix, matrix + 16), toCamera) << type;
        ASSERT_TRUE(back.spec.getattribute("worldtoscreen", OIIO::TypeMatrix, matrix)) << type;
        EXPECT_EQ(std::vector<float>(matrix, matrix + 16), toScreen) << type;
    }
    EXPECT_EQ(Read(dir.File("light.sm")).spec.get_string_attribute("textureformat"), "Shadow");
    EXPECT_FALSE(WriteDisplay(Display(dir.File("x.sm"), "shadow", "rgb"), TestImage(),
                              kChannelNames, Exposure{}, Quantization{}, Quantization{},
                              diagnostics.Get()));
    EXPECT_NE(diagnostics.Text().find("its mode must be \"z\""), std::string::npos);
}

TEST(WriteDisplay, AovModeWritesItsComponentsAsFloat) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    std::string file = dir.File("normals.exr");
    ASSERT_TRUE(WriteDisplay(Display(file, "openexr", "N"), TestImage(), kChannelNames,
                             Exposure{4.0f, 1.0f}, Quantization{}, kFloat, diagnostics.Get()));
    ReadBack back = Read(file);
    ASSERT_EQ(back.spec.nchannels, 3);
    EXPECT_EQ(back.spec.channelnames[0], "N.x");
    EXPECT_EQ(back.pixels[0], -0.5f);  // neither exposed nor clamped
    EXPECT_EQ(back.pixels[2], 3.0f);
}

TEST(WriteDisplay, PngRgbAndFramebufferNote) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    Image image = TestImage();
    std::string file = dir.File("window.png");
    ASSERT_TRUE(WriteDisplay(Display(file, "framebuffer", "rgb"), image, kChannelNames, Exposure{},
                             kNoDither, kFloat, diagnostics.Get()));
    ReadBack back = Read(file);
    EXPECT_EQ(back.format, "png");
    ASSERT_EQ(back.spec.nchannels, 3);
    EXPECT_FLOAT_EQ(back.pixels[(2 * 5 + 4) * 3 + 1], std::lround(0.4f * 255) / 255.0f);
    EXPECT_NE(diagnostics.Text().find("note:"), std::string::npos) << diagnostics.Text();
}

TEST(WriteDisplay, PngCannotHoldFloatSoGetsSixteenBits) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    std::string file = dir.File("float.png");
    ASSERT_TRUE(WriteDisplay(Display(file, "png", "rgb"), TestImage(), kChannelNames, Exposure{},
                             kFloat, kFloat, diagnostics.Get()));
    EXPECT_EQ(Read(file).spec.format, OIIO::TypeDesc::UINT16);
    EXPECT_EQ(diagnostics.Get().WarningCount(), 1);
}

TEST(WriteDisplay, FileTypeFollowsTheExtension) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    std::string exr = dir.File("by_extension.exr"), plain = dir.File("no_extension");
    ASSERT_TRUE(WriteDisplay(Display(exr, "file", "rgba"), TestImage(), kChannelNames, Exposure{},
                             Quantization{}, kFloat, diagnostics.Get()));
    EXPECT_EQ(Read(exr).format, "openexr");
    ASSERT_TRUE(WriteDisplay(Display(plain, "file", "rgba"), TestImage(), kChannelNames, Exposure{},
                             Quantization{}, kFloat, diagnostics.Get()));
    EXPECT_EQ(Read(plain).format, "tiff");
    EXPECT_EQ(diagnostics.Get().WarningCount(), 0);
    std::string odd = dir.File("odd.png");
    ASSERT_TRUE(WriteDisplay(Display(odd, "it8", "rgb"), TestImage(), kChannelNames, Exposure{},
                             Quantization{}, kFloat, diagnostics.Get()));
    EXPECT_EQ(Read(odd).format, "png");
    EXPECT_EQ(diagnostics.Get().WarningCount(), 1);
    EXPECT_NE(diagnostics.Text().find("it8"), std::string::npos);
}

TEST(WriteDisplay, CropWindowKeepsItsPlaceInTheFrame) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    Image image = TestImage();
    image.xorigin = 10;
    image.yorigin = 20;
    image.fullWidth = 64;
    image.fullHeight = 48;
    for (const char* name : {"crop.tif", "crop.exr", "crop.png"}) {
        std::string file = dir.File(name);
        ASSERT_TRUE(WriteDisplay(Display(file, "file", "rgb"), image, kChannelNames, Exposure{},
                                 Quantization{}, kFloat, diagnostics.Get()));
        ReadBack back = Read(file);
        EXPECT_EQ(back.spec.width, 5) << name;
        EXPECT_EQ(back.spec.height, 3) << name;
        if (std::string(name) == "crop.png") continue;  // PNG has no data window
        EXPECT_EQ(back.spec.x, 10) << name;
        EXPECT_EQ(back.spec.y, 20) << name;
    }
    // OpenEXR also keeps the display window (the full frame).
    ReadBack exr = Read(dir.File("crop.exr"));
    EXPECT_EQ(exr.spec.full_width, 64);
    EXPECT_EQ(exr.spec.full_height, 48);
}

TEST(WriteDisplay, FailedWriteNamesTheFileAndLeavesNothing) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    std::string missing = dir.File("no/such/folder/out.tif");
    EXPECT_FALSE(WriteDisplay(Display(missing, "file", "rgb"), TestImage(), kChannelNames,
                              Exposure{}, Quantization{}, kFloat, diagnostics.Get()));
    EXPECT_EQ(diagnostics.Get().ErrorCount(), 1);
    std::string text = diagnostics.Text();
    EXPECT_NE(text.find("scene.rib:3: error: cannot write image \"" + missing + "\""),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("does not exist"), std::string::npos) << text;
    // The rename onto an existing folder fails after the data was written: the temporary goes.
    std::string folder = dir.File("taken");
    fs::create_directory(folder);
    EXPECT_FALSE(WriteDisplay(Display(folder, "tiff", "rgb"), TestImage(), kChannelNames,
                              Exposure{}, Quantization{}, kFloat, diagnostics.Get()));
    EXPECT_EQ(diagnostics.Get().ErrorCount(), 2);
    EXPECT_EQ(dir.Entries(), std::vector<std::string>{"taken"});
    EXPECT_TRUE(fs::is_empty(folder));
    EXPECT_EQ(diagnostics.Text().find(".tmp"), std::string::npos)  // only the name the user gave
        << diagnostics.Text();
}

TEST(WriteDisplay, ChannelNamesMustMatchTheImage) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    EXPECT_FALSE(WriteDisplay(Display(dir.File("x.tif"), "file", "rgb"), TestImage(),
                              {"r", "g", "b"}, Exposure{}, Quantization{}, kFloat,
                              diagnostics.Get()));
    EXPECT_EQ(diagnostics.Get().ErrorCount(), 1);
    EXPECT_TRUE(dir.Entries().empty());
}

TEST(WriteDisplay, MissingChannelIsAnError) {
    TempDir dir;
    CapturedDiagnostics diagnostics;
    std::string file = dir.File("z.tif");
    EXPECT_FALSE(WriteDisplay(Display(file, "file", "rgbz"), TestImage(),
                              {"r", "g", "b", "a", "depth", "N.x", "N.y", "N.z"}, Exposure{},
                              Quantization{}, kFloat, diagnostics.Get()));
    EXPECT_EQ(diagnostics.Get().ErrorCount(), 1);
    EXPECT_FALSE(fs::exists(file));
}

}  // namespace
}  // namespace gonio
