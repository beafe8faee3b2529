// ApplyImager (renderer/shading/imager_shading.h) on hand-made images, with the Imager request
// parsed from RIB: the globals an imager sees (Ci, Oi, alpha, P, Du/Dv), what it writes back,
// ColorSamples, the error messages of unusable requests, and independence from threads.

#include "renderer/shading/imager_shading.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

// A folder holding the test's shaders and (by name) its scene, removed at the end.
class ShaderFolder {
  public:
    ShaderFolder() {
        path_ = fs::temp_directory_path() /
                ("gonio_imager_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
        fs::create_directories(path_);
    }
    ~ShaderFolder() { fs::remove_all(path_); }
    void Write(const std::string& name, const std::string& text) const {
        std::ofstream(path_ / name) << text;
    }
    std::string Scene() const { return (path_ / "scene.rib").string(); }

  private:
    static inline int counter_ = 0;
    fs::path path_;
};

// The frame of `options` (requests before WorldBegin), built through the RIB parser as if read
// from `sceneFile`; the diagnostics so far go to `diagnostics`.
Frame BuildFrame(const std::string& options, const std::string& sceneFile,
                 Diagnostics& diagnostics) {
    std::vector<Frame> frames;
    SceneBuilder builder(sceneFile, diagnostics,
                         [&](const Frame& frame) { frames.push_back(frame); });
    ParseRibString(options + "WorldBegin\nWorldEnd\n", sceneFile, builder, diagnostics);
    builder.Finish(FileLoc{});
    EXPECT_EQ(frames.size(), 1u);
    return frames.empty() ? Frame{} : frames[0];
}

// A 19x11 crop of a larger frame at (3, 5): pixel (x, y) has colour (x, y, x + y)/40 scaled by
// its alpha (premultiplied), alpha x/18, depth 7 and one AOV channel 9.
Image TestImage() {
    Image image;
    image.width = 19, image.height = 11, image.channels = 6;
    image.xorigin = 3, image.yorigin = 5;
    image.fullWidth = 40, image.fullHeight = 30;
    image.pixels.resize(size_t(image.width) * image.height * image.channels);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            float* p = image.At(x, y);
            const float a = x / 18.f;
            p[0] = a * x / 40.f, p[1] = a * y / 40.f, p[2] = a * (x + y) / 40.f;
            p[3] = a, p[4] = 7, p[5] = 9;
        }
    }
    return image;
}

// Everything Diagnostics printed while `run` ran.
template <typename F>
std::string Messages(F run) {
    test::CapturedDiagnostics diagnostics;
    run(diagnostics.Get());
    return diagnostics.Text();
}

TEST(ImagerShading, BackgroundCompositesUnderThePixels) {
    ShaderFolder folder;
    Image image = TestImage();
    const Image before = image;
    const std::string messages = Messages([&](Diagnostics& d) {
        const Frame frame =
            BuildFrame("Imager \"background\" \"background\" [0.2 0.4 0.6]\n", folder.Scene(), d);
        EXPECT_TRUE(ApplyImager(frame, 0, image, d));
    });
    EXPECT_EQ(messages, "");
    const float background[3] = {0.2f, 0.4f, 0.6f};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float* was = before.At(x, y);
            const float* is = image.At(x, y);
            for (int c = 0; c < 3; ++c)  // background.sl: Ci += (1 - alpha) * background
                EXPECT_NEAR(is[c], was[c] + (1 - was[3]) * background[c], 1e-6f) << x << "," << y;
            EXPECT_EQ(is[3], 1.f) << "alpha = 1";
            EXPECT_EQ(is[4], 7.f) << "depth untouched";
            EXPECT_EQ(is[5], 9.f) << "AOV untouched";
        }
    }
}

TEST(ImagerShading, NullOrNoImagerLeavesTheImage) {
    for (const char* request : {"", "Imager \"null\"\n", "Imager \"\"\n"}) {
        Image image = TestImage();
        const std::string messages = Messages([&](Diagnostics& d) {
            const Frame frame = BuildFrame(request, "scene.rib", d);
            EXPECT_FALSE(ApplyImager(frame, 0, image, d));
        });
        EXPECT_EQ(messages, "") << request;
        EXPECT_EQ(image.pixels, TestImage().pixels) << request;
    }
}

TEST(ImagerShading, SeesRasterPositionOpacityAndPixelDerivatives) {
    ShaderFolder folder;
    folder.Write(
        "probe.sl",
        "imager probe() {\n"
        "    float x = xcomp(P), y = ycomp(P);\n"
        "    float ok = (comp(Oi, 0) == alpha && comp(Oi, 2) == alpha && zcomp(P) == 0 &&\n"
        "                Du(x) == 1 && Dv(y) == 1 && Du(y) == 0 && Dv(x) == 0) ? 1 : 0;\n"
        "    Ci = color(x, y, ok + ncomps);\n"
        "    alpha = 0.25;\n"
        "}\n");
    Image image = TestImage();
    const std::string messages = Messages([&](Diagnostics& d) {
        EXPECT_TRUE(ApplyImager(BuildFrame("Imager \"probe\"\n", folder.Scene(), d), 0, image, d));
    });
    EXPECT_EQ(messages, "");
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.At(x, y);
            EXPECT_EQ(p[0], x + 3 + 0.5f) << "P.x: the pixel centre in full-frame raster space";
            EXPECT_EQ(p[1], y + 5 + 0.5f) << "P.y";
            EXPECT_EQ(p[2], 4.f) << "Oi = alpha, P.z = 0, unit pixel steps, ncomps 3 at " << x
                                 << "," << y;
            EXPECT_EQ(p[3], 0.25f) << "alpha written back";
        }
    }
}

// s, t: the pixel centre across the whole frame (Format 40 30), as Pixie's imagers read them.
TEST(ImagerShading, SeesTheFramePositionAsST) {
    ShaderFolder folder;
    folder.Write("st.sl", "imager st() { Ci = color(s, t, 0); }\n");
    Image image = TestImage();
    const std::string messages = Messages([&](Diagnostics& d) {
        EXPECT_TRUE(ApplyImager(BuildFrame("Format 40 30 1\nImager \"st\"\n", folder.Scene(), d), 0,
                                image, d));
    });
    EXPECT_EQ(messages, "");
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            EXPECT_FLOAT_EQ(image.At(x, y)[0], (x + 3 + 0.5f) / 40) << "s at " << x << "," << y;
            EXPECT_FLOAT_EQ(image.At(x, y)[1], (y + 5 + 0.5f) / 30) << "t at " << x << "," << y;
        }
    }
}

TEST(ImagerShading, ColorSamplesConvertOnlyWhatTheImagerChanged) {
    // One component: nRGB maps it to grey, RGBn averages RGB. A pixel of RGB (r, g, b) and
    // alpha a reaches the shader as (r + g + b)/3; background adds (1 - a)·0.5, and that change
    // comes back through nRGB on every channel.
    ShaderFolder folder;
    Image image = TestImage();
    const Image before = image;
    const std::string messages = Messages([&](Diagnostics& d) {
        const Frame frame = BuildFrame(
            "ColorSamples [1 1 1] [0.333333 0.333333 0.333333]\n"
            "Imager \"background\" \"background\" [0.5]\n",
            folder.Scene(), d);
        EXPECT_TRUE(ApplyImager(frame, 0, image, d));
    });
    EXPECT_EQ(messages, "");
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float* was = before.At(x, y);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.At(x, y)[c], was[c] + (1 - was[3]) * 0.5f, 1e-6f);
        }
    }
    EXPECT_EQ(image.At(18, 0)[0], before.At(18, 0)[0]) << "an opaque pixel is left exactly as is";
}

TEST(ImagerShading, UnusableRequestsAreReportedAtTheirRibLine) {
    ShaderFolder folder;
    folder.Write("flat.sl", "surface flat() { Ci = 1; }\n");
    folder.Write("typed.sl", "imager typed(color tint = 1) { Ci = tint; }\n");
    const std::string scene = folder.Scene();
    struct Case {
        const char* rib;
        std::string message;
        bool runs;
    };
    const Case cases[] = {
        {"Format 40 30 1\nImager \"nosuch\"\n", scene + ":2:1: error: cannot find shader 'nosuch'",
         false},
        {"Format 40 30 1\n\nImager \"flat\"\n",
         scene + ":3:1: error: \"flat\" is a surface shader, not an imager shader", false},
        // A parameter of the wrong type is reported and keeps its default, as for any shader.
        {"Imager \"typed\" \"string tint\" \"red\"\n",
         scene + ":1:16: error: parameter 'tint' is declared string in the RIB but color in shader "
                 "'typed'",
         true},
    };
    for (const Case& c : cases) {
        Image image = TestImage();
        bool ran = false;
        const std::string messages = Messages(
            [&](Diagnostics& d) { ran = ApplyImager(BuildFrame(c.rib, scene, d), 0, image, d); });
        EXPECT_EQ(messages.rfind(c.message, 0), 0u) << messages;
        EXPECT_EQ(ran, c.runs) << c.rib;
        if (!ran) {
            EXPECT_EQ(image.pixels, TestImage().pixels) << "unchanged after an error";
        }
    }
}

TEST(ImagerShading, ImagerInsideTheWorldIsAnError) {
    const std::string messages = Messages([&](Diagnostics& d) {
        std::vector<Frame> frames;
        SceneBuilder builder("scene.rib", d, [&](const Frame& f) { frames.push_back(f); });
        ParseRibString("WorldBegin\nImager \"background\"\nWorldEnd\n", "scene.rib", builder, d);
        ASSERT_EQ(frames.size(), 1u);
        EXPECT_FALSE(frames[0].options.imager.IsSet());
    });
    EXPECT_EQ(messages,
              "scene.rib:2:1: error: Imager is an option and is not valid inside "
              "WorldBegin/WorldEnd\n");
}

TEST(ImagerShading, RandomDoesNotDependOnThreads) {
    ShaderFolder folder;
    folder.Write("noisy.sl", "imager noisy() { Ci = color random(); }\n");
    auto run = [&](int threads, uint64_t seed) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        Image image = TestImage();
        Messages([&](Diagnostics& d) {
            EXPECT_TRUE(
                ApplyImager(BuildFrame("Imager \"noisy\"\n", folder.Scene(), d), seed, image, d));
        });
        return image.pixels;
    };
    const std::vector<float> one = run(1, 0);
    EXPECT_EQ(one, run(2, 0));
    EXPECT_NE(one, run(2, 7)) << "the render's seed changes random()";
}

}  // namespace
}  // namespace gonio
