#pragma once
// A RiTarget that prints every request back as RIB text (`gonio catrib`). Blocks are indented,
// numbers are written in their shortest exact form, so parsing the output again gives the same
// calls as parsing the input.

#include <ostream>
#include <string>
#include <vector>

#include "renderer/rib/ri_target.h"

namespace gonio {

class RibWriter : public RiTarget {
  public:
    explicit RibWriter(std::ostream& out) : out_(out) {}

    void FrameBegin(int frame, const FileLoc& loc) override;
    void FrameEnd(const FileLoc& loc) override;
    void WorldBegin(const FileLoc& loc) override;
    void WorldEnd(const FileLoc& loc) override;
    void AttributeBegin(const FileLoc& loc) override;
    void AttributeEnd(const FileLoc& loc) override;
    void TransformBegin(const FileLoc& loc) override;
    void TransformEnd(const FileLoc& loc) override;
    void ObjectBegin(const RtHandle& handle, const FileLoc& loc) override;
    void ObjectEnd(const FileLoc& loc) override;
    void ObjectInstance(const RtHandle& handle, const FileLoc& loc) override;
    void MotionBegin(const std::vector<float>& times, const FileLoc& loc) override;
    void MotionEnd(const FileLoc& loc) override;
    void SolidBegin(const std::string& operation, const FileLoc& loc) override;
    void SolidEnd(const FileLoc& loc) override;
    void Declare(const std::string& name, const std::string& declaration,
                 const FileLoc& loc) override;
    void Format(int xres, int yres, float pixelAspect, const FileLoc& loc) override;
    void FrameAspectRatio(float ratio, const FileLoc& loc) override;
    void ScreenWindow(float left, float right, float bottom, float top,
                      const FileLoc& loc) override;
    void CropWindow(float xmin, float xmax, float ymin, float ymax, const FileLoc& loc) override;
    void Projection(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Clipping(float nearPlane, float farPlane, const FileLoc& loc) override;
    void ClippingPlane(float x, float y, float z, float nx, float ny, float nz,
                       const FileLoc& loc) override;
    void DepthOfField(float fstop, float focalLength, float focalDistance,
                      const FileLoc& loc) override;
    void Shutter(float open, float close, const FileLoc& loc) override;
    void PixelVariance(float variance, const FileLoc& loc) override;
    void PixelSamples(float xsamples, float ysamples, const FileLoc& loc) override;
    void PixelFilter(const std::string& name, float xwidth, float ywidth,
                     const FileLoc& loc) override;
    void Exposure(float gain, float gamma, const FileLoc& loc) override;
    void Imager(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Quantize(const std::string& type, int one, int min, int max, float dither,
                  const FileLoc& loc) override;
    void Display(const std::string& name, const std::string& type, const std::string& mode,
                 const ParamList& params, const FileLoc& loc) override;
    void Hider(const std::string& type, const ParamList& params, const FileLoc& loc) override;
    void ColorSamples(const std::vector<float>& nRGB, const std::vector<float>& RGBn,
                      const FileLoc& loc) override;
    void RelativeDetail(float relativeDetail, const FileLoc& loc) override;
    void Option(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Color(const std::vector<float>& color, const FileLoc& loc) override;
    void Opacity(const std::vector<float>& opacity, const FileLoc& loc) override;
    void TextureCoordinates(const std::vector<float>& st8, const FileLoc& loc) override;
    void LightSource(const std::string& name, const RtHandle& handle, const ParamList& params,
                     const FileLoc& loc) override;
    void AreaLightSource(const std::string& name, const RtHandle& handle, const ParamList& params,
                         const FileLoc& loc) override;
    void Illuminate(const RtHandle& light, bool on, const FileLoc& loc) override;
    void Surface(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Displacement(const std::string& name, const ParamList& params,
                      const FileLoc& loc) override;
    void Atmosphere(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Interior(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Exterior(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void ShadingRate(float size, const FileLoc& loc) override;
    void ShadingInterpolation(const std::string& type, const FileLoc& loc) override;
    void Matte(bool on, const FileLoc& loc) override;
    void Bound(const std::vector<float>& bound6, const FileLoc& loc) override;
    void Detail(const std::vector<float>& bound6, const FileLoc& loc) override;
    void DetailRange(float minVisible, float lowerTransition, float upperTransition,
                     float maxVisible, const FileLoc& loc) override;
    void GeometricApproximation(const std::string& type, float value, const FileLoc& loc) override;
    void Orientation(const std::string& orientation, const FileLoc& loc) override;
    void ReverseOrientation(const FileLoc& loc) override;
    void Sides(int sides, const FileLoc& loc) override;
    void Attribute(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Basis(const RtBasis& ubasis, int ustep, const RtBasis& vbasis, int vstep,
               const FileLoc& loc) override;
    void TrimCurve(const std::vector<int>& ncurves, const std::vector<int>& order,
                   const std::vector<float>& knot, const std::vector<float>& min,
                   const std::vector<float>& max, const std::vector<int>& n,
                   const std::vector<float>& u, const std::vector<float>& v,
                   const std::vector<float>& w, const FileLoc& loc) override;
    void Identity(const FileLoc& loc) override;
    void Transform(const RtMatrix& m, const FileLoc& loc) override;
    void ConcatTransform(const RtMatrix& m, const FileLoc& loc) override;
    void Perspective(float fov, const FileLoc& loc) override;
    void Translate(float dx, float dy, float dz, const FileLoc& loc) override;
    void Rotate(float angle, float dx, float dy, float dz, const FileLoc& loc) override;
    void Scale(float sx, float sy, float sz, const FileLoc& loc) override;
    void Skew(float angle, float dx1, float dy1, float dz1, float dx2, float dy2, float dz2,
              const FileLoc& loc) override;
    void CoordinateSystem(const std::string& space, const FileLoc& loc) override;
    void ScopedCoordinateSystem(const std::string& space, const FileLoc& loc) override;
    void CoordSysTransform(const std::string& space, const FileLoc& loc) override;
    void Polygon(const ParamList& params, const FileLoc& loc) override;
    void GeneralPolygon(const std::vector<int>& nverts, const ParamList& params,
                        const FileLoc& loc) override;
    void PointsPolygons(const std::vector<int>& nverts, const std::vector<int>& verts,
                        const ParamList& params, const FileLoc& loc) override;
    void PointsGeneralPolygons(const std::vector<int>& nloops, const std::vector<int>& nverts,
                               const std::vector<int>& verts, const ParamList& params,
                               const FileLoc& loc) override;
    void Patch(const std::string& type, const ParamList& params, const FileLoc& loc) override;
    void PatchMesh(const std::string& type, int nu, const std::string& uwrap, int nv,
                   const std::string& vwrap, const ParamList& params, const FileLoc& loc) override;
    void NuPatch(int nu, int uorder, const std::vector<float>& uknot, float umin, float umax,
                 int nv, int vorder, const std::vector<float>& vknot, float vmin, float vmax,
                 const ParamList& params, const FileLoc& loc) override;
    void SubdivisionMesh(const std::string& scheme, const std::vector<int>& nverts,
                         const std::vector<int>& verts, const std::vector<std::string>& tags,
                         const std::vector<int>& nargs, const std::vector<int>& intargs,
                         const std::vector<float>& floatargs, const ParamList& params,
                         const FileLoc& loc) override;
    void Sphere(float radius, float zmin, float zmax, float thetamax, const ParamList& params,
                const FileLoc& loc) override;
    void Cone(float height, float radius, float thetamax, const ParamList& params,
              const FileLoc& loc) override;
    void Cylinder(float radius, float zmin, float zmax, float thetamax, const ParamList& params,
                  const FileLoc& loc) override;
    void Hyperboloid(float x1, float y1, float z1, float x2, float y2, float z2, float thetamax,
                     const ParamList& params, const FileLoc& loc) override;
    void Paraboloid(float rmax, float zmin, float zmax, float thetamax, const ParamList& params,
                    const FileLoc& loc) override;
    void Disk(float height, float radius, float thetamax, const ParamList& params,
              const FileLoc& loc) override;
    void Torus(float majorRadius, float minorRadius, float phimin, float phimax, float thetamax,
               const ParamList& params, const FileLoc& loc) override;
    void Points(const ParamList& params, const FileLoc& loc) override;
    void Curves(const std::string& type, const std::vector<int>& nvertices, const std::string& wrap,
                const ParamList& params, const FileLoc& loc) override;
    void Blobby(int nleaf, const std::vector<int>& code, const std::vector<float>& floats,
                const std::vector<std::string>& strings, const ParamList& params,
                const FileLoc& loc) override;
    // Prints the request as it is; the procedural is not read.
    void Procedural(const std::string& name, const std::vector<std::string>& args,
                    const std::vector<float>& bound6, ProceduralReader& reader,
                    const FileLoc& loc) override;
    void Geometry(const std::string& type, const ParamList& params, const FileLoc& loc) override;
    void MakeTexture(const std::string& picture, const std::string& texture,
                     const std::string& swrap, const std::string& twrap, const std::string& filter,
                     float swidth, float twidth, const ParamList& params,
                     const FileLoc& loc) override;
    void MakeLatLongEnvironment(const std::string& picture, const std::string& texture,
                                const std::string& filter, float swidth, float twidth,
                                const ParamList& params, const FileLoc& loc) override;
    void MakeCubeFaceEnvironment(const std::vector<std::string>& faces, const std::string& texture,
                                 float fov, const std::string& filter, float swidth, float twidth,
                                 const ParamList& params, const FileLoc& loc) override;
    void MakeShadow(const std::string& picture, const std::string& texture, const ParamList& params,
                    const FileLoc& loc) override;
    void ErrorHandler(const std::string& handler, const FileLoc& loc) override;

  private:
    template <typename... Values>
    void Emit(const char* request, const Values&... values);
    void Indent();
    void BeginBlock(const char* request) { Emit(request), ++depth_; }
    void EndBlock(const char* request);

    void Put(int value);
    void Put(bool value) { Put(value ? 1 : 0); }
    void Put(float value);
    void Put(double value);
    void Put(const std::string& text);
    void Put(const std::vector<float>& values);
    void Put(const std::vector<int>& values);
    void Put(const std::vector<std::string>& values);
    void Put(const RtHandle& handle);
    void Put(const RtBasis& basis);
    void Put(const RtMatrix& matrix);
    void Put(const ParamList& params);

    std::ostream& out_;
    int depth_ = 0;
};

}  // namespace gonio
