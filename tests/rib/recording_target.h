#pragma once
// A RiTarget for tests: records every call as one line of text (`Sphere 1 -1 1 360 {"Kd"=[0.5]}`)
// and its location, so a test can assert exactly what the parser produced.

#include <charconv>
#include <string>
#include <vector>

#include "renderer/rib/ri_target.h"

namespace gonio {

class RecordingTarget : public RiTarget {
  public:
    std::vector<std::string> calls;
    std::vector<FileLoc> locs;

    // All calls, one per line.
    std::string Text() const {
        std::string text;
        for (const std::string& call : calls) text += call + "\n";
        return text;
    }

    void FrameBegin(int frame, const FileLoc& loc) override { Record(loc, "FrameBegin", frame); }
    void FrameEnd(const FileLoc& loc) override { Record(loc, "FrameEnd"); }
    void WorldBegin(const FileLoc& loc) override { Record(loc, "WorldBegin"); }
    void WorldEnd(const FileLoc& loc) override { Record(loc, "WorldEnd"); }
    void AttributeBegin(const FileLoc& loc) override { Record(loc, "AttributeBegin"); }
    void AttributeEnd(const FileLoc& loc) override { Record(loc, "AttributeEnd"); }
    void TransformBegin(const FileLoc& loc) override { Record(loc, "TransformBegin"); }
    void TransformEnd(const FileLoc& loc) override { Record(loc, "TransformEnd"); }
    void ObjectBegin(const RtHandle& handle, const FileLoc& loc) override {
        Record(loc, "ObjectBegin", handle);
    }
    void ObjectEnd(const FileLoc& loc) override { Record(loc, "ObjectEnd"); }
    void ObjectInstance(const RtHandle& handle, const FileLoc& loc) override {
        Record(loc, "ObjectInstance", handle);
    }
    void MotionBegin(const std::vector<float>& times, const FileLoc& loc) override {
        Record(loc, "MotionBegin", times);
    }
    void MotionEnd(const FileLoc& loc) override { Record(loc, "MotionEnd"); }
    void SolidBegin(const std::string& operation, const FileLoc& loc) override {
        Record(loc, "SolidBegin", operation);
    }
    void SolidEnd(const FileLoc& loc) override { Record(loc, "SolidEnd"); }
    void Declare(const std::string& name, const std::string& declaration,
                 const FileLoc& loc) override {
        Record(loc, "Declare", name, declaration);
    }
    void Format(int xres, int yres, float pixelAspect, const FileLoc& loc) override {
        Record(loc, "Format", xres, yres, pixelAspect);
    }
    void FrameAspectRatio(float ratio, const FileLoc& loc) override {
        Record(loc, "FrameAspectRatio", ratio);
    }
    void ScreenWindow(float left, float right, float bottom, float top,
                      const FileLoc& loc) override {
        Record(loc, "ScreenWindow", left, right, bottom, top);
    }
    void CropWindow(float xmin, float xmax, float ymin, float ymax, const FileLoc& loc) override {
        Record(loc, "CropWindow", xmin, xmax, ymin, ymax);
    }
    void Projection(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Projection", name, params);
    }
    void Clipping(float nearPlane, float farPlane, const FileLoc& loc) override {
        Record(loc, "Clipping", nearPlane, farPlane);
    }
    void ClippingPlane(float x, float y, float z, float nx, float ny, float nz,
                       const FileLoc& loc) override {
        Record(loc, "ClippingPlane", x, y, z, nx, ny, nz);
    }
    void DepthOfField(float fstop, float focalLength, float focalDistance,
                      const FileLoc& loc) override {
        Record(loc, "DepthOfField", fstop, focalLength, focalDistance);
    }
    void Shutter(float open, float close, const FileLoc& loc) override {
        Record(loc, "Shutter", open, close);
    }
    void PixelVariance(float variance, const FileLoc& loc) override {
        Record(loc, "PixelVariance", variance);
    }
    void PixelSamples(float xsamples, float ysamples, const FileLoc& loc) override {
        Record(loc, "PixelSamples", xsamples, ysamples);
    }
    void PixelFilter(const std::string& name, float xwidth, float ywidth,
                     const FileLoc& loc) override {
        Record(loc, "PixelFilter", name, xwidth, ywidth);
    }
    void Exposure(float gain, float gamma, const FileLoc& loc) override {
        Record(loc, "Exposure", gain, gamma);
    }
    void Imager(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Imager", name, params);
    }
    void Quantize(const std::string& type, int one, int min, int max, float dither,
                  const FileLoc& loc) override {
        Record(loc, "Quantize", type, one, min, max, dither);
    }
    void Display(const std::string& name, const std::string& type, const std::string& mode,
                 const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Display", name, type, mode, params);
    }
    void Hider(const std::string& type, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Hider", type, params);
    }
    void ColorSamples(const std::vector<float>& nRGB, const std::vector<float>& RGBn,
                      const FileLoc& loc) override {
        Record(loc, "ColorSamples", nRGB, RGBn);
    }
    void RelativeDetail(float relativeDetail, const FileLoc& loc) override {
        Record(loc, "RelativeDetail", relativeDetail);
    }
    void Option(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Option", name, params);
    }
    void Color(const std::vector<float>& color, const FileLoc& loc) override {
        Record(loc, "Color", color);
    }
    void Opacity(const std::vector<float>& opacity, const FileLoc& loc) override {
        Record(loc, "Opacity", opacity);
    }
    void TextureCoordinates(const std::vector<float>& st8, const FileLoc& loc) override {
        Record(loc, "TextureCoordinates", st8);
    }
    void LightSource(const std::string& name, const RtHandle& handle, const ParamList& params,
                     const FileLoc& loc) override {
        Record(loc, "LightSource", name, handle, params);
    }
    void AreaLightSource(const std::string& name, const RtHandle& handle, const ParamList& params,
                         const FileLoc& loc) override {
        Record(loc, "AreaLightSource", name, handle, params);
    }
    void Illuminate(const RtHandle& light, bool on, const FileLoc& loc) override {
        Record(loc, "Illuminate", light, on);
    }
    void Surface(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Surface", name, params);
    }
    void Displacement(const std::string& name, const ParamList& params,
                      const FileLoc& loc) override {
        Record(loc, "Displacement", name, params);
    }
    void Atmosphere(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Atmosphere", name, params);
    }
    void Interior(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Interior", name, params);
    }
    void Exterior(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Exterior", name, params);
    }
    void ShadingRate(float size, const FileLoc& loc) override { Record(loc, "ShadingRate", size); }
    void ShadingInterpolation(const std::string& type, const FileLoc& loc) override {
        Record(loc, "ShadingInterpolation", type);
    }
    void Matte(bool on, const FileLoc& loc) override { Record(loc, "Matte", on); }
    void Bound(const std::vector<float>& bound6, const FileLoc& loc) override {
        Record(loc, "Bound", bound6);
    }
    void Detail(const std::vector<float>& bound6, const FileLoc& loc) override {
        Record(loc, "Detail", bound6);
    }
    void DetailRange(float minVisible, float lowerTransition, float upperTransition,
                     float maxVisible, const FileLoc& loc) override {
        Record(loc, "DetailRange", minVisible, lowerTransition, upperTransition, maxVisible);
    }
    void GeometricApproximation(const std::string& type, float value, const FileLoc& loc) override {
        Record(loc, "GeometricApproximation", type, value);
    }
    void Orientation(const std::string& orientation, const FileLoc& loc) override {
        Record(loc, "Orientation", orientation);
    }
    void ReverseOrientation(const FileLoc& loc) override { Record(loc, "ReverseOrientation"); }
    void Sides(int sides, const FileLoc& loc) override { Record(loc, "Sides", sides); }
    void Attribute(const std::string& name, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Attribute", name, params);
    }
    void Basis(const RtBasis& ubasis, int ustep, const RtBasis& vbasis, int vstep,
               const FileLoc& loc) override {
        Record(loc, "Basis", ubasis, ustep, vbasis, vstep);
    }
    void TrimCurve(const std::vector<int>& ncurves, const std::vector<int>& order,
                   const std::vector<float>& knot, const std::vector<float>& min,
                   const std::vector<float>& max, const std::vector<int>& n,
                   const std::vector<float>& u, const std::vector<float>& v,
                   const std::vector<float>& w, const FileLoc& loc) override {
        Record(loc, "TrimCurve", ncurves, order, knot, min, max, n, u, v, w);
    }
    void Identity(const FileLoc& loc) override { Record(loc, "Identity"); }
    void Transform(const RtMatrix& m, const FileLoc& loc) override { Record(loc, "Transform", m); }
    void ConcatTransform(const RtMatrix& m, const FileLoc& loc) override {
        Record(loc, "ConcatTransform", m);
    }
    void Perspective(float fov, const FileLoc& loc) override { Record(loc, "Perspective", fov); }
    void Translate(float dx, float dy, float dz, const FileLoc& loc) override {
        Record(loc, "Translate", dx, dy, dz);
    }
    void Rotate(float angle, float dx, float dy, float dz, const FileLoc& loc) override {
        Record(loc, "Rotate", angle, dx, dy, dz);
    }
    void Scale(float sx, float sy, float sz, const FileLoc& loc) override {
        Record(loc, "Scale", sx, sy, sz);
    }
    void Skew(float angle, float dx1, float dy1, float dz1, float dx2, float dy2, float dz2,
              const FileLoc& loc) override {
        Record(loc, "Skew", angle, dx1, dy1, dz1, dx2, dy2, dz2);
    }
    void CoordinateSystem(const std::string& space, const FileLoc& loc) override {
        Record(loc, "CoordinateSystem", space);
    }
    void ScopedCoordinateSystem(const std::string& space, const FileLoc& loc) override {
        Record(loc, "ScopedCoordinateSystem", space);
    }
    void CoordSysTransform(const std::string& space, const FileLoc& loc) override {
        Record(loc, "CoordSysTransform", space);
    }
    void Polygon(const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Polygon", params);
    }
    void GeneralPolygon(const std::vector<int>& nverts, const ParamList& params,
                        const FileLoc& loc) override {
        Record(loc, "GeneralPolygon", nverts, params);
    }
    void PointsPolygons(const std::vector<int>& nverts, const std::vector<int>& verts,
                        const ParamList& params, const FileLoc& loc) override {
        Record(loc, "PointsPolygons", nverts, verts, params);
    }
    void PointsGeneralPolygons(const std::vector<int>& nloops, const std::vector<int>& nverts,
                               const std::vector<int>& verts, const ParamList& params,
                               const FileLoc& loc) override {
        Record(loc, "PointsGeneralPolygons", nloops, nverts, verts, params);
    }
    void Patch(const std::string& type, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Patch", type, params);
    }
    void PatchMesh(const std::string& type, int nu, const std::string& uwrap, int nv,
                   const std::string& vwrap, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "PatchMesh", type, nu, uwrap, nv, vwrap, params);
    }
    void NuPatch(int nu, int uorder, const std::vector<float>& uknot, float umin, float umax,
                 int nv, int vorder, const std::vector<float>& vknot, float vmin, float vmax,
                 const ParamList& params, const FileLoc& loc) override {
        Record(loc, "NuPatch", nu, uorder, uknot, umin, umax, nv, vorder, vknot, vmin, vmax,
               params);
    }
    void SubdivisionMesh(const std::string& scheme, const std::vector<int>& nverts,
                         const std::vector<int>& verts, const std::vector<std::string>& tags,
                         const std::vector<int>& nargs, const std::vector<int>& intargs,
                         const std::vector<float>& floatargs, const ParamList& params,
                         const FileLoc& loc) override {
        Record(loc, "SubdivisionMesh", scheme, nverts, verts, tags, nargs, intargs, floatargs,
               params);
    }
    void Sphere(float radius, float zmin, float zmax, float thetamax, const ParamList& params,
                const FileLoc& loc) override {
        Record(loc, "Sphere", radius, zmin, zmax, thetamax, params);
    }
    void Cone(float height, float radius, float thetamax, const ParamList& params,
              const FileLoc& loc) override {
        Record(loc, "Cone", height, radius, thetamax, params);
    }
    void Cylinder(float radius, float zmin, float zmax, float thetamax, const ParamList& params,
                  const FileLoc& loc) override {
        Record(loc, "Cylinder", radius, zmin, zmax, thetamax, params);
    }
    void Hyperboloid(float x1, float y1, float z1, float x2, float y2, float z2, float thetamax,
                     const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Hyperboloid", x1, y1, z1, x2, y2, z2, thetamax, params);
    }
    void Paraboloid(float rmax, float zmin, float zmax, float thetamax, const ParamList& params,
                    const FileLoc& loc) override {
        Record(loc, "Paraboloid", rmax, zmin, zmax, thetamax, params);
    }
    void Disk(float height, float radius, float thetamax, const ParamList& params,
              const FileLoc& loc) override {
        Record(loc, "Disk", height, radius, thetamax, params);
    }
    void Torus(float majorRadius, float minorRadius, float phimin, float phimax, float thetamax,
               const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Torus", majorRadius, minorRadius, phimin, phimax, thetamax, params);
    }
    void Points(const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Points", params);
    }
    void Curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
                const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Curves", type, nvertices, wrap, params);
    }
    void Blobby(int nleaf, const std::vector<int>& code, const std::vector<float>& floats,
                const std::vector<std::string>& strings, const ParamList& params,
                const FileLoc& loc) override {
        Record(loc, "Blobby", nleaf, code, floats, strings, params);
    }
    // Records the request, then reads the procedural if `readProcedurals` (with the detail and
    // time-out below), so that tests see what it expands to.
    void Procedural(const std::string& name, const std::vector<std::string>& args,
                    const std::vector<float>& bound6, ProceduralReader& reader,
                    const FileLoc& loc) override {
        Record(loc, "Procedural", name, args, bound6);
        if (readProcedurals) reader.Read(proceduralDetail, proceduralTimeout);
    }
    bool readProcedurals = false;
    float proceduralDetail = 100;
    double proceduralTimeout = 10;
    void Geometry(const std::string& type, const ParamList& params, const FileLoc& loc) override {
        Record(loc, "Geometry", type, params);
    }
    void MakeTexture(const std::string& picture, const std::string& texture,
                     const std::string& swrap, const std::string& twrap, const std::string& filter,
                     float swidth, float twidth, const ParamList& params,
                     const FileLoc& loc) override {
        Record(loc, "MakeTexture", picture, texture, swrap, twrap, filter, swidth, twidth, params);
    }
    void MakeLatLongEnvironment(const std::string& picture, const std::string& texture,
                                const std::string& filter, float swidth, float twidth,
                                const ParamList& params, const FileLoc& loc) override {
        Record(loc, "MakeLatLongEnvironment", picture, texture, filter, swidth, twidth, params);
    }
    void MakeCubeFaceEnvironment(const std::vector<std::string>& faces, const std::string& texture,
                                 float fov, const std::string& filter, float swidth, float twidth,
                                 const ParamList& params, const FileLoc& loc) override {
        Record(loc, "MakeCubeFaceEnvironment", faces, texture, fov, filter, swidth, twidth, params);
    }
    void MakeShadow(const std::string& picture, const std::string& texture, const ParamList& params,
                    const FileLoc& loc) override {
        Record(loc, "MakeShadow", picture, texture, params);
    }
    void ErrorHandler(const std::string& handler, const FileLoc& loc) override {
        Record(loc, "ErrorHandler", handler);
    }

  private:
    template <typename... Values>
    void Record(const FileLoc& loc, const char* request, const Values&... values) {
        std::string line = request;
        ((line += ' ', Format(values, &line)), ...);
        calls.push_back(line);
        locs.push_back(loc);
    }

    static void Format(int value, std::string* out) { *out += std::to_string(value); }
    static void Format(bool value, std::string* out) { *out += value ? "on" : "off"; }
    template <typename Number>
    static void FormatNumber(Number value, std::string* out) {
        char text[32];
        *out += std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
    }
    static void Format(float value, std::string* out) { FormatNumber(value, out); }
    static void Format(double value, std::string* out) { FormatNumber(value, out); }
    static void Format(const std::string& text, std::string* out) { *out += '"' + text + '"'; }
    template <typename Value>
    static void Format(const std::vector<Value>& values, std::string* out) {
        *out += '[';
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (i) *out += ' ';
            Format(values[i], out);
        }
        *out += ']';
    }
    static void Format(const RtMatrix& m, std::string* out) {
        Format(std::vector<float>(m.begin(), m.end()), out);
    }
    static void Format(const RtHandle& handle, std::string* out) {
        *out += "handle:";
        if (handle.isString)
            Format(handle.text, out);
        else
            *out += handle.text;
    }
    static void Format(const RtBasis& basis, std::string* out) {
        if (basis.name.empty())
            Format(basis.matrix, out);
        else
            Format(basis.name, out);
    }
    static void Format(const ParamList& params, std::string* out) {
        *out += '{';
        for (std::size_t i = 0; i < params.size(); ++i) {
            if (i) *out += ' ';
            Format(params[i].token, out);
            *out += '=';
            if (params[i].isString)
                Format(params[i].strings, out);
            else
                Format(params[i].numbers, out);
        }
        *out += '}';
    }
};

}  // namespace gonio
