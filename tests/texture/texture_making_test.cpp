// MakeTexture, MakeLatLongEnvironment and MakeCubeFaceEnvironment end to end: pictures written
// by the built-in TIFF driver, made into textures by RIB requests, looked up by a shader in a
// render, every answer derived from the picture (RISpec §7.1, §15.7).
//
// The probe scene renders one pixel per lookup: pixel i is covered by its own polygon whose
// shader looks up at a uniform (s, t) or direction, so the footprint is zero and OpenImageIO
// reads the top MIP level with its B-spline bicubic (weights summing to 1 over 4 × 4 pixels):
// inside a constant block of 4 × 4 pixels that is the block's value, midway between two blocks
// their mean.

#include <gtest/gtest.h>
#include <tiffio.h>

#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>

#include "imageio/environment_layout.h"
#include "imageio/image_formats.h"
#include "imageio/oiio_plugin.h"
#include "tests/support/render_rib.h"
#include "tests/support/test_folder.h"

namespace gonio {
namespace {

using Rgb = std::array<float, 3>;

const char* const kProbeShader = R"(
surface probe(string map = ""; float ss = 0, tt = 0; string wrap = "default";
              float env = 0, dx = 0, dy = 0, dz = 0) {
    if (env > 0)
        Ci = color environment(map, vector(dx, dy, dz));
    else
        Ci = color texture(map, ss, tt, "swrap", wrap, "twrap", wrap);
    Oi = 1;
}
)";

// A scratch folder per test case, holding the probe shader.
class Scratch : public test::TestFolder {
  public:
    Scratch() : TestFolder("gonio_texture_test_") {
        std::ofstream(File("probe.sl")) << kProbeShader;
    }
};

// A float RGB picture written by the built-in TIFF driver.
void WritePicture(const std::string& path, int width, int height,
                  const std::function<Rgb(int x, int y)>& texel) {
    ImageFileSpec spec;
    spec.width = width, spec.height = height;
    spec.channelNames = {"R", "G", "B"};
    spec.fileType = PixelType::Float;
    std::vector<float> pixels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (float v : texel(x, y)) pixels.push_back(v);
    ASSERT_EQ(WriteImageFile("tiff", path, spec, PixelBuffer{PixelType::Float, pixels.data()}), "");
}

struct Render {
    test::RibRenderResult result;
    std::vector<Rgb> pixels;  // one per probe
};

// Renders the RIB `before` (the texture-making requests) and one probe pixel per entry of
// `probes` (the parameters of its Surface "probe").
Render RenderProbes(const Scratch& scratch, const std::string& before,
                    const std::vector<std::string>& probes) {
    const int n = int(probes.size());
    std::ostringstream rib;
    rib << "Option \"searchpath\" \"shader\" \"" << scratch.File("") << ":@\"\n"
        << before << "FrameBegin 1\nFormat " << n << " 1 1\nPixelSamples 1 1\n"
        << "PixelFilter \"box\" 1 1\nShadingRate 1\n"
        << "Display \"" << scratch.File("probes.exr") << "\" \"openexr\" \"rgba\"\n"
        << "Projection \"orthographic\"\nScreenWindow 0 " << n << " -0.5 0.5\n"
        << "Translate 0 0 5\nWorldBegin\n";
    for (int i = 0; i < n; ++i)
        rib << "Surface \"probe\" " << probes[i] << "\nPolygon \"P\" [" << i << " -1 0  " << i + 1
            << " -1 0  " << i + 1 << " 1 0  " << i << " 1 0]\n";
    rib << "WorldEnd\nFrameEnd\n";
    Render render;
    render.result = test::RenderRibString(rib.str(), scratch.File("probes.rib"));
    std::string error;
    const ImageFileContents image =
        LoadOiioPlugin("the test").ReadImage(scratch.File("probes.exr"), &error);
    if (!error.empty() || image.spec.width != n) return render;
    const int channels = image.spec.Channels();
    for (int i = 0; i < n; ++i) {
        const float* p = &image.pixels[size_t(i) * channels];
        render.pixels.push_back({p[0], p[1], p[2]});
    }
    return render;
}

std::string TextureProbe(const std::string& map, float s, float t, const char* wrap = "default") {
    std::ostringstream probe;
    probe << "\"string map\" \"" << map << "\" \"float ss\" " << s << " \"float tt\" " << t
          << " \"string wrap\" \"" << wrap << "\"";
    return probe.str();
}

std::string EnvironmentProbe(const std::string& map, float x, float y, float z) {
    std::ostringstream probe;
    probe << "\"string map\" \"" << map << "\" \"float env\" 1 \"float dx\" " << x
          << " \"float dy\" " << y << " \"float dz\" " << z;
    return probe.str();
}

void ExpectRgb(const Rgb& got, const Rgb& want, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f) << what << ", channel " << c;
}

// ---- MakeTexture and the wrap modes ---------------------------------------------------------

// 4 x 2 texels: red grows with the column, green with the row, so every texel differs. Each is
// a block of 4 x 4 pixels of the picture, wider than the bicubic lookup's reach.
constexpr int kW = 4, kH = 2, kBlock = 4;
Rgb Texel(int x, int y) { return {0.1f * (x + 1), 0.2f * (y + 1), 0.5f}; }
void WriteGrid(const std::string& path) {
    WritePicture(path, kW * kBlock, kH * kBlock,
                 [](int x, int y) { return Texel(x / kBlock, y / kBlock); });
}
// Texel centres: s = (x + 1/2) / 4, t = (y + 1/2) / 2.
float S(int x) { return (x + 0.5f) / kW; }
float T(int y) { return (y + 0.5f) / kH; }
Rgb Mean(const Rgb& a, const Rgb& b) {
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

TEST(MakeTexture, WrapModesOutsideTheUnitSquare) {
    Scratch scratch;
    WriteGrid(scratch.File("grid.tif"));
    const std::string grid = scratch.File("grid.tif");
    const std::string periodic = scratch.File("periodic.tx"), clamp = scratch.File("clamp.tx"),
                      black = scratch.File("black.tx");
    // One request outside any frame, one inside a frame that renders nothing, one after it:
    // each is made at its place in the RIB.
    const std::string before =
        "MakeTexture \"" + grid + "\" \"" + periodic + "\" \"periodic\" \"clamp\" \"box\" 1 1\n" +
        "FrameBegin 0\nMakeTexture \"" + grid + "\" \"" + clamp +
        "\" \"clamp\" \"clamp\" \"gaussian\" 2 2\nFrameEnd\n" + "MakeTexture \"" + grid + "\" \"" +
        black + "\" \"black\" \"black\" \"triangle\" 2 2\n";
    const Render r =
        RenderProbes(scratch, before,
                     {TextureProbe(periodic, S(1), T(0)), TextureProbe(periodic, S(1) + 1, T(0)),
                      TextureProbe(periodic, S(2) - 2, T(1)), TextureProbe(periodic, 0.25f, T(0)),
                      TextureProbe(periodic, 1.25f, T(0)), TextureProbe(periodic, S(0), 1.5f),
                      TextureProbe(clamp, 1.5f, T(1)), TextureProbe(clamp, -0.5f, T(0)),
                      TextureProbe(clamp, S(2), -3.0f), TextureProbe(black, 1.5f, T(0)),
                      TextureProbe(black, S(1), -0.5f), TextureProbe(black, S(3), T(1))});
    ASSERT_EQ(r.result.errors, 0) << r.result.messages;
    ASSERT_EQ(r.pixels.size(), 12u) << r.result.messages;
    ExpectRgb(r.pixels[0], Texel(1, 0), "periodic at a texel centre");
    ExpectRgb(r.pixels[1], Texel(1, 0), "periodic: s + 1 reads s");
    ExpectRgb(r.pixels[2], Texel(2, 1), "periodic: s - 2 reads s");
    ExpectRgb(r.pixels[3], Mean(Texel(0, 0), Texel(1, 0)), "periodic at s = 0.25");
    ExpectRgb(r.pixels[4], r.pixels[3], "periodic: s = 1.25 reads s = 0.25");
    ExpectRgb(r.pixels[5], Texel(0, 1), "twrap clamp: t = 1.5 reads the last row");
    ExpectRgb(r.pixels[6], Texel(3, 1), "clamp: s = 1.5 reads the right edge");
    ExpectRgb(r.pixels[7], Texel(0, 0), "clamp: s = -0.5 reads the left edge");
    ExpectRgb(r.pixels[8], Texel(2, 0), "clamp: t = -3 reads the first row");
    ExpectRgb(r.pixels[9], {0, 0, 0}, "black: s = 1.5");
    ExpectRgb(r.pixels[10], {0, 0, 0}, "black: t = -0.5");
    ExpectRgb(r.pixels[11], Texel(3, 1), "black inside the square");
}

// texture()'s "swrap"/"twrap" parameters override the file's modes.
TEST(MakeTexture, LookupWrapParametersOverrideTheFile) {
    Scratch scratch;
    WriteGrid(scratch.File("grid.tif"));
    const std::string black = scratch.File("black.tx");
    const Render r = RenderProbes(
        scratch,
        "MakeTexture \"" + scratch.File("grid.tif") + "\" \"" + black +
            "\" \"black\" \"black\" \"box\" 1 1\n",
        {TextureProbe(black, S(1) + 1, T(0), "periodic"), TextureProbe(black, 1.5f, T(1), "clamp"),
         TextureProbe(black, 1.5f, T(1), "default")});
    ASSERT_EQ(r.result.errors, 0) << r.result.messages;
    ASSERT_EQ(r.pixels.size(), 3u) << r.result.messages;
    ExpectRgb(r.pixels[0], Texel(1, 0), "\"wrap\" \"periodic\" on a black file");
    ExpectRgb(r.pixels[1], Texel(3, 1), "\"wrap\" \"clamp\" on a black file");
    ExpectRgb(r.pixels[2], {0, 0, 0}, "\"wrap\" \"default\": the file's black");
}

// ---- environments ---------------------------------------------------------------------------

// One colour per octant of directions: bit 0 x < 0, bit 1 y < 0, bit 2 z < 0.
Rgb OctantColour(int octant) {
    return {0.1f + 0.1f * octant, octant & 1 ? 0.9f : 0.3f, octant & 4 ? 0.2f : 0.7f};
}
int OctantOf(double x, double y, double z) { return (x < 0) | (y < 0) << 1 | (z < 0) << 2; }

TEST(MakeLatLongEnvironment, EachOctantOfDirectionsReadsItsColour) {
    Scratch scratch;
    // RenderMan's lat-long layout, as documented: s = 1/2 + atan2(y, x)/2π, t = acos(z)/π;
    // each texel gets the colour of the octant of the direction at its centre (octants are
    // 16 x 16 texels, and the probes look at their middles, far from the resampling's blur).
    const int w = 64, h = 32;
    constexpr double kPi = 3.14159265358979323846;
    WritePicture(scratch.File("sky.tif"), w, h, [&](int x, int y) {
        const double phi = 2 * kPi * ((x + 0.5) / w - 0.5), theta = kPi * (y + 0.5) / h;
        return OctantColour(OctantOf(std::cos(phi), std::sin(phi), std::cos(theta)));
    });
    const std::string sky = scratch.File("sky.env");
    std::vector<std::string> probes;
    for (int octant = 0; octant < 8; ++octant)
        probes.push_back(
            EnvironmentProbe(sky, octant & 1 ? -1 : 1, octant & 2 ? -1 : 1, octant & 4 ? -1 : 1));
    const Render r = RenderProbes(
        scratch,
        "MakeLatLongEnvironment \"" + scratch.File("sky.tif") + "\" \"" + sky + "\" \"box\" 1 1\n",
        probes);
    ASSERT_EQ(r.result.errors, 0) << r.result.messages;
    ASSERT_EQ(r.pixels.size(), 8u) << r.result.messages;
    for (int octant = 0; octant < 8; ++octant)
        ExpectRgb(r.pixels[octant], OctantColour(octant), "octant " + std::to_string(octant));
}

Rgb FaceColour(int face) { return {0.1f * (face + 1), 1.0f - 0.1f * face, face % 2 ? 0.8f : 0.4f}; }

TEST(MakeCubeFaceEnvironment, EachAxisReadsItsFace) {
    Scratch scratch;
    const char* const names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    std::string faces;
    for (int f = 0; f < 6; ++f) {
        const std::string path = scratch.File(std::string(names[f]) + ".tif");
        WritePicture(path, 8, 8, [&](int, int) { return FaceColour(f); });
        faces += "\"" + path + "\" ";
    }
    const std::string cube = scratch.File("cube.env");
    const Render r = RenderProbes(
        scratch, "MakeCubeFaceEnvironment " + faces + "\"" + cube + "\" 95 \"box\" 1 1\n",
        {EnvironmentProbe(cube, 1, 0, 0), EnvironmentProbe(cube, -1, 0, 0),
         EnvironmentProbe(cube, 0, 1, 0), EnvironmentProbe(cube, 0, -1, 0),
         EnvironmentProbe(cube, 0, 0, 1), EnvironmentProbe(cube, 0, 0, -1)});
    ASSERT_EQ(r.result.errors, 0) << r.result.messages;
    ASSERT_EQ(r.pixels.size(), 6u) << r.result.messages;
    for (int f = 0; f < 6; ++f) ExpectRgb(r.pixels[f], FaceColour(f), names[f]);
}

// RISpec's faces are views from the origin along each axis, up +y for the x and z faces, -z for
// py and +z for ny, in RenderMan's left-handed space (right = up × forward).
TEST(MakeCubeFaceEnvironment, FaceOrientationFollowsRISpec) {
    struct Case {
        float dx, dy, dz;
        int face;
        float x, y;
    };
    const Case cases[] = {
        {1, 0, 0, 0, 0.5f, 0.5f},       {1, 0.5f, 0, 0, 0.5f, 0.25f},   // px: up +y
        {1, 0, -0.5f, 0, 0.75f, 0.5f},                                  // px: right -z
        {-1, 0, 0.5f, 1, 0.75f, 0.5f},  {-1, 0.5f, 0, 1, 0.5f, 0.25f},  // nx: right +z, up +y
        {0.5f, 1, 0, 2, 0.75f, 0.5f},   {0, 1, -0.5f, 2, 0.5f, 0.25f},  // py: right +x, up -z
        {0.5f, -1, 0, 3, 0.75f, 0.5f},  {0, -1, 0.5f, 3, 0.5f, 0.25f},  // ny: right +x, up +z
        {0.5f, 0, 1, 4, 0.75f, 0.5f},   {0, 0.5f, 1, 4, 0.5f, 0.25f},   // pz: right +x, up +y
        {-0.5f, 0, -1, 5, 0.75f, 0.5f}, {0, 0.5f, -1, 5, 0.5f, 0.25f},  // nz: right -x, up +y
    };
    for (const Case& c : cases) {
        const CubeFacePoint p = CubeFacePointOf(c.dx, c.dy, c.dz, 90);
        EXPECT_EQ(p.face, c.face) << c.dx << " " << c.dy << " " << c.dz;
        EXPECT_NEAR(p.x, c.x, 1e-6f) << c.dx << " " << c.dy << " " << c.dz;
        EXPECT_NEAR(p.y, c.y, 1e-6f) << c.dx << " " << c.dy << " " << c.dz;
    }
    // A wider field of view puts the face's edge (45 degrees off its axis) inside the picture:
    // tan 45° / tan 47.5°.
    const CubeFacePoint wide = CubeFacePointOf(1, 0, -1, 95);
    EXPECT_NEAR(wide.x, 0.5f + 0.5f / std::tan(47.5f * 3.14159265f / 180), 1e-5f);
}

// ---- the MIP levels' filter ------------------------------------------------------------------

// Level `level` (0 the picture's size) of a one-channel float texture file, read with libtiff
// (make_texture writes each level as a TIFF directory of 64 x 64 tiles); empty on failure.
struct Level {
    int width = 0, height = 0;
    std::vector<float> pixels;
    float At(int x, int y) const { return pixels[size_t(y) * width + x]; }
};
Level ReadLevel(const std::string& path, int level) {
    Level out;
    std::unique_ptr<TIFF, void (*)(TIFF*)> tif(TIFFOpen(path.c_str(), "r"), TIFFClose);
    uint32_t width = 0, height = 0, tileWidth = 0, tileHeight = 0;
    if (!tif || !TIFFSetDirectory(tif.get(), uint16_t(level)) ||
        !TIFFGetField(tif.get(), TIFFTAG_IMAGEWIDTH, &width) ||
        !TIFFGetField(tif.get(), TIFFTAG_IMAGELENGTH, &height) ||
        !TIFFGetField(tif.get(), TIFFTAG_TILEWIDTH, &tileWidth) ||
        !TIFFGetField(tif.get(), TIFFTAG_TILELENGTH, &tileHeight) ||
        TIFFTileSize(tif.get()) != tmsize_t(tileWidth * tileHeight * sizeof(float)))
        return out;
    out.width = int(width), out.height = int(height);
    out.pixels.assign(size_t(width) * height, 0.f);
    std::vector<float> tile(size_t(tileWidth) * tileHeight);
    for (uint32_t y0 = 0; y0 < height; y0 += tileHeight)
        for (uint32_t x0 = 0; x0 < width; x0 += tileWidth) {
            if (TIFFReadTile(tif.get(), tile.data(), x0, y0, 0, 0) < 0) return {};
            for (uint32_t y = y0; y < std::min(height, y0 + tileHeight); ++y)
                for (uint32_t x = x0; x < std::min(width, x0 + tileWidth); ++x)
                    out.pixels[size_t(y) * width + x] = tile[size_t(y - y0) * tileWidth + x - x0];
        }
    return out;
}

// The pixels of a level that are not 0, as (x, y) -> value.
std::map<std::pair<int, int>, float> Lit(const Level& level) {
    std::map<std::pair<int, int>, float> lit;
    for (int y = 0; y < level.height; ++y)
        for (int x = 0; x < level.width; ++x)
            if (level.At(x, y) != 0) lit[{x, y}] = level.At(x, y);
    return lit;
}

// A 64 x 64 black picture with one white pixel at (21, 37). Level 1 is 32 x 32; in its pixel
// units the picture's pixel centres sit at (i + 1/2) / 2, the white one at (10.75, 18.75). A
// box filter of width w gathers, for a level pixel centred at j + 1/2, the picture's pixels
// whose centres lie within w / 2 of it, each with the same weight: 2w of them in a line for an
// even w. So a box 3 x 1 lights the level pixels x = 9, 10, 11 of row 18 with 1/(6 · 2) each,
// and a box 1 x 1 (the 2 x 2 mean) lights (10, 18) with 1/4, then (5, 9) of level 2 with 1/16.
TEST(MakeTexture, MipLevelsAreFilteredAtTheRequestedWidths) {
    Scratch scratch;
    ImageFileSpec spec;
    spec.width = spec.height = 64;
    spec.channelNames = {"Y"};
    spec.fileType = PixelType::Float;
    std::vector<float> pixels(64 * 64, 0.f);
    pixels[37 * 64 + 21] = 1;
    ASSERT_EQ(WriteImageFile("tiff", scratch.File("dot.tif"), spec,
                             PixelBuffer{PixelType::Float, pixels.data()}),
              "");
    const std::string wide = scratch.File("wide.tx"), narrow = scratch.File("narrow.tx");
    const std::string rib = "MakeTexture \"" + scratch.File("dot.tif") + "\" \"" + wide +
                            "\" \"clamp\" \"clamp\" \"box\" 3 1\n" + "MakeTexture \"" +
                            scratch.File("dot.tif") + "\" \"" + narrow +
                            "\" \"clamp\" \"clamp\" \"box\" 1 1\n";
    const test::RibRenderResult r = test::RenderRibString(rib, "make.rib");
    ASSERT_EQ(r.errors, 0) << r.messages;

    const Level top = ReadLevel(wide, 0);
    ASSERT_EQ(top.width, 64);
    EXPECT_EQ(top.At(21, 37), 1.f) << "level 0 is the picture";
    const Level wide1 = ReadLevel(wide, 1);
    ASSERT_EQ(wide1.width, 32);
    ASSERT_EQ(wide1.height, 32);
    const auto wideLit = Lit(wide1);
    ASSERT_EQ(wideLit.size(), 3u);
    for (int x : {9, 10, 11}) EXPECT_NEAR(wideLit.at({x, 18}), 1.f / 12, 1e-6f) << "x = " << x;

    const auto narrowLit = Lit(ReadLevel(narrow, 1));
    ASSERT_EQ(narrowLit.size(), 1u);
    EXPECT_NEAR(narrowLit.at({10, 18}), 1.f / 4, 1e-6f);
    const Level narrow2 = ReadLevel(narrow, 2);
    ASSERT_EQ(narrow2.width, 16);
    const auto narrow2Lit = Lit(narrow2);
    ASSERT_EQ(narrow2Lit.size(), 1u);
    EXPECT_NEAR(narrow2Lit.at({5, 9}), 1.f / 16, 1e-6f);
    // The levels' scratch files are gone.
    EXPECT_EQ(scratch.Entries().size(), 4u) << "expected probe.sl, dot.tif and the two textures";
}

// ---- errors ---------------------------------------------------------------------------------

TEST(MakeTexture, BadRequestsAreLocatedErrorsAndMakeNoFile) {
    Scratch scratch;
    std::ofstream(scratch.File("notapicture.tif")) << "this is text, not a TIFF\n";
    WriteGrid(scratch.File("grid.tif"));
    const auto request = [&](const std::string& picture, const std::string& texture,
                             const std::string& rest) {
        return "MakeTexture \"" + picture + "\" \"" + texture + "\" " + rest;
    };
    const std::string bad = scratch.File("notapicture.tif"), grid = scratch.File("grid.tif");
    // Each request, on its own line, and the error it gives there.
    const std::vector<std::pair<std::string, std::string>> cases = {
        {request("missing.tif", scratch.File("a.tx"), "\"periodic\" \"periodic\" \"box\" 1 1"),
         "MakeTexture: cannot find the picture \"missing.tif\""},
        {request(bad, scratch.File("b.tx"), "\"periodic\" \"periodic\" \"box\" 1 1"),
         "MakeTexture \"" + scratch.File("b.tx") + "\": cannot read the picture \"" + bad + "\""},
        {request("x.tif", "c.tx", "\"wrap\" \"periodic\" \"box\" 1 1"),
         "MakeTexture: swrap must be \"periodic\", \"clamp\" or \"black\", got \"wrap\""},
        {request(grid, scratch.File("d.tx"), "\"clamp\" \"clamp\" \"box\" 0 1"),
         "MakeTexture: the filter widths must be in (0, 256] pixels, got 0 1"},
        {request(grid, scratch.File("e.tx"), "\"clamp\" \"clamp\" \"gaussian\" 2 1e9"),
         "MakeTexture: the filter widths must be in (0, 256] pixels, got 2 1e+09"}};
    std::string rib;
    for (const auto& entry : cases) rib += entry.first + "\n";
    const test::RibRenderResult r = test::RenderRibString(rib, "make.rib");
    EXPECT_EQ(r.errors, int(cases.size())) << r.messages;
    for (size_t i = 0; i < cases.size(); ++i)
        EXPECT_NE(
            r.messages.find("make.rib:" + std::to_string(i + 1) + ":1: error: " + cases[i].second),
            std::string::npos)
            << r.messages;
    // Nothing made, no temporary left behind.
    EXPECT_EQ(scratch.Entries().size(), 3u) << "expected only probe.sl and the two pictures";
}

}  // namespace
}  // namespace gonio
