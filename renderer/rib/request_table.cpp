// The request table: every RIB request the parser knows, with its positional-argument signature
// (see request_table.h) and the RiTarget call it makes. Adding a request touches one row.

#include "renderer/rib/request_table.h"

#include <cmath>
#include <unordered_map>

namespace gonio {
namespace {

using A = const RequestArgs&;
using T = RiTarget&;
using H = ParserHooks&;

void Ignore(A a, T, H h) { h.Ignore(a.Name(), a.Loc()); }
void Unsupported(A a, T, H h) { h.Unsupported(a.Name(), a.Loc()); }
void Nothing(A, T, H) {}

// A 16-float signature, for Transform and ConcatTransform.
constexpr const char* kMatrix = "ffffffffffffffff";

const std::vector<RequestRule> kRules = {
    // Parser-level requests (RISpec App. C).
    {"version", "f", false, Nothing},
    {"ArchiveRecord", "*", false, Nothing},
    {"ReadArchive", "s", false, [](A a, T, H h) { h.ReadArchive(a.S(0), a.Loc()); }},
    {"Declare", "ss", false, [](A a, T t, H) { t.Declare(a.S(0), a.S(1), a.Loc()); }},

    // Block structure (RISpec §4).
    {"FrameBegin", "i", false, [](A a, T t, H) { t.FrameBegin(a.I(0), a.Loc()); }},
    {"FrameEnd", "", false, [](A a, T t, H) { t.FrameEnd(a.Loc()); }},
    {"WorldBegin", "", false, [](A a, T t, H) { t.WorldBegin(a.Loc()); }},
    {"WorldEnd", "", false, [](A a, T t, H) { t.WorldEnd(a.Loc()); }},
    {"AttributeBegin", "", false, [](A a, T t, H) { t.AttributeBegin(a.Loc()); }},
    {"AttributeEnd", "", false, [](A a, T t, H) { t.AttributeEnd(a.Loc()); }},
    {"TransformBegin", "", false, [](A a, T t, H) { t.TransformBegin(a.Loc()); }},
    {"TransformEnd", "", false, [](A a, T t, H) { t.TransformEnd(a.Loc()); }},
    {"ObjectBegin", "h", false, [](A a, T t, H) { t.ObjectBegin(a.H(0), a.Loc()); }},
    {"ObjectEnd", "", false, [](A a, T t, H) { t.ObjectEnd(a.Loc()); }},
    {"ObjectInstance", "h", false, [](A a, T t, H) { t.ObjectInstance(a.H(0), a.Loc()); }},
    {"MotionBegin", "F", false, [](A a, T t, H) { t.MotionBegin(a.FA(0), a.Loc()); }},
    {"MotionEnd", "", false, [](A a, T t, H) { t.MotionEnd(a.Loc()); }},
    {"SolidBegin", "s", false, [](A a, T t, H) { t.SolidBegin(a.S(0), a.Loc()); }},
    {"SolidEnd", "", false, [](A a, T t, H) { t.SolidEnd(a.Loc()); }},

    // Options (RISpec §4.1).
    {"Format", "iif", false, [](A a, T t, H) { t.Format(a.I(0), a.I(1), a.F(2), a.Loc()); }},
    {"FrameAspectRatio", "f", false, [](A a, T t, H) { t.FrameAspectRatio(a.F(0), a.Loc()); }},
    {"ScreenWindow", "ffff", false,
     [](A a, T t, H) { t.ScreenWindow(a.F(0), a.F(1), a.F(2), a.F(3), a.Loc()); }},
    {"CropWindow", "ffff", false,
     [](A a, T t, H) { t.CropWindow(a.F(0), a.F(1), a.F(2), a.F(3), a.Loc()); }},
    {"Projection", "s", true, [](A a, T t, H) { t.Projection(a.S(0), a.Params(), a.Loc()); }},
    {"Clipping", "ff", false, [](A a, T t, H) { t.Clipping(a.F(0), a.F(1), a.Loc()); }},
    {"ClippingPlane", "ffffff", false,
     [](A a, T t, H) {
         t.ClippingPlane(a.F(0), a.F(1), a.F(2), a.F(3), a.F(4), a.F(5), a.Loc());
     }},
    // No arguments: a pinhole camera (RISpec §4.1.1), an infinite f-stop.
    {"DepthOfField", "|fff", false,
     [](A a, T t, H) {
         if (a.Count() == 0)
             t.DepthOfField(INFINITY, 0.0f, 0.0f, a.Loc());
         else
             t.DepthOfField(a.F(0), a.F(1), a.F(2), a.Loc());
     }},
    {"Shutter", "ff", false, [](A a, T t, H) { t.Shutter(a.F(0), a.F(1), a.Loc()); }},
    {"PixelVariance", "f", false, [](A a, T t, H) { t.PixelVariance(a.F(0), a.Loc()); }},
    {"PixelSamples", "ff", false, [](A a, T t, H) { t.PixelSamples(a.F(0), a.F(1), a.Loc()); }},
    {"PixelFilter", "sff", false,
     [](A a, T t, H) { t.PixelFilter(a.S(0), a.F(1), a.F(2), a.Loc()); }},
    {"Exposure", "ff", false, [](A a, T t, H) { t.Exposure(a.F(0), a.F(1), a.Loc()); }},
    {"Imager", "s", true, [](A a, T t, H) { t.Imager(a.S(0), a.Params(), a.Loc()); }},
    {"Quantize", "siiif", false,
     [](A a, T t, H) { t.Quantize(a.S(0), a.I(1), a.I(2), a.I(3), a.F(4), a.Loc()); }},
    {"Display", "sss", true,
     [](A a, T t, H) { t.Display(a.S(0), a.S(1), a.S(2), a.Params(), a.Loc()); }},
    {"Hider", "s", true, [](A a, T t, H) { t.Hider(a.S(0), a.Params(), a.Loc()); }},
    // The RIB binding has no n (RISpec App. C); an explicit leading n is accepted too.
    {"ColorSamples", "iFF|FF", false,
     [](A a, T t, H h) {
         const int first = a.Alternative() == 0 ? 1 : 0;
         const std::vector<float> nRGB = a.FA(first), RGBn = a.FA(first + 1);
         h.ColorSamplesSeen(static_cast<int>(nRGB.size() / 3));
         t.ColorSamples(nRGB, RGBn, a.Loc());
     }},
    {"RelativeDetail", "f", false, [](A a, T t, H) { t.RelativeDetail(a.F(0), a.Loc()); }},
    {"Option", "s", true,
     [](A a, T t, H h) {
         h.OptionSeen(a.S(0), a.Params());
         t.Option(a.S(0), a.Params(), a.Loc());
     }},

    // Attributes (RISpec §4.2).
    {"Color", "c", false, [](A a, T t, H) { t.Color(a.AllFloats(), a.Loc()); }},
    {"Opacity", "c", false, [](A a, T t, H) { t.Opacity(a.AllFloats(), a.Loc()); }},
    {"TextureCoordinates", "ffffffff", false,
     [](A a, T t, H) { t.TextureCoordinates(a.AllFloats(), a.Loc()); }},
    {"LightSource", "sh", true,
     [](A a, T t, H) { t.LightSource(a.S(0), a.H(1), a.Params(), a.Loc()); }},
    {"AreaLightSource", "sh", true,
     [](A a, T t, H) { t.AreaLightSource(a.S(0), a.H(1), a.Params(), a.Loc()); }},
    {"Illuminate", "hi", false,
     [](A a, T t, H) { t.Illuminate(a.H(0), a.I(1) != 0, a.Loc()); }},
    {"Surface", "s", true, [](A a, T t, H) { t.Surface(a.S(0), a.Params(), a.Loc()); }},
    {"Displacement", "s", true,
     [](A a, T t, H) { t.Displacement(a.S(0), a.Params(), a.Loc()); }},
    {"Atmosphere", "s", true, [](A a, T t, H) { t.Atmosphere(a.S(0), a.Params(), a.Loc()); }},
    {"Interior", "s", true, [](A a, T t, H) { t.Interior(a.S(0), a.Params(), a.Loc()); }},
    {"Exterior", "s", true, [](A a, T t, H) { t.Exterior(a.S(0), a.Params(), a.Loc()); }},
    {"ShadingRate", "f", false, [](A a, T t, H) { t.ShadingRate(a.F(0), a.Loc()); }},
    {"ShadingInterpolation", "s", false,
     [](A a, T t, H) { t.ShadingInterpolation(a.S(0), a.Loc()); }},
    {"Matte", "i", false, [](A a, T t, H) { t.Matte(a.I(0) != 0, a.Loc()); }},
    {"Bound", "ffffff", false, [](A a, T t, H) { t.Bound(a.AllFloats(), a.Loc()); }},
    {"Detail", "ffffff", false, [](A a, T t, H) { t.Detail(a.AllFloats(), a.Loc()); }},
    {"DetailRange", "ffff", false,
     [](A a, T t, H) { t.DetailRange(a.F(0), a.F(1), a.F(2), a.F(3), a.Loc()); }},
    {"GeometricApproximation", "sf", false,
     [](A a, T t, H) { t.GeometricApproximation(a.S(0), a.F(1), a.Loc()); }},
    {"Orientation", "s", false, [](A a, T t, H) { t.Orientation(a.S(0), a.Loc()); }},
    {"ReverseOrientation", "", false, [](A a, T t, H) { t.ReverseOrientation(a.Loc()); }},
    {"Sides", "i", false, [](A a, T t, H) { t.Sides(a.I(0), a.Loc()); }},
    {"Attribute", "s", true, [](A a, T t, H) { t.Attribute(a.S(0), a.Params(), a.Loc()); }},
    {"Basis", "BiBi", false,
     [](A a, T t, H) { t.Basis(a.B(0), a.I(1), a.B(2), a.I(3), a.Loc()); }},
    {"TrimCurve", "IIFFFIFFF", false,
     [](A a, T t, H) {
         t.TrimCurve(a.IA(0), a.IA(1), a.FA(2), a.FA(3), a.FA(4), a.IA(5), a.FA(6), a.FA(7),
                     a.FA(8), a.Loc());
     }},

    // Transformations (RISpec §4.3).
    {"Identity", "", false, [](A a, T t, H) { t.Identity(a.Loc()); }},
    {"Transform", kMatrix, false, [](A a, T t, H) { t.Transform(a.Matrix(), a.Loc()); }},
    {"ConcatTransform", kMatrix, false,
     [](A a, T t, H) { t.ConcatTransform(a.Matrix(), a.Loc()); }},
    {"Perspective", "f", false, [](A a, T t, H) { t.Perspective(a.F(0), a.Loc()); }},
    {"Translate", "fff", false,
     [](A a, T t, H) { t.Translate(a.F(0), a.F(1), a.F(2), a.Loc()); }},
    {"Rotate", "ffff", false,
     [](A a, T t, H) { t.Rotate(a.F(0), a.F(1), a.F(2), a.F(3), a.Loc()); }},
    {"Scale", "fff", false, [](A a, T t, H) { t.Scale(a.F(0), a.F(1), a.F(2), a.Loc()); }},
    {"Skew", "fffffff", false,
     [](A a, T t, H) {
         t.Skew(a.F(0), a.F(1), a.F(2), a.F(3), a.F(4), a.F(5), a.F(6), a.Loc());
     }},
    {"CoordinateSystem", "s", false, [](A a, T t, H) { t.CoordinateSystem(a.S(0), a.Loc()); }},
    {"ScopedCoordinateSystem", "s", false,
     [](A a, T t, H) { t.ScopedCoordinateSystem(a.S(0), a.Loc()); }},
    {"CoordSysTransform", "s", false,
     [](A a, T t, H) { t.CoordSysTransform(a.S(0), a.Loc()); }},

    // Geometric primitives (RISpec §5).
    {"Polygon", "", true, [](A a, T t, H) { t.Polygon(a.Params(), a.Loc()); }},
    {"GeneralPolygon", "I", true,
     [](A a, T t, H) { t.GeneralPolygon(a.IA(0), a.Params(), a.Loc()); }},
    {"PointsPolygons", "II", true,
     [](A a, T t, H) { t.PointsPolygons(a.IA(0), a.IA(1), a.Params(), a.Loc()); }},
    {"PointsGeneralPolygons", "III", true,
     [](A a, T t, H) {
         t.PointsGeneralPolygons(a.IA(0), a.IA(1), a.IA(2), a.Params(), a.Loc());
     }},
    {"Patch", "s", true, [](A a, T t, H) { t.Patch(a.S(0), a.Params(), a.Loc()); }},
    {"PatchMesh", "sisis", true,
     [](A a, T t, H) {
         t.PatchMesh(a.S(0), a.I(1), a.S(2), a.I(3), a.S(4), a.Params(), a.Loc());
     }},
    {"NuPatch", "iiFffiiFff", true,
     [](A a, T t, H) {
         t.NuPatch(a.I(0), a.I(1), a.FA(2), a.F(3), a.F(4), a.I(5), a.I(6), a.FA(7), a.F(8),
                   a.F(9), a.Params(), a.Loc());
     }},
    // The tag arrays are optional in practice (exporters leave them out for plain meshes).
    {"SubdivisionMesh", "sII|sIISIIF", true,
     [](A a, T t, H) {
         if (a.Alternative() == 0)
             t.SubdivisionMesh(a.S(0), a.IA(1), a.IA(2), {}, {}, {}, {}, a.Params(), a.Loc());
         else
             t.SubdivisionMesh(a.S(0), a.IA(1), a.IA(2), a.SA(3), a.IA(4), a.IA(5), a.FA(6),
                               a.Params(), a.Loc());
     }},
    {"Sphere", "ffff", true,
     [](A a, T t, H) { t.Sphere(a.F(0), a.F(1), a.F(2), a.F(3), a.Params(), a.Loc()); }},
    {"Cone", "fff", true,
     [](A a, T t, H) { t.Cone(a.F(0), a.F(1), a.F(2), a.Params(), a.Loc()); }},
    {"Cylinder", "ffff", true,
     [](A a, T t, H) { t.Cylinder(a.F(0), a.F(1), a.F(2), a.F(3), a.Params(), a.Loc()); }},
    {"Hyperboloid", "fffffff", true,
     [](A a, T t, H) {
         t.Hyperboloid(a.F(0), a.F(1), a.F(2), a.F(3), a.F(4), a.F(5), a.F(6), a.Params(),
                       a.Loc());
     }},
    {"Paraboloid", "ffff", true,
     [](A a, T t, H) { t.Paraboloid(a.F(0), a.F(1), a.F(2), a.F(3), a.Params(), a.Loc()); }},
    {"Disk", "fff", true,
     [](A a, T t, H) { t.Disk(a.F(0), a.F(1), a.F(2), a.Params(), a.Loc()); }},
    {"Torus", "fffff", true,
     [](A a, T t, H) {
         t.Torus(a.F(0), a.F(1), a.F(2), a.F(3), a.F(4), a.Params(), a.Loc());
     }},
    {"Points", "", true, [](A a, T t, H) { t.Points(a.Params(), a.Loc()); }},
    {"Curves", "sIs", true,
     [](A a, T t, H) { t.Curves(a.S(0), a.IA(1), a.S(2), a.Params(), a.Loc()); }},
    {"Blobby", "iIFS", true,
     [](A a, T t, H) { t.Blobby(a.I(0), a.IA(1), a.FA(2), a.SA(3), a.Params(), a.Loc()); }},
    {"Procedural", "sSF", false,
     [](A a, T, H h) { h.Procedural(a.S(0), a.SA(1), a.FA(2), a.Loc()); }},
    {"Geometry", "s", true, [](A a, T t, H) { t.Geometry(a.S(0), a.Params(), a.Loc()); }},

    // External resources (RISpec §7).
    {"MakeTexture", "sssssff", true,
     [](A a, T t, H) {
         t.MakeTexture(a.S(0), a.S(1), a.S(2), a.S(3), a.S(4), a.F(5), a.F(6), a.Params(),
                       a.Loc());
     }},
    {"MakeLatLongEnvironment", "sssff", true,
     [](A a, T t, H) {
         t.MakeLatLongEnvironment(a.S(0), a.S(1), a.S(2), a.F(3), a.F(4), a.Params(), a.Loc());
     }},
    {"MakeCubeFaceEnvironment", "sssssssfsff", true,
     [](A a, T t, H) {
         t.MakeCubeFaceEnvironment({a.S(0), a.S(1), a.S(2), a.S(3), a.S(4), a.S(5)}, a.S(6),
                                   a.F(7), a.S(8), a.F(9), a.F(10), a.Params(), a.Loc());
     }},
    {"MakeShadow", "ss", true,
     [](A a, T t, H) { t.MakeShadow(a.S(0), a.S(1), a.Params(), a.Loc()); }},
    {"ErrorHandler", "s", false, [](A a, T t, H) { t.ErrorHandler(a.S(0), a.Loc()); }},

    // Extensions with no meaning for this renderer (rib_checklist.md §9b): warned once, ignored.
    {"Deformation", "*", false, Ignore},
    {"MakeBump", "*", false, Ignore},
    {"MakeOcclusion", "*", false, Ignore},
    {"MakeBrickMap", "*", false, Ignore},
    {"DisplayChannel", "*", false, Ignore},
    {"GeometricRepresentation", "*", false, Ignore},
    {"Camera", "*", false, Ignore},
    {"Shader", "*", false, Ignore},
    {"ShaderLayer", "*", false, Ignore},
    {"ConnectShaderLayers", "*", false, Ignore},
    {"System", "*", false, Ignore},
    {"Resource", "*", false, Ignore},
    {"ResourceBegin", "*", false, Ignore},
    {"ResourceEnd", "*", false, Ignore},
    {"Bxdf", "*", false, Ignore},
    {"Pattern", "*", false, Ignore},
    {"Integrator", "*", false, Ignore},
    {"Light", "*", false, Ignore},
    // Ignoring these would change what the file means, so they are errors.
    {"ArchiveBegin", "*", false, Unsupported},
    {"ArchiveEnd", "*", false, Unsupported},
    {"IfBegin", "*", false, Unsupported},
    {"ElseIf", "*", false, Unsupported},
    {"Else", "*", false, Unsupported},
    {"IfEnd", "*", false, Unsupported},
};

}  // namespace

const std::vector<RequestRule>& AllRequests() { return kRules; }

const RequestRule* FindRequest(std::string_view name) {
    static const std::unordered_map<std::string_view, const RequestRule*> byName = [] {
        std::unordered_map<std::string_view, const RequestRule*> map;
        for (const RequestRule& rule : kRules) map.emplace(rule.name, &rule);
        return map;
    }();
    const auto found = byName.find(name);
    return found == byName.end() ? nullptr : found->second;
}

}  // namespace gonio
