// Error and warning messages of the scene builder (renderer/scene/), driven through the RIB
// parser: each class of bad input must produce its exact `file:line:col: severity: message`,
// and the requests that are not in error must still reach the Frame.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "base/math.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"
#include "renderer/scene/unused_parameters.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio {
namespace {

struct BuildResult {
    std::string messages;  // everything Diagnostics printed, one line per message
    int errors = 0, warnings = 0;
    std::vector<Frame> frames;  // every Frame handed over at WorldEnd
};

// Parses `rib` (named test.rib) into a SceneBuilder, capturing the diagnostics in memory; with
// `reportUnused`, each frame's unread parameters are reported as after a render.
BuildResult Build(const std::string& rib, bool reportUnused = false) {
    BuildResult result;
    test::CapturedDiagnostics captured;
    {
        Diagnostics& diagnostics = captured.Get();
        SceneBuilder builder("test.rib", diagnostics, [&](const Frame& frame) {
            result.frames.push_back(frame);
            if (reportUnused) ReportUnusedParameters(frame, diagnostics);
        });
        ParseRibString(rib, "test.rib", builder, diagnostics);
        builder.Finish(FileLoc{std::make_shared<const std::string>("test.rib"), 0, 0});
        result.errors = diagnostics.ErrorCount();
        result.warnings = diagnostics.WarningCount();
    }
    result.messages = captured.Text();
    return result;
}

// ---- block structure ------------------------------------------------------------------------

TEST(SceneBuilderBlocks, AttributeEndWithoutBeginOutsideAnyBlock) {
    const BuildResult r = Build("AttributeEnd\n");
    EXPECT_EQ(r.messages, "test.rib:1:1: error: AttributeEnd does not match: no block is open\n");
    EXPECT_EQ(r.errors, 1);
}

TEST(SceneBuilderBlocks, AttributeEndWithoutBeginInsideTheWorld) {
    const BuildResult r = Build("WorldBegin\n  AttributeEnd\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:3: error: AttributeEnd does not match: WorldBegin at test.rib:1:1 is "
              "still open\n");
    ASSERT_EQ(r.frames.size(), 1u) << "the world is still closed and rendered";
}

TEST(SceneBuilderBlocks, EndOfTheWrongKind) {
    const BuildResult r =
        Build("WorldBegin\nTransformBegin\nAttributeEnd\nTransformEnd\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:3:1: error: AttributeEnd does not match: TransformBegin at test.rib:2:1 "
              "is still open\n");
    EXPECT_EQ(r.errors, 1);
}

TEST(SceneBuilderBlocks, WorldBeginNeverClosed) {
    const BuildResult r = Build("Format 8 8 1\nWorldBegin\nSphere 1 -1 1 360\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: WorldBegin is never closed (input ends at test.rib)\n");
    EXPECT_TRUE(r.frames.empty());
}

TEST(SceneBuilderBlocks, EveryOpenBlockIsReportedInnermostFirst) {
    const BuildResult r = Build("FrameBegin 1\nWorldBegin\nAttributeBegin\n");
    EXPECT_EQ(r.messages,
              "test.rib:3:1: error: AttributeBegin is never closed (input ends at test.rib)\n"
              "test.rib:2:1: error: WorldBegin is never closed (input ends at test.rib)\n"
              "test.rib:1:1: error: FrameBegin is never closed (input ends at test.rib)\n");
}

TEST(SceneBuilderBlocks, NestedObjectBegin) {
    const BuildResult r = Build("WorldBegin\nObjectBegin 1\nObjectBegin 2\nObjectEnd\nWorldEnd\n");
    EXPECT_EQ(r.messages, "test.rib:3:1: error: ObjectBegin inside another ObjectBegin block\n");
}

// ---- scope ----------------------------------------------------------------------------------

TEST(SceneBuilderScope, OptionsInsideTheWorld) {
    const BuildResult r = Build(
        "WorldBegin\nFormat 10 10 1\nProjection \"perspective\"\nOption \"limits\" "
        "\"bucketsize\" [16 16]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: Format is an option and is not valid inside "
              "WorldBegin/WorldEnd\n"
              "test.rib:3:1: error: Projection is an option and is not valid inside "
              "WorldBegin/WorldEnd\n"
              "test.rib:4:1: error: Option is an option and is not valid inside "
              "WorldBegin/WorldEnd\n");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].options.xres, 640) << "the rejected Format must not apply";
}

TEST(SceneBuilderScope, PrimitivesOutsideTheWorld) {
    const BuildResult r = Build("Sphere 1 -1 1 360\nPolygon \"P\" [0 0 0 1 0 0 1 1 0]\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:1: error: Sphere is a primitive and is only valid inside "
              "WorldBegin/WorldEnd\n"
              "test.rib:2:1: error: Polygon is a primitive and is only valid inside "
              "WorldBegin/WorldEnd\n");
}

TEST(SceneBuilderScope, IlluminateOutsideTheWorld) {
    const BuildResult r = Build("Illuminate 1 1\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:1: error: Illuminate is only valid inside WorldBegin/WorldEnd\n");
}

// ---- primitive variables --------------------------------------------------------------------

TEST(SceneBuilderPrimVars, PointsPolygonsWithTooFewPoints) {
    // Vertex indices reach 3, so P needs 4 points; it has 3.
    const BuildResult r = Build(
        "WorldBegin\n"
        "PointsPolygons [4] [0 1 2 3] \"P\" [0 0 0  1 0 0  1 1 0]\n"
        "Sphere 1 -1 1 360\n"
        "WorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: PointsPolygons: vertex index 3 is out of range (P has 3 "
              "values)\n");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].shapes.size(), 1u) << "the bad mesh is skipped, the sphere is kept";
}

TEST(SceneBuilderPrimVars, VaryingColourWithTheWrongCountOnAQuadric) {
    const BuildResult r =
        Build("WorldBegin\nSphere 1 -1 1 360 \"varying color Cs\" [1 0 0  0 1 0]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: Sphere: varying variable \"Cs\" needs 4 values, got 2\n");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_TRUE(r.frames[0].shapes.empty());
}

TEST(SceneBuilderPrimVars, UniformColourWithTheWrongCountOnAMesh) {
    const BuildResult r = Build(
        "WorldBegin\nPointsPolygons [3 3] [0 1 2  0 2 3] \"P\" [0 0 0  1 0 0  1 1 0  0 1 0]\n"
        "  \"uniform color Cs\" [1 0 0]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: PointsPolygons: uniform variable \"Cs\" needs 2 values, got "
              "1\n");
}

TEST(SceneBuilderPrimVars, ValueCountNotAMultipleOfTheType) {
    const BuildResult r = Build("WorldBegin\nPolygon \"P\" [0 0 0  1 0 0  1 1]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:9: error: parameter \"P\" needs a multiple of 3 numbers, got 8\n");
}

TEST(SceneBuilderPrimVars, UndeclaredParameterOnAPrimitiveIsAnError) {
    const BuildResult r = Build("WorldBegin\nSphere 1 -1 1 360 \"roughness2\" [0.5]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:19: error: parameter \"roughness2\" is not declared (use Declare or an "
              "inline type, e.g. \"uniform float roughness2\")\n");
    EXPECT_EQ(r.errors, 1);
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_TRUE(r.frames[0].shapes.empty()) << "a primitive with a bad parameter is skipped";
}

TEST(SceneBuilderPrimVars, DeclaredParameterIsAccepted) {
    const BuildResult r = Build(
        "Declare \"roughness2\" \"uniform float\"\n"
        "WorldBegin\nSphere 1 -1 1 360 \"roughness2\" [0.5]\nWorldEnd\n");
    EXPECT_EQ(r.messages, "");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].shapes.size(), 1u);
}

// ---- unknown names: warnings for Option/Attribute, errors for handles -----------------------

TEST(SceneBuilderUnknown, UnknownOptionAndAttributeAreWarnings) {
    const BuildResult r = Build(
        "Option \"nosuchoption\" \"float x\" [1]\n"
        "WorldBegin\nAttribute \"nosuchattribute\" \"float y\" [2]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:1: warning: unknown Option \"nosuchoption\" ignored\n"
              "test.rib:3:1: warning: unknown Attribute \"nosuchattribute\" (kept for "
              "shaders)\n");
    EXPECT_EQ(r.errors, 0);
    EXPECT_EQ(r.warnings, 2);
    ASSERT_EQ(r.frames.size(), 1u);
}

TEST(SceneBuilderUnknown, UnknownParameterOfAKnownOptionIsAWarning) {
    const BuildResult r = Build("Option \"limits\" \"nosuchlimit\" [3]\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:17: warning: Option \"limits\": unknown parameter \"nosuchlimit\" "
              "ignored\n");
    EXPECT_EQ(r.errors, 0);
}

TEST(SceneBuilderUnknown, IlluminateWithAnUnknownHandle) {
    const BuildResult r = Build(
        "WorldBegin\nLightSource \"pointlight\" 1\nIlluminate 1 0\nIlluminate 7 1\n"
        "Illuminate \"key\" 1\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:4:1: error: Illuminate: no light has handle 7\n"
              "test.rib:5:1: error: Illuminate: no light has handle \"key\"\n");
}

TEST(SceneBuilderUnknown, ObjectInstanceOfAnUnknownHandle) {
    const BuildResult r = Build(
        "WorldBegin\nObjectBegin 1\nSphere 1 -1 1 360\nObjectEnd\nObjectInstance 1\n"
        "ObjectInstance 3\nObjectInstance \"tree\"\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:6:1: error: ObjectInstance: no object was defined with handle 3\n"
              "test.rib:7:1: error: ObjectInstance: no object was defined with handle "
              "\"tree\"\n");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].instances.size(), 1u);
}

TEST(SceneBuilderUnknown, CoordSysTransformToAnUnknownSpace) {
    const BuildResult r = Build("WorldBegin\nCoordSysTransform \"lamp\"\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: CoordSysTransform: no coordinate system named \"lamp\"\n");
}

// ---- bad values -----------------------------------------------------------------------------

TEST(SceneBuilderValues, BadOrientation) {
    const BuildResult r = Build("WorldBegin\nOrientation \"sideways\"\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: Orientation must be outside, inside, lh or rh, got "
              "\"sideways\"\n");
}

TEST(SceneBuilderValues, BadSides) {
    const BuildResult r = Build("WorldBegin\nSides 3\nWorldEnd\n");
    EXPECT_EQ(r.messages, "test.rib:2:1: error: Sides must be 1 or 2, got 3\n");
}

TEST(SceneBuilderValues, ColourWithTheWrongNumberOfComponents) {
    // Checked by the parser against ColorSamples, at the argument.
    const BuildResult r = Build("WorldBegin\nColor [1 0]\nOpacity [1 1 1 1]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:7: error: Color expects 3 numbers, got 2\n"
              "test.rib:3:9: error: Opacity expects 3 numbers, got 4\n");
}

TEST(SceneBuilderValues, BadCameraOptions) {
    const BuildResult r = Build(
        "Format 0 10 1\nProjection \"fisheye\"\nClipping 5 1\nScreenWindow 1 1 0 1\n"
        "CropWindow 0.6 0.4 0 1\nPixelSamples 0 1\nPixelFilter \"box\" 0 1\nExposure 1 0\n"
        "ErrorHandler \"explode\"\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:1: error: Format needs a positive resolution, got 0x10\n"
              "test.rib:2:1: error: Projection \"fisheye\" is not supported (perspective, "
              "orthographic)\n"
              "test.rib:3:1: error: Clipping needs 0 < near < far\n"
              "test.rib:4:1: error: ScreenWindow has zero width or height\n"
              "test.rib:5:1: error: CropWindow is empty\n"
              "test.rib:6:1: error: PixelSamples must be at least 1 1\n"
              "test.rib:7:1: error: PixelFilter widths must be positive\n"
              "test.rib:8:1: error: Exposure gamma must be positive\n"
              "test.rib:9:1: error: ErrorHandler must be \"print\", \"ignore\" or \"abort\", got "
              "\"explode\"\n");
    EXPECT_EQ(r.errors, 9);
}

// Sizes that would run for days or exhaust memory are refused where they are asked for.
TEST(SceneBuilderValues, SamplesAndFiltersPastTheLimits) {
    const BuildResult r = Build(
        "PixelSamples 100000 100000\nPixelFilter \"gaussian\" 100000 2\nPixelSamples 1024 1024\n"
        "PixelFilter \"box\" 256 256\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:1: error: PixelSamples must be at most 1024 in each direction\n"
              "test.rib:2:1: error: PixelFilter widths must be at most 256 pixels\n");
    EXPECT_EQ(r.errors, 2);
}

// ---- what survives ----------------------------------------------------------------------------

TEST(SceneBuilderFrames, OptionsSetInAFrameDoNotLeakIntoTheNext) {
    const BuildResult r = Build(
        "Format 64 48 1\n"
        "FrameBegin 1\nFormat 16 16 1\nDisplay \"a.tif\" \"file\" \"rgba\"\nWorldBegin\n"
        "WorldEnd\nFrameEnd\n"
        "FrameBegin 2\nWorldBegin\nWorldEnd\nFrameEnd\n");
    EXPECT_EQ(r.messages, "");
    ASSERT_EQ(r.frames.size(), 2u);
    EXPECT_EQ(r.frames[0].number, 1);
    EXPECT_EQ(r.frames[0].options.xres, 16);
    EXPECT_EQ(r.frames[0].options.displays.size(), 1u);
    EXPECT_EQ(r.frames[1].number, 2);
    EXPECT_EQ(r.frames[1].options.xres, 64);
    EXPECT_TRUE(r.frames[1].options.displays.empty());
}

TEST(SceneBuilderFrames, PlusAddsADisplayAndAPlainNameReplacesThem) {
    const BuildResult r = Build(
        "Display \"a.tif\" \"file\" \"rgba\"\nDisplay \"+b.exr\" \"openexr\" \"z\"\n"
        "WorldBegin\nWorldEnd\n"
        "Display \"c.png\" \"png\" \"rgb\"\nWorldBegin\nWorldEnd\n");
    ASSERT_EQ(r.frames.size(), 2u);
    ASSERT_EQ(r.frames[0].options.displays.size(), 2u);
    EXPECT_EQ(r.frames[0].options.displays[1].name, "b.exr");
    EXPECT_EQ(r.frames[0].options.displays[1].mode, "z");
    ASSERT_EQ(r.frames[1].options.displays.size(), 1u);
    EXPECT_EQ(r.frames[1].options.displays[0].name, "c.png");
}

TEST(SceneBuilderFrames, ReyesOnlyRequestsAreNotedOnce) {
    const BuildResult r = Build(
        "WorldBegin\nBound [0 1 0 1 0 1]\nShadingInterpolation \"smooth\"\nBound [0 1 0 1 0 "
        "1]\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: note: Bound is accepted and ignored by this ray tracer\n"
              "test.rib:3:1: note: ShadingInterpolation is accepted and ignored by this ray "
              "tracer\n");
    EXPECT_EQ(r.errors + r.warnings, 0);
}

TEST(SceneBuilderAttributes, ShadingRateIsAnAttribute) {
    const BuildResult r = Build(
        "WorldBegin\nShadingRate 4\nSphere 1 -1 1 360\nAttributeBegin\nShadingRate 0.25\n"
        "Sphere 1 -1 1 360\nAttributeEnd\nSphere 1 -1 1 360\nWorldEnd\n");
    EXPECT_EQ(r.errors + r.warnings, 0) << r.messages;
    ASSERT_EQ(r.frames.size(), 1u);
    ASSERT_EQ(r.frames[0].shapes.size(), 3u);
    EXPECT_FLOAT_EQ(r.frames[0].shapes[0].attributes->shadingRate, 4);
    EXPECT_FLOAT_EQ(r.frames[0].shapes[1].attributes->shadingRate, 0.25f);
    EXPECT_FLOAT_EQ(r.frames[0].shapes[2].attributes->shadingRate, 4);
}

TEST(SceneBuilderAttributes, ShadingRateMustBePositive) {
    const BuildResult r = Build("WorldBegin\nShadingRate 0\nShadingRate -1\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:2:1: error: ShadingRate must be a positive, finite area in pixels\n"
              "test.rib:3:1: error: ShadingRate must be a positive, finite area in pixels\n");
}

TEST(SceneBuilderFrames, PerspectiveIsTreatedAsProjection) {
    const BuildResult r = Build("Perspective 40\nWorldBegin\nWorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:1:1: note: Perspective is rendered as Projection \"perspective\" with "
              "this fov\n");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].options.projection, "perspective");
    EXPECT_FLOAT_EQ(r.frames[0].options.fov, 40);
}

TEST(SceneBuilderFrames, MotionBlocksKeepTheTransformAtEachTime) {
    const BuildResult r = Build(
        "WorldBegin\nMotionBegin [0 1]\nTranslate 1 0 0\nTranslate 2 0 0\nMotionEnd\n"
        "Scale 2 2 2\nSphere 1 -1 1 360\nWorldEnd\n");
    EXPECT_EQ(r.messages, "");
    ASSERT_EQ(r.frames.size(), 1u);
    ASSERT_EQ(r.frames[0].shapes.size(), 1u);
    const SceneShape& shape = r.frames[0].shapes[0];
    // The static transform is the first sample; the Scale after the block applies at every time.
    EXPECT_FLOAT_EQ(shape.worldFromObject[3][0], 1);
    ASSERT_EQ(shape.motionTimes, (std::vector<float>{0, 1}));
    ASSERT_EQ(shape.worldFromObjectMotion.size(), 2u);
    EXPECT_FLOAT_EQ(shape.worldFromObjectMotion[0][3][0], 1);
    EXPECT_FLOAT_EQ(shape.worldFromObjectMotion[1][3][0], 2);
    EXPECT_FLOAT_EQ(shape.worldFromObjectMotion[1][0][0], 2);
}

// RISpec's RiSkew shifts points along the second vector, turning the first towards it: Skew 45
// from y towards x takes (0, 1, 0) to (1, 1, 0) and leaves x and z alone.
TEST(SceneBuilderFrames, SkewTurnsTheFirstVectorTowardsTheSecond) {
    const BuildResult r = Build(
        "WorldBegin\nSkew 45 0 1 0 1 0 0\nSphere 1 -1 1 360\nSkew 30 1 0 0 0 0 1\n"
        "Sphere 1 -1 1 360\nWorldEnd\n");
    EXPECT_EQ(r.messages, "");
    ASSERT_EQ(r.frames.size(), 1u);
    ASSERT_EQ(r.frames[0].shapes.size(), 2u);
    const M44f& skew = r.frames[0].shapes[0].worldFromObject;
    V3f y, x, z;
    skew.multVecMatrix(V3f(0, 1, 0), y);
    skew.multVecMatrix(V3f(1, 0, 0), x);
    skew.multVecMatrix(V3f(0, 0, 1), z);
    EXPECT_NEAR((y - V3f(1, 1, 0)).length(), 0, 1e-6);
    EXPECT_NEAR((x - V3f(1, 0, 0)).length(), 0, 1e-6);
    EXPECT_NEAR((z - V3f(0, 0, 1)).length(), 0, 1e-6);
    // x turned 30° towards z (x is 90° from z: it ends 60° from it, still in the xz plane).
    const M44f& second = r.frames[0].shapes[1].worldFromObject;
    V3f x2;
    (second * skew.inverse()).multVecMatrix(V3f(1, 0, 0), x2);
    EXPECT_NEAR(x2.normalized().dot(V3f(0, 0, 1)), std::cos(60 * kDegree), 1e-6);
    EXPECT_NEAR(x2.y, 0, 1e-6);
}

TEST(SceneBuilderFrames, SearchPathAmpersandIsThePreviousPath) {
    const BuildResult r = Build(
        "Option \"searchpath\" \"shader\" \"one:&\"\nOption \"searchpath\" \"shader\" "
        "\"two:&\"\nWorldBegin\nWorldEnd\n");
    EXPECT_EQ(r.messages, "");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].options.user.at("searchpath").GetString("shader", ""), "two:one:@");
}

TEST(SceneBuilderFrames, MovingQuadricsUseTheirFirstSample) {
    const BuildResult r = Build(
        "WorldBegin\nMotionBegin [0 1]\nSphere 1 -1 1 360\nSphere 2 -2 2 360\nMotionEnd\n"
        "WorldEnd\n");
    EXPECT_EQ(r.messages,
              "test.rib:4:1: note: only polygon, patch and subdivision meshes of unchanged "
              "topology deform in a motion block; this primitive uses its first sample\n");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].shapes.size(), 1u);
}

TEST(SceneBuilderFrames, MovingMeshesKeepTheirPositionsAtEachTime) {
    const BuildResult r = Build(
        "WorldBegin\nMotionBegin [0 1]\n"
        "Polygon \"P\" [0 0 0 1 0 0 1 1 0]\nPolygon \"P\" [0 0 1 1 0 1 1 1 1]\n"
        "MotionEnd\nWorldEnd\n");
    EXPECT_EQ(r.messages, "");
    ASSERT_EQ(r.frames.size(), 1u);
    ASSERT_EQ(r.frames[0].shapes.size(), 1u);
    const SceneShape& shape = r.frames[0].shapes[0];
    ASSERT_EQ(shape.deformPositions.size(), 2u);
    EXPECT_FLOAT_EQ(shape.deformPositions[0][2].z, 0);
    EXPECT_FLOAT_EQ(shape.deformPositions[1][2].z, 1);
}

// ---- parameters nobody read ------------------------------------------------------------------

TEST(SceneBuilderUnused, UnreadOptionAndAttributeParametersAreReportedAtTheirLocation) {
    const BuildResult r = Build(
        "Option \"trace\" \"integer maxdeph\" [3]\n"
        "WorldBegin\nAttribute \"user\" \"float unread\" [1]\nSphere 1 -1 1 360\nWorldEnd\n",
        true);
    EXPECT_EQ(r.messages,
              "test.rib:1:16: warning: Option \"trace\" parameter \"maxdeph\" had no effect on "
              "this frame\n"
              "test.rib:3:18: warning: Attribute \"user\" parameter \"unread\" had no effect on "
              "this frame\n");
}

TEST(SceneBuilderUnused, ReadParametersAreNotReported) {
    const BuildResult r = Build(
        "Option \"searchpath\" \"archive\" [\".\"]\n"
        "WorldBegin\nAttribute \"identifier\" \"name\" [\"ball\"]\n"
        "Attribute \"light\" \"shadows\" [\"on\"]\nLightSource \"distantlight\" 1\n"
        "Sphere 1 -1 1 360\nWorldEnd\n",
        true);
    EXPECT_EQ(r.messages, "");
    EXPECT_EQ(r.warnings, 0);
}

TEST(SceneBuilderUnused, DisplayParametersAreTyped) {
    const BuildResult r = Build(
        "Display \"x.exr\" \"openexr\" \"rgb\" \"exrpixeltype\" [\"half\"] \"bogus\" [1]\n"
        "WorldBegin\nWorldEnd\n");
    ASSERT_EQ(r.frames.size(), 1u);
    const ParamDict& params = r.frames[0].options.displays.at(0).params;
    EXPECT_EQ(params.GetString("exrpixeltype", ""), "half");
    EXPECT_FALSE(params.Has("bogus"));
    EXPECT_EQ(r.messages, "test.rib:1:57: warning: Display: unknown parameter \"bogus\" ignored\n");
}

// ---- Geometry -------------------------------------------------------------------------------

TEST(SceneBuilderGeometry, TeapotAddsItsPatchesAndOtherTypesWarn) {
    const BuildResult r =
        Build("WorldBegin\nGeometry \"teapot\"\nGeometry \"bunny\"\nGeometry \"cow\"\nWorldEnd\n");
    EXPECT_EQ(r.errors, 0);
    EXPECT_EQ(r.messages,
              "test.rib:3:1: warning: Geometry \"bunny\" is not supported (gonio has only "
              "\"teapot\"): skipped\n"
              "test.rib:4:1: warning: Geometry \"cow\" is not supported (gonio has only "
              "\"teapot\"): skipped\n");
    ASSERT_EQ(r.frames.size(), 1u);
    EXPECT_EQ(r.frames[0].shapes.size(), 32u);
}

TEST(SceneBuilderGeometry, TeapotOutsideTheWorldIsAnError) {
    const BuildResult r = Build("Geometry \"teapot\"\n");
    EXPECT_EQ(r.errors, 1);
    EXPECT_NE(r.messages.find("test.rib:1:1: error: Geometry is a primitive"), std::string::npos)
        << r.messages;
}

}  // namespace
}  // namespace gonio
