// Every request the parser passes on reaches exactly one RiTarget call with the values written.

#include <gtest/gtest.h>

#include <set>

#include "rib_test_util.h"

namespace gonio {
namespace {

struct RequestCase {
    const char* rib;
    const char* expected;  // the recorded call
};

const RequestCase kCases[] = {
    {"FrameBegin 3", "FrameBegin 3"},
    {"FrameEnd", "FrameEnd"},
    {"WorldBegin", "WorldBegin"},
    {"WorldEnd", "WorldEnd"},
    {"AttributeBegin", "AttributeBegin"},
    {"AttributeEnd", "AttributeEnd"},
    {"TransformBegin", "TransformBegin"},
    {"TransformEnd", "TransformEnd"},
    {"ObjectBegin 7", "ObjectBegin handle:7"},
    {"ObjectBegin \"tree\"", "ObjectBegin handle:\"tree\""},
    {"ObjectEnd", "ObjectEnd"},
    {"ObjectInstance 7", "ObjectInstance handle:7"},
    {"MotionBegin [0 0.5 1]", "MotionBegin [0 0.5 1]"},
    {"MotionEnd", "MotionEnd"},
    {"SolidBegin \"union\"", "SolidBegin \"union\""},
    {"SolidEnd", "SolidEnd"},
    {"Declare \"foo\" \"varying float[2]\"", "Declare \"foo\" \"varying float[2]\""},
    {"Format 640 480 1", "Format 640 480 1"},
    {"FrameAspectRatio 1.5", "FrameAspectRatio 1.5"},
    {"ScreenWindow -1 1 -0.75 0.75", "ScreenWindow -1 1 -0.75 0.75"},
    {"CropWindow 0 0.5 0.25 1", "CropWindow 0 0.5 0.25 1"},
    {"Projection \"perspective\" \"fov\" 45", "Projection \"perspective\" {\"fov\"=[45]}"},
    {"Projection \"orthographic\"", "Projection \"orthographic\" {}"},
    {"Clipping 0.1 1000", "Clipping 0.1 1000"},
    {"ClippingPlane 0 0 1 0 0 -1", "ClippingPlane 0 0 1 0 0 -1"},
    {"DepthOfField 22 45 1200", "DepthOfField 22 45 1200"},
    {"DepthOfField", "DepthOfField inf 0 0"},
    {"Shutter 0 1", "Shutter 0 1"},
    {"PixelVariance 0.01", "PixelVariance 0.01"},
    {"PixelSamples 4 4", "PixelSamples 4 4"},
    {"PixelFilter \"gaussian\" 2 2", "PixelFilter \"gaussian\" 2 2"},
    {"Exposure 1.5 2.2", "Exposure 1.5 2.2"},
    {"Imager \"background\" \"background\" [1 1 1]",
     "Imager \"background\" {\"background\"=[1 1 1]}"},
    {"Quantize \"rgba\" 255 0 255 0.5", "Quantize \"rgba\" 255 0 255 0.5"},
    {"Display \"+out.tif\" \"file\" \"rgba\" \"string compression\" \"lzw\"",
     "Display \"+out.tif\" \"file\" \"rgba\" {\"string compression\"=[\"lzw\"]}"},
    {"Hider \"hidden\" \"jitter\" [1]", "Hider \"hidden\" {\"jitter\"=[1]}"},
    {"ColorSamples [1 0 0 0 1 0] [1 0 0 0 1 0]", "ColorSamples [1 0 0 0 1 0] [1 0 0 0 1 0]"},
    {"RelativeDetail 0.6", "RelativeDetail 0.6"},
    {"Option \"limits\" \"bucketsize\" [16 16]", "Option \"limits\" {\"bucketsize\"=[16 16]}"},
    {"Color [0.1 0.2 0.3]", "Color [0.1 0.2 0.3]"},
    {"Color 0.1 0.2 0.3", "Color [0.1 0.2 0.3]"},
    {"Opacity [1 0.5 0.25]", "Opacity [1 0.5 0.25]"},
    {"TextureCoordinates 0 0 1 0 0 1 1 1", "TextureCoordinates [0 0 1 0 0 1 1 1]"},
    {"LightSource \"pointlight\" 1 \"intensity\" 10",
     "LightSource \"pointlight\" handle:1 {\"intensity\"=[10]}"},
    {"LightSource \"spotlight\" \"key\" \"from\" [0 1 0]",
     "LightSource \"spotlight\" handle:\"key\" {\"from\"=[0 1 0]}"},
    {"AreaLightSource \"arealight\" 2", "AreaLightSource \"arealight\" handle:2 {}"},
    {"Illuminate 1 0", "Illuminate handle:1 off"},
    {"Illuminate \"key\" 1", "Illuminate handle:\"key\" on"},
    {"Surface \"plastic\" \"Kd\" 0.5 \"Ks\" [0.25]",
     "Surface \"plastic\" {\"Kd\"=[0.5] \"Ks\"=[0.25]}"},
    {"Displacement \"bumpy\" \"Km\" 0.1", "Displacement \"bumpy\" {\"Km\"=[0.1]}"},
    {"Atmosphere \"fog\" \"distance\" 10", "Atmosphere \"fog\" {\"distance\"=[10]}"},
    {"Interior \"water\"", "Interior \"water\" {}"},
    {"Exterior \"air\"", "Exterior \"air\" {}"},
    {"ShadingRate 1", "ShadingRate 1"},
    {"ShadingInterpolation \"smooth\"", "ShadingInterpolation \"smooth\""},
    {"Matte 1", "Matte on"},
    {"Bound [-1 1 -1 1 -1 1]", "Bound [-1 1 -1 1 -1 1]"},
    {"Detail -1 1 -1 1 -1 1", "Detail [-1 1 -1 1 -1 1]"},
    {"DetailRange [0 0 10 20]", "DetailRange 0 0 10 20"},
    {"GeometricApproximation \"flatness\" 0.5", "GeometricApproximation \"flatness\" 0.5"},
    {"Orientation \"lh\"", "Orientation \"lh\""},
    {"ReverseOrientation", "ReverseOrientation"},
    {"Sides 2", "Sides 2"},
    {"Attribute \"identifier\" \"name\" \"ball\"",
     "Attribute \"identifier\" {\"name\"=[\"ball\"]}"},
    {"Basis \"bezier\" 3 \"b-spline\" 1", "Basis \"bezier\" 3 \"b-spline\" 1"},
    {"Basis [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] 4 \"power\" 4",
     "Basis [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1] 4 \"power\" 4"},
    {"TrimCurve [1] [3] [0 0 0 1 1 1] [0] [1] [3] [0 1 0] [0 0 1] [1 1 1]",
     "TrimCurve [1] [3] [0 0 0 1 1 1] [0] [1] [3] [0 1 0] [0 0 1] [1 1 1]"},
    {"Identity", "Identity"},
    {"Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 5 1]", "Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 5 1]"},
    {"ConcatTransform [2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1]",
     "ConcatTransform [2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1]"},
    {"Perspective 90", "Perspective 90"},
    {"Translate 1 2 3", "Translate 1 2 3"},
    {"Rotate 90 0 0 1", "Rotate 90 0 0 1"},
    {"Scale 1 -1 1", "Scale 1 -1 1"},
    {"Skew [45 0 1 0 1 0 0]", "Skew 45 0 1 0 1 0 0"},
    {"CoordinateSystem \"lamp\"", "CoordinateSystem \"lamp\""},
    {"ScopedCoordinateSystem \"lamp\"", "ScopedCoordinateSystem \"lamp\""},
    {"CoordSysTransform \"lamp\"", "CoordSysTransform \"lamp\""},
    {"Polygon \"P\" [0 0 0 1 0 0 0 1 0]", "Polygon {\"P\"=[0 0 0 1 0 0 0 1 0]}"},
    {"GeneralPolygon [4 3] \"P\" [0 0 0]", "GeneralPolygon [4 3] {\"P\"=[0 0 0]}"},
    {"PointsPolygons [3 3] [0 1 2 2 1 3] \"P\" [0 0 0]",
     "PointsPolygons [3 3] [0 1 2 2 1 3] {\"P\"=[0 0 0]}"},
    {"PointsGeneralPolygons [2] [4 3] [0 1 2 3 4 5 6]",
     "PointsGeneralPolygons [2] [4 3] [0 1 2 3 4 5 6] {}"},
    {"Patch \"bilinear\" \"P\" [0 0 0]", "Patch \"bilinear\" {\"P\"=[0 0 0]}"},
    {"PatchMesh \"bicubic\" 7 \"nonperiodic\" 4 \"periodic\"",
     "PatchMesh \"bicubic\" 7 \"nonperiodic\" 4 \"periodic\" {}"},
    {"NuPatch 4 4 [0 0 0 0 1 1 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"Pw\" [0 0 0 1]",
     "NuPatch 4 4 [0 0 0 0 1 1 1 1] 0 1 2 2 [0 0 1 1] 0 1 {\"Pw\"=[0 0 0 1]}"},
    {"SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] \"P\" [0 0 0]",
     "SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [] [] [] [] {\"P\"=[0 0 0]}"},
    {"SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [\"crease\" \"interpolateboundary\"] "
     "[2 1 0 0] [0 1] [2.5]",
     "SubdivisionMesh \"catmull-clark\" [4] [0 1 2 3] [\"crease\" \"interpolateboundary\"] "
     "[2 1 0 0] [0 1] [2.5] {}"},
    {"SubdivisionMesh \"loop\" [3] [0 1 2] [] [] [] []",
     "SubdivisionMesh \"loop\" [3] [0 1 2] [] [] [] [] {}"},
    {"Sphere 1 -1 1 360", "Sphere 1 -1 1 360 {}"},
    {"Sphere [1 -1 1 360] \"Kd\" [0.5]", "Sphere 1 -1 1 360 {\"Kd\"=[0.5]}"},
    {"Cone 2 1 360", "Cone 2 1 360 {}"},
    {"Cylinder 1 0 2 180", "Cylinder 1 0 2 180 {}"},
    {"Hyperboloid 1 0 0 0 1 1 360", "Hyperboloid 1 0 0 0 1 1 360 {}"},
    {"Hyperboloid [1 0 0 0 1 1 360]", "Hyperboloid 1 0 0 0 1 1 360 {}"},
    {"Paraboloid 1 0 2 360", "Paraboloid 1 0 2 360 {}"},
    {"Disk 0 1 360", "Disk 0 1 360 {}"},
    {"Torus 1 0.25 0 360 360", "Torus 1 0.25 0 360 360 {}"},
    {"Points \"P\" [0 0 0] \"constantwidth\" 0.1",
     "Points {\"P\"=[0 0 0] \"constantwidth\"=[0.1]}"},
    {"Curves \"cubic\" [4] \"nonperiodic\" \"width\" [0.1 0.2]",
     "Curves \"cubic\" [4] \"nonperiodic\" {\"width\"=[0.1 0.2]}"},
    {"Blobby 2 [1001 0 1001 16 0 2 0 1] [1 0 0 0] [\"\"]",
     "Blobby 2 [1001 0 1001 16 0 2 0 1] [1 0 0 0] [\"\"] {}"},
    {"Procedural \"DelayedReadArchive\" [\"tree.rib\"] [-1 1 -1 1 0 2]",
     "Procedural \"DelayedReadArchive\" [\"tree.rib\"] [-1 1 -1 1 0 2]"},
    {"Geometry \"teapot\"", "Geometry \"teapot\" {}"},
    {"MakeTexture \"in.tif\" \"out.tx\" \"periodic\" \"clamp\" \"gaussian\" 2 2",
     "MakeTexture \"in.tif\" \"out.tx\" \"periodic\" \"clamp\" \"gaussian\" 2 2 {}"},
    {"MakeLatLongEnvironment \"in.tif\" \"out.env\" \"box\" 1 1",
     "MakeLatLongEnvironment \"in.tif\" \"out.env\" \"box\" 1 1 {}"},
    {"MakeCubeFaceEnvironment \"px\" \"nx\" \"py\" \"ny\" \"pz\" \"nz\" \"env\" 95 \"box\" 1 1",
     "MakeCubeFaceEnvironment [\"px\" \"nx\" \"py\" \"ny\" \"pz\" \"nz\"] \"env\" 95 \"box\" 1 1 "
     "{}"},
    {"MakeShadow \"depth.z\" \"shadow.tx\"", "MakeShadow \"depth.z\" \"shadow.tx\" {}"},
    {"ErrorHandler \"print\"", "ErrorHandler \"print\""},
};

class RequestTest : public ::testing::TestWithParam<RequestCase> {};

TEST_P(RequestTest, MakesExactlyOneCall) {
    const ParseResult result = ParseText(GetParam().rib);
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.messages, "");
    ASSERT_EQ(result.target.calls.size(), 1u) << result.target.Text();
    EXPECT_EQ(result.target.calls[0], GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(AllRequests, RequestTest, ::testing::ValuesIn(kCases));

TEST(Requests, EveryTargetMethodIsCovered) {
    // Each request of the table that reaches the target appears in kCases.
    std::set<std::string> covered;
    for (const RequestCase& c : kCases)
        covered.insert(std::string(c.expected).substr(0, std::string(c.expected).find(' ')));
    EXPECT_EQ(covered.size(), 96u);  // RiTarget has 96 methods
}

TEST(Requests, LocationsPointAtTheRequestName) {
    const ParseResult result = ParseText("WorldBegin\n  Sphere 1 -1 1 360\n\tWorldEnd");
    ASSERT_EQ(result.target.locs.size(), 3u);
    EXPECT_EQ(result.target.locs[1].ToString(), "test.rib:2:3");
    EXPECT_EQ(result.target.locs[2].ToString(), "test.rib:3:2");
}

TEST(Requests, ParameterLocationsPointAtTheToken) {
    struct SurfaceTarget : RecordingTarget {
        ParamList params;
        void Surface(const std::string& name, const ParamList& list, const FileLoc& loc) override {
            params = list;
            RecordingTarget::Surface(name, list, loc);
        }
    } target;
    Diagnostics diagnostics(nullptr);
    ASSERT_TRUE(
        ParseRibString("Surface \"plastic\"\n    \"Kd\" 0.5 \"string texturename\" \"a.tx\"",
                       "s.rib", target, diagnostics));
    ASSERT_EQ(target.params.size(), 2u);
    EXPECT_EQ(target.params[0].loc.ToString(), "s.rib:2:5");
    EXPECT_EQ(target.params[1].token, "string texturename");
    EXPECT_TRUE(target.params[1].isString);
    EXPECT_EQ(target.params[1].strings, std::vector<std::string>{"a.tx"});
    EXPECT_FALSE(target.params[0].isString);
}

TEST(Requests, ParserLevelRequestsDoNotReachTheTarget) {
    const ParseResult result = ParseText(
        "##RenderMan RIB-Structure 1.1\n"
        "version 3.04\n"
        "ArchiveRecord \"structure\" \"Scene foo\"\n"
        "# a comment\n"
        "WorldBegin # trailing comment\n");
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.target.Text(), "WorldBegin\n");
}

TEST(Requests, ExtensionRequestsWarnOnceAndAreIgnored) {
    const ParseResult result =
        ParseText("DisplayChannel \"color Ci\"\nDisplayChannel \"float a\"\nWorldBegin\n");
    EXPECT_TRUE(result.ok);
    EXPECT_EQ(result.target.Text(), "WorldBegin\n");
    EXPECT_EQ(result.messages,
              "test.rib:1:1: warning: DisplayChannel is not supported and is ignored\n");
}

TEST(Requests, RequestsThatCannotBeIgnoredAreErrors) {
    const ParseResult result = ParseText("IfBegin \"1\"\nWorldBegin\n");
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.messages, "test.rib:1:1: error: IfBegin is not supported\n");
    EXPECT_EQ(result.target.Text(), "WorldBegin\n");
}

}  // namespace
}  // namespace gonio
