// Printing RiTarget calls back as RIB.

#include "renderer/rib/rib_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace gonio {

void RibWriter::Indent() {
    // Deeper blocks are not indented further: output grows linearly with the input, where
    // 10,000 nested blocks would otherwise print 200 MB of spaces.
    constexpr int kMaxIndentLevels = 16;
    for (int i = 0; i < std::min(depth_, kMaxIndentLevels); ++i) out_ << "    ";
}

template <typename... Values>
void RibWriter::Emit(const char* request, const Values&... values) {
    Indent();
    out_ << request;
    (Put(values), ...);
    out_ << '\n';
}

void RibWriter::EndBlock(const char* request) {
    if (depth_ > 0) --depth_;  // unbalanced input is the scene builder's error, not ours
    Emit(request);
}

void RibWriter::Put(int value) { out_ << ' ' << value; }

void RibWriter::Put(float value) {
    // An infinity can only come from a number beyond float range; 1e39 reads back as one.
    if (std::isinf(value)) {
        out_ << (value > 0 ? " 1e39" : " -1e39");
        return;
    }
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    out_ << ' ';
    out_.write(text, result.ptr - text);
}

void RibWriter::Put(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    out_ << ' ';
    out_.write(text, result.ptr - text);
}

void RibWriter::Put(const std::string& text) {
    out_ << " \"";
    for (const char c : text) {
        switch (c) {
            case '"':
                out_ << "\\\"";
                break;
            case '\\':
                out_ << "\\\\";
                break;
            case '\n':
                out_ << "\\n";
                break;
            case '\t':
                out_ << "\\t";
                break;
            case '\r':
                out_ << "\\r";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
                    char octal[8];
                    std::snprintf(octal, sizeof octal, "\\%03o", static_cast<unsigned char>(c));
                    out_ << octal;
                } else {
                    out_ << c;
                }
        }
    }
    out_ << '"';
}

void RibWriter::Put(const std::vector<float>& values) {
    out_ << " [";
    for (const float value : values) Put(value);
    out_ << " ]";
}

void RibWriter::Put(const std::vector<int>& values) {
    out_ << " [";
    for (const int value : values) Put(value);
    out_ << " ]";
}

void RibWriter::Put(const std::vector<std::string>& values) {
    out_ << " [";
    for (const std::string& value : values) Put(value);
    out_ << " ]";
}

void RibWriter::Put(const RtHandle& handle) {
    if (handle.isString)
        Put(handle.text);
    else
        out_ << ' ' << handle.text;
}

void RibWriter::Put(const RtBasis& basis) {
    if (!basis.name.empty())
        Put(basis.name);
    else
        Put(basis.matrix);
}

void RibWriter::Put(const RtMatrix& matrix) {
    out_ << " [";
    for (const float value : matrix) Put(value);
    out_ << " ]";
}

void RibWriter::Put(const ParamList& params) {
    for (const Param& param : params) {
        Put(param.token);
        out_ << " [";
        if (param.isString)
            for (const std::string& text : param.strings) Put(text);
        else
            for (const double number : param.numbers) Put(number);
        out_ << " ]";
    }
}

// No arguments in RIB means a pinhole camera: an infinite f-stop.
void RibWriter::DepthOfField(float fstop, float focalLength, float focalDistance, const FileLoc&) {
    if (std::isinf(fstop))
        Emit("DepthOfField");
    else
        Emit("DepthOfField", fstop, focalLength, focalDistance);
}

void RibWriter::MakeCubeFaceEnvironment(const std::vector<std::string>& faces,
                                        const std::string& texture, float fov,
                                        const std::string& filter, float swidth, float twidth,
                                        const ParamList& params, const FileLoc&) {
    Indent();
    out_ << "MakeCubeFaceEnvironment";
    for (const std::string& face : faces) Put(face);
    Put(texture);
    Put(fov);
    Put(filter);
    Put(swidth);
    Put(twidth);
    Put(params);
    out_ << '\n';
}

void RibWriter::SubdivisionMesh(const std::string& scheme, const std::vector<int>& nverts,
                                const std::vector<int>& verts, const std::vector<std::string>& tags,
                                const std::vector<int>& nargs, const std::vector<int>& intargs,
                                const std::vector<float>& floatargs, const ParamList& params,
                                const FileLoc&) {
    if (tags.empty() && nargs.empty() && intargs.empty() && floatargs.empty())
        Emit("SubdivisionMesh", scheme, nverts, verts, params);
    else
        Emit("SubdivisionMesh", scheme, nverts, verts, tags, nargs, intargs, floatargs, params);
}

void RibWriter::FrameBegin(int frame, const FileLoc&) {
    Emit("FrameBegin", frame);
    ++depth_;
}

void RibWriter::FrameEnd(const FileLoc&) { EndBlock("FrameEnd"); }

void RibWriter::WorldBegin(const FileLoc&) { BeginBlock("WorldBegin"); }

void RibWriter::WorldEnd(const FileLoc&) { EndBlock("WorldEnd"); }

void RibWriter::AttributeBegin(const FileLoc&) { BeginBlock("AttributeBegin"); }

void RibWriter::AttributeEnd(const FileLoc&) { EndBlock("AttributeEnd"); }

void RibWriter::TransformBegin(const FileLoc&) { BeginBlock("TransformBegin"); }

void RibWriter::TransformEnd(const FileLoc&) { EndBlock("TransformEnd"); }

void RibWriter::ObjectBegin(const RtHandle& handle, const FileLoc&) {
    Emit("ObjectBegin", handle);
    ++depth_;
}

void RibWriter::ObjectEnd(const FileLoc&) { EndBlock("ObjectEnd"); }

void RibWriter::ObjectInstance(const RtHandle& handle, const FileLoc&) {
    Emit("ObjectInstance", handle);
}

void RibWriter::MotionBegin(const std::vector<float>& times, const FileLoc&) {
    Emit("MotionBegin", times);
    ++depth_;
}

void RibWriter::MotionEnd(const FileLoc&) { EndBlock("MotionEnd"); }

void RibWriter::SolidBegin(const std::string& operation, const FileLoc&) {
    Emit("SolidBegin", operation);
    ++depth_;
}

void RibWriter::SolidEnd(const FileLoc&) { EndBlock("SolidEnd"); }

void RibWriter::Declare(const std::string& name, const std::string& declaration, const FileLoc&) {
    Emit("Declare", name, declaration);
}

void RibWriter::Format(int xres, int yres, float pixelAspect, const FileLoc&) {
    Emit("Format", xres, yres, pixelAspect);
}

void RibWriter::FrameAspectRatio(float ratio, const FileLoc&) { Emit("FrameAspectRatio", ratio); }

void RibWriter::ScreenWindow(float left, float right, float bottom, float top, const FileLoc&) {
    Emit("ScreenWindow", left, right, bottom, top);
}

void RibWriter::CropWindow(float xmin, float xmax, float ymin, float ymax, const FileLoc&) {
    Emit("CropWindow", xmin, xmax, ymin, ymax);
}

void RibWriter::Projection(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Projection", name, params);
}

void RibWriter::Clipping(float nearPlane, float farPlane, const FileLoc&) {
    Emit("Clipping", nearPlane, farPlane);
}

void RibWriter::ClippingPlane(float x, float y, float z, float nx, float ny, float nz,
                              const FileLoc&) {
    Emit("ClippingPlane", x, y, z, nx, ny, nz);
}

void RibWriter::Shutter(float open, float close, const FileLoc&) { Emit("Shutter", open, close); }

void RibWriter::PixelVariance(float variance, const FileLoc&) { Emit("PixelVariance", variance); }

void RibWriter::PixelSamples(float xsamples, float ysamples, const FileLoc&) {
    Emit("PixelSamples", xsamples, ysamples);
}

void RibWriter::PixelFilter(const std::string& name, float xwidth, float ywidth, const FileLoc&) {
    Emit("PixelFilter", name, xwidth, ywidth);
}

void RibWriter::Exposure(float gain, float gamma, const FileLoc&) { Emit("Exposure", gain, gamma); }

void RibWriter::Imager(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Imager", name, params);
}

void RibWriter::Quantize(const std::string& type, int one, int min, int max, float dither,
                         const FileLoc&) {
    Emit("Quantize", type, one, min, max, dither);
}

void RibWriter::Display(const std::string& name, const std::string& type, const std::string& mode,
                        const ParamList& params, const FileLoc&) {
    Emit("Display", name, type, mode, params);
}

void RibWriter::Hider(const std::string& type, const ParamList& params, const FileLoc&) {
    Emit("Hider", type, params);
}

void RibWriter::ColorSamples(const std::vector<float>& nRGB, const std::vector<float>& RGBn,
                             const FileLoc&) {
    Emit("ColorSamples", nRGB, RGBn);
}

void RibWriter::RelativeDetail(float relativeDetail, const FileLoc&) {
    Emit("RelativeDetail", relativeDetail);
}

void RibWriter::Option(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Option", name, params);
}

void RibWriter::Color(const std::vector<float>& color, const FileLoc&) { Emit("Color", color); }

void RibWriter::Opacity(const std::vector<float>& opacity, const FileLoc&) {
    Emit("Opacity", opacity);
}

void RibWriter::TextureCoordinates(const std::vector<float>& st8, const FileLoc&) {
    Emit("TextureCoordinates", st8);
}

void RibWriter::LightSource(const std::string& name, const RtHandle& handle,
                            const ParamList& params, const FileLoc&) {
    Emit("LightSource", name, handle, params);
}

void RibWriter::AreaLightSource(const std::string& name, const RtHandle& handle,
                                const ParamList& params, const FileLoc&) {
    Emit("AreaLightSource", name, handle, params);
}

void RibWriter::Illuminate(const RtHandle& light, bool on, const FileLoc&) {
    Emit("Illuminate", light, on);
}

void RibWriter::Surface(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Surface", name, params);
}

void RibWriter::Displacement(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Displacement", name, params);
}

void RibWriter::Atmosphere(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Atmosphere", name, params);
}

void RibWriter::Interior(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Interior", name, params);
}

void RibWriter::Exterior(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Exterior", name, params);
}

void RibWriter::ShadingRate(float size, const FileLoc&) { Emit("ShadingRate", size); }

void RibWriter::ShadingInterpolation(const std::string& type, const FileLoc&) {
    Emit("ShadingInterpolation", type);
}

void RibWriter::Matte(bool on, const FileLoc&) { Emit("Matte", on); }

void RibWriter::Bound(const std::vector<float>& bound6, const FileLoc&) { Emit("Bound", bound6); }

void RibWriter::Detail(const std::vector<float>& bound6, const FileLoc&) { Emit("Detail", bound6); }

void RibWriter::DetailRange(float minVisible, float lowerTransition, float upperTransition,
                            float maxVisible, const FileLoc&) {
    Emit("DetailRange", minVisible, lowerTransition, upperTransition, maxVisible);
}

void RibWriter::GeometricApproximation(const std::string& type, float value, const FileLoc&) {
    Emit("GeometricApproximation", type, value);
}

void RibWriter::Orientation(const std::string& orientation, const FileLoc&) {
    Emit("Orientation", orientation);
}

void RibWriter::ReverseOrientation(const FileLoc&) { Emit("ReverseOrientation"); }

void RibWriter::Sides(int sides, const FileLoc&) { Emit("Sides", sides); }

void RibWriter::Attribute(const std::string& name, const ParamList& params, const FileLoc&) {
    Emit("Attribute", name, params);
}

void RibWriter::Basis(const RtBasis& ubasis, int ustep, const RtBasis& vbasis, int vstep,
                      const FileLoc&) {
    Emit("Basis", ubasis, ustep, vbasis, vstep);
}

void RibWriter::TrimCurve(const std::vector<int>& ncurves, const std::vector<int>& order,
                          const std::vector<float>& knot, const std::vector<float>& min,
                          const std::vector<float>& max, const std::vector<int>& n,
                          const std::vector<float>& u, const std::vector<float>& v,
                          const std::vector<float>& w, const FileLoc&) {
    Emit("TrimCurve", ncurves, order, knot, min, max, n, u, v, w);
}

void RibWriter::Identity(const FileLoc&) { Emit("Identity"); }

void RibWriter::Transform(const RtMatrix& m, const FileLoc&) { Emit("Transform", m); }

void RibWriter::ConcatTransform(const RtMatrix& m, const FileLoc&) { Emit("ConcatTransform", m); }

void RibWriter::Perspective(float fov, const FileLoc&) { Emit("Perspective", fov); }

void RibWriter::Translate(float dx, float dy, float dz, const FileLoc&) {
    Emit("Translate", dx, dy, dz);
}

void RibWriter::Rotate(float angle, float dx, float dy, float dz, const FileLoc&) {
    Emit("Rotate", angle, dx, dy, dz);
}

void RibWriter::Scale(float sx, float sy, float sz, const FileLoc&) { Emit("Scale", sx, sy, sz); }

void RibWriter::Skew(float angle, float dx1, float dy1, float dz1, float dx2, float dy2, float dz2,
                     const FileLoc&) {
    Emit("Skew", angle, dx1, dy1, dz1, dx2, dy2, dz2);
}

void RibWriter::CoordinateSystem(const std::string& space, const FileLoc&) {
    Emit("CoordinateSystem", space);
}

void RibWriter::ScopedCoordinateSystem(const std::string& space, const FileLoc&) {
    Emit("ScopedCoordinateSystem", space);
}

void RibWriter::CoordSysTransform(const std::string& space, const FileLoc&) {
    Emit("CoordSysTransform", space);
}

void RibWriter::Polygon(const ParamList& params, const FileLoc&) { Emit("Polygon", params); }

void RibWriter::GeneralPolygon(const std::vector<int>& nverts, const ParamList& params,
                               const FileLoc&) {
    Emit("GeneralPolygon", nverts, params);
}

void RibWriter::PointsPolygons(const std::vector<int>& nverts, const std::vector<int>& verts,
                               const ParamList& params, const FileLoc&) {
    Emit("PointsPolygons", nverts, verts, params);
}

void RibWriter::PointsGeneralPolygons(const std::vector<int>& nloops,
                                      const std::vector<int>& nverts, const std::vector<int>& verts,
                                      const ParamList& params, const FileLoc&) {
    Emit("PointsGeneralPolygons", nloops, nverts, verts, params);
}

void RibWriter::Patch(const std::string& type, const ParamList& params, const FileLoc&) {
    Emit("Patch", type, params);
}

void RibWriter::PatchMesh(const std::string& type, int nu, const std::string& uwrap, int nv,
                          const std::string& vwrap, const ParamList& params, const FileLoc&) {
    Emit("PatchMesh", type, nu, uwrap, nv, vwrap, params);
}

void RibWriter::NuPatch(int nu, int uorder, const std::vector<float>& uknot, float umin, float umax,
                        int nv, int vorder, const std::vector<float>& vknot, float vmin, float vmax,
                        const ParamList& params, const FileLoc&) {
    Emit("NuPatch", nu, uorder, uknot, umin, umax, nv, vorder, vknot, vmin, vmax, params);
}

void RibWriter::Sphere(float radius, float zmin, float zmax, float thetamax,
                       const ParamList& params, const FileLoc&) {
    Emit("Sphere", radius, zmin, zmax, thetamax, params);
}

void RibWriter::Cone(float height, float radius, float thetamax, const ParamList& params,
                     const FileLoc&) {
    Emit("Cone", height, radius, thetamax, params);
}

void RibWriter::Cylinder(float radius, float zmin, float zmax, float thetamax,
                         const ParamList& params, const FileLoc&) {
    Emit("Cylinder", radius, zmin, zmax, thetamax, params);
}

void RibWriter::Hyperboloid(float x1, float y1, float z1, float x2, float y2, float z2,
                            float thetamax, const ParamList& params, const FileLoc&) {
    Emit("Hyperboloid", x1, y1, z1, x2, y2, z2, thetamax, params);
}

void RibWriter::Paraboloid(float rmax, float zmin, float zmax, float thetamax,
                           const ParamList& params, const FileLoc&) {
    Emit("Paraboloid", rmax, zmin, zmax, thetamax, params);
}

void RibWriter::Disk(float height, float radius, float thetamax, const ParamList& params,
                     const FileLoc&) {
    Emit("Disk", height, radius, thetamax, params);
}

void RibWriter::Torus(float majorRadius, float minorRadius, float phimin, float phimax,
                      float thetamax, const ParamList& params, const FileLoc&) {
    Emit("Torus", majorRadius, minorRadius, phimin, phimax, thetamax, params);
}

void RibWriter::Points(const ParamList& params, const FileLoc&) { Emit("Points", params); }

void RibWriter::Curves(const std::string& type, const std::vector<int>& nvertices,
                       const std::string& wrap, const ParamList& params, const FileLoc&) {
    Emit("Curves", type, nvertices, wrap, params);
}

void RibWriter::Blobby(int nleaf, const std::vector<int>& code, const std::vector<float>& floats,
                       const std::vector<std::string>& strings, const ParamList& params,
                       const FileLoc&) {
    Emit("Blobby", nleaf, code, floats, strings, params);
}

void RibWriter::Procedural(const std::string& name, const std::vector<std::string>& args,
                           const std::vector<float>& bound6, ProceduralReader&, const FileLoc&) {
    Emit("Procedural", name, args, bound6);
}

void RibWriter::Geometry(const std::string& type, const ParamList& params, const FileLoc&) {
    Emit("Geometry", type, params);
}

void RibWriter::MakeTexture(const std::string& picture, const std::string& texture,
                            const std::string& swrap, const std::string& twrap,
                            const std::string& filter, float swidth, float twidth,
                            const ParamList& params, const FileLoc&) {
    Emit("MakeTexture", picture, texture, swrap, twrap, filter, swidth, twidth, params);
}

void RibWriter::MakeLatLongEnvironment(const std::string& picture, const std::string& texture,
                                       const std::string& filter, float swidth, float twidth,
                                       const ParamList& params, const FileLoc&) {
    Emit("MakeLatLongEnvironment", picture, texture, filter, swidth, twidth, params);
}

void RibWriter::MakeShadow(const std::string& picture, const std::string& texture,
                           const ParamList& params, const FileLoc&) {
    Emit("MakeShadow", picture, texture, params);
}

void RibWriter::ErrorHandler(const std::string& handler, const FileLoc&) {
    Emit("ErrorHandler", handler);
}
}  // namespace gonio
