// RibWriter prints calls back as RIB that parses to the same calls: parse(print(parse(x))) ==
// parse(x), for every request kind and for awkward values.

#include "renderer/rib/rib_writer.h"

#include <gtest/gtest.h>

#include <sstream>

#include "rib_test_util.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

std::string Print(const std::string& rib) {
    std::ostringstream out;
    RibWriter writer(out);
    Diagnostics diagnostics(nullptr);
    EXPECT_TRUE(ParseRibString(rib, "in.rib", writer, diagnostics)) << rib;
    return out.str();
}

void ExpectRoundTrip(const std::string& rib) {
    const ParseResult first = ParseText(rib);
    ASSERT_TRUE(first.ok) << first.messages;
    const std::string printed = Print(rib);
    const ParseResult second = ParseText(printed);
    EXPECT_TRUE(second.ok) << second.messages << printed;
    EXPECT_EQ(second.target.Text(), first.target.Text()) << printed;
}

TEST(RibWriter, PrintsIndentedBlocks) {
    EXPECT_EQ(Print("FrameBegin 1 WorldBegin AttributeBegin Sphere 1 -1 1 360 "
                    "AttributeEnd WorldEnd FrameEnd"),
              "FrameBegin 1\n"
              "    WorldBegin\n"
              "        AttributeBegin\n"
              "            Sphere 1 -1 1 360\n"
              "        AttributeEnd\n"
              "    WorldEnd\n"
              "FrameEnd\n");
}

TEST(RibWriter, PrintsParametersBracketed) {
    EXPECT_EQ(Print("Surface \"plastic\" \"Kd\" 0.5 \"string texturename\" \"a\\\"b\""),
              "Surface \"plastic\" \"Kd\" [ 0.5 ] \"string texturename\" [ \"a\\\"b\" ]\n");
}

TEST(RibWriter, PinholeDepthOfFieldHasNoArguments) {
    EXPECT_EQ(Print("DepthOfField"), "DepthOfField\n");
}

TEST(RibWriter, RoundTripsAwkwardValues) {
    ExpectRoundTrip("Translate 0.1 1e-7 -3.4028235e38\n");
    ExpectRoundTrip("Translate 1e39 0 0\n");  // beyond float range: an infinity both times
    ExpectRoundTrip("Polygon \"P\" [0.1 0.2 0.30000000000000004 16777217]\n");
    ExpectRoundTrip("Attribute \"user\" \"string s\" \"tab\\there\\nnew \\\\ \\\"q\\\" \\001\"\n");
    ExpectRoundTrip("LightSource \"spotlight\" \"key light\" Illuminate \"key light\" 0\n");
    ExpectRoundTrip("Basis [1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16] 3 \"catmull-rom\" 1\n");
    ExpectRoundTrip("ColorSamples [1 1 1 1 1 1] [0.5 0.5 0.5 0.5 0.5 0.5] Color [0.25 0.75]\n");
    ExpectRoundTrip("SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [\"hole\"] [0 0] [] []\n");
    ExpectRoundTrip("AttributeEnd AttributeEnd WorldBegin\n");  // unbalanced: not our business
}

TEST(RibWriter, RoundTripsEveryRequest) {
    // One of each request, as in rib_requests_test.cpp.
    ExpectRoundTrip(
        "FrameBegin 3 WorldBegin AttributeBegin TransformBegin ObjectBegin 7 ObjectEnd "
        "ObjectInstance \"x\" MotionBegin [0 1] MotionEnd SolidBegin \"union\" SolidEnd "
        "Declare \"foo\" \"uniform float\" Format 640 480 1.5 FrameAspectRatio 1.5 "
        "ScreenWindow -1 1 -1 1 CropWindow 0 1 0 1 Projection \"perspective\" \"fov\" 30 "
        "Clipping 0.1 100 ClippingPlane 0 0 1 0 0 -1 DepthOfField 2.8 50 100 Shutter 0 1 "
        "PixelVariance 0.1 PixelSamples 2 2 PixelFilter \"box\" 1 1 Exposure 1 2.2 "
        "Imager \"background\" Quantize \"rgba\" 255 0 255 0.5 "
        "Display \"out.tif\" \"file\" \"rgba\" \"origin\" [0 0] Hider \"hidden\" "
        "RelativeDetail 1 Option \"limits\" \"bucketsize\" [16 16] Color [1 0 0] Opacity 1 1 1 "
        "TextureCoordinates [0 0 1 0 0 1 1 1] LightSource \"pointlight\" 1 "
        "AreaLightSource \"arealight\" 2 Illuminate 1 1 Surface \"matte\" "
        "Displacement \"bumpy\" Atmosphere \"fog\" Interior \"i\" Exterior \"e\" ShadingRate 1 "
        "ShadingInterpolation \"smooth\" Matte 0 Bound [0 1 0 1 0 1] Detail [0 1 0 1 0 1] "
        "DetailRange 0 0 1 2 GeometricApproximation \"flatness\" 0.5 Orientation \"rh\" "
        "ReverseOrientation Sides 1 Attribute \"identifier\" \"name\" \"n\" "
        "Basis \"bezier\" 3 \"bezier\" 3 "
        "TrimCurve [1] [2] [0 0 1 1] [0] [1] [2] [0 1] [0 1] [1 1] Identity "
        "Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] "
        "ConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 1 2 3 1] Perspective 45 Translate 1 2 3 "
        "Rotate 30 0 1 0 Scale 2 2 2 Skew 45 0 1 0 1 0 0 CoordinateSystem \"c\" "
        "ScopedCoordinateSystem \"d\" CoordSysTransform \"c\" Polygon \"P\" [0 0 0 1 0 0 0 1 0] "
        "GeneralPolygon [3] \"P\" [0 0 0 1 0 0 0 1 0] PointsPolygons [3] [0 1 2] "
        "PointsGeneralPolygons [1] [3] [0 1 2] Patch \"bilinear\" "
        "PatchMesh \"bilinear\" 2 \"nonperiodic\" 2 \"nonperiodic\" "
        "NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 "
        "SubdivisionMesh \"catmull-clark\" [3] [0 1 2] Sphere 1 -1 1 360 Cone 1 1 360 "
        "Cylinder 1 0 1 360 Hyperboloid 1 0 0 0 1 1 360 Paraboloid 1 0 1 360 Disk 0 1 360 "
        "Torus 1 0.5 0 360 360 Points \"P\" [0 0 0] Curves \"linear\" [2] \"nonperiodic\" "
        "Blobby 1 [1001 0] [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] [] "
        "Procedural \"DelayedReadArchive\" [\"a.rib\"] [0 1 0 1 0 1] Geometry \"teapot\" "
        "MakeTexture \"a\" \"b\" \"clamp\" \"clamp\" \"box\" 1 1 "
        "MakeLatLongEnvironment \"a\" \"b\" \"box\" 1 1 "
        "MakeCubeFaceEnvironment \"a\" \"b\" \"c\" \"d\" \"e\" \"f\" \"g\" 90 \"box\" 1 1 "
        "MakeShadow \"a\" \"b\" ErrorHandler \"print\" "
        "TransformEnd AttributeEnd WorldEnd FrameEnd\n");
}

TEST(RibWriter, RoundTripsTheConformanceScenes) {
    const fs::path root = GONIO_CONFORMANCE_DIR "/scenes";
    if (!fs::exists(root)) GTEST_SKIP() << "no " << root;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (entry.path().extension() != ".rib") continue;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        // Parsed as a string named after the file, so archives resolve as they would.
        const ParseResult first = ParseText(text.str(), entry.path().string());
        std::ostringstream printed;
        RibWriter writer(printed);
        Diagnostics quiet(nullptr);
        ParseRibString(text.str(), entry.path().string(), writer, quiet);
        const ParseResult second = ParseText(printed.str(), entry.path().string());
        EXPECT_EQ(second.target.Text(), first.target.Text()) << entry.path();
    }
}

}  // namespace
}  // namespace gonio
