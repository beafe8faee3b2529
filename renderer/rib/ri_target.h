#pragma once
// The abstract target of the RIB parser: one method per RIB request, each with the location of
// the request. The parser checks the positional arguments' count and kind and calls exactly one
// method per request; it never builds scene objects. Targets: the scene builder (rendering and
// photon tracing), the RIB printer of `gonio catrib`, and the recording target of the tests.
//
// Requests the parser handles itself never reach a target: `version`, `ReadArchive` (its
// contents arrive as ordinary requests), `ArchiveRecord` and structure comments, and the
// extension requests that have no method here (warned about once and ignored).

#include <string>
#include <vector>

#include "base/file_loc.h"
#include "renderer/rib/param_list.h"

namespace gonio {

// What the parser offers a target with a Procedural request (RISpec 3.2 §5.7): the RIB the
// procedural stands for (DelayedReadArchive's archive, RunProgram's answer), read in place, as
// if it followed the request. The target chooses whether to read it (SceneBuilder: when the
// bound can be seen), wraps it in an attribute block, and may call Read only during its
// Procedural call. Errors (a missing archive, a failing program, DynamicLoad, an unknown
// procedural) are reported at the Procedural request when Read is called.
class ProceduralReader {
  public:
    virtual ~ProceduralReader() = default;
    // `detail`: the bound's area in raster pixels, which a RunProgram program is told; a
    // program still running after `timeoutSeconds` (<= 0: no limit) is killed.
    virtual void Read(float detail, double timeoutSeconds) = 0;
};

class RiTarget {
  public:
    virtual ~RiTarget() = default;

    // Block structure (RISpec §4).
    virtual void FrameBegin(int frame, const FileLoc& loc) = 0;
    virtual void FrameEnd(const FileLoc& loc) = 0;
    virtual void WorldBegin(const FileLoc& loc) = 0;
    virtual void WorldEnd(const FileLoc& loc) = 0;
    virtual void AttributeBegin(const FileLoc& loc) = 0;
    virtual void AttributeEnd(const FileLoc& loc) = 0;
    virtual void TransformBegin(const FileLoc& loc) = 0;
    virtual void TransformEnd(const FileLoc& loc) = 0;
    virtual void ObjectBegin(const RtHandle& handle, const FileLoc& loc) = 0;
    virtual void ObjectEnd(const FileLoc& loc) = 0;
    virtual void ObjectInstance(const RtHandle& handle, const FileLoc& loc) = 0;
    virtual void MotionBegin(const std::vector<float>& times, const FileLoc& loc) = 0;
    virtual void MotionEnd(const FileLoc& loc) = 0;
    virtual void SolidBegin(const std::string& operation, const FileLoc& loc) = 0;
    virtual void SolidEnd(const FileLoc& loc) = 0;

    // Declarations (RISpec §3). The Declare state belongs to the target (declarations.h), which
    // types parameter lists with it.
    virtual void Declare(const std::string& name, const std::string& declaration,
                         const FileLoc& loc) = 0;

    // Options (RISpec §4.1).
    virtual void Format(int xres, int yres, float pixelAspect, const FileLoc& loc) = 0;
    virtual void FrameAspectRatio(float ratio, const FileLoc& loc) = 0;
    virtual void ScreenWindow(float left, float right, float bottom, float top,
                              const FileLoc& loc) = 0;
    virtual void CropWindow(float xmin, float xmax, float ymin, float ymax, const FileLoc& loc) = 0;
    virtual void Projection(const std::string& name, const ParamList& params,
                            const FileLoc& loc) = 0;
    virtual void Clipping(float nearPlane, float farPlane, const FileLoc& loc) = 0;
    virtual void ClippingPlane(float x, float y, float z, float nx, float ny, float nz,
                               const FileLoc& loc) = 0;
    // With no arguments in the RIB, fstop is +infinity (a pinhole camera).
    virtual void DepthOfField(float fstop, float focalLength, float focalDistance,
                              const FileLoc& loc) = 0;
    virtual void Shutter(float open, float close, const FileLoc& loc) = 0;
    virtual void PixelVariance(float variance, const FileLoc& loc) = 0;
    virtual void PixelSamples(float xsamples, float ysamples, const FileLoc& loc) = 0;
    virtual void PixelFilter(const std::string& name, float xwidth, float ywidth,
                             const FileLoc& loc) = 0;
    virtual void Exposure(float gain, float gamma, const FileLoc& loc) = 0;
    virtual void Imager(const std::string& name, const ParamList& params, const FileLoc& loc) = 0;
    virtual void Quantize(const std::string& type, int one, int min, int max, float dither,
                          const FileLoc& loc) = 0;
    virtual void Display(const std::string& name, const std::string& type, const std::string& mode,
                         const ParamList& params, const FileLoc& loc) = 0;
    virtual void Hider(const std::string& type, const ParamList& params, const FileLoc& loc) = 0;
    virtual void ColorSamples(const std::vector<float>& nRGB, const std::vector<float>& RGBn,
                              const FileLoc& loc) = 0;
    virtual void RelativeDetail(float relativeDetail, const FileLoc& loc) = 0;
    virtual void Option(const std::string& name, const ParamList& params, const FileLoc& loc) = 0;

    // Attributes (RISpec §4.2).
    virtual void Color(const std::vector<float>& color, const FileLoc& loc) = 0;
    virtual void Opacity(const std::vector<float>& opacity, const FileLoc& loc) = 0;
    virtual void TextureCoordinates(const std::vector<float>& st8, const FileLoc& loc) = 0;
    virtual void LightSource(const std::string& name, const RtHandle& handle,
                             const ParamList& params, const FileLoc& loc) = 0;
    virtual void AreaLightSource(const std::string& name, const RtHandle& handle,
                                 const ParamList& params, const FileLoc& loc) = 0;
    virtual void Illuminate(const RtHandle& light, bool on, const FileLoc& loc) = 0;
    virtual void Surface(const std::string& name, const ParamList& params, const FileLoc& loc) = 0;
    virtual void Displacement(const std::string& name, const ParamList& params,
                              const FileLoc& loc) = 0;
    virtual void Atmosphere(const std::string& name, const ParamList& params,
                            const FileLoc& loc) = 0;
    virtual void Interior(const std::string& name, const ParamList& params, const FileLoc& loc) = 0;
    virtual void Exterior(const std::string& name, const ParamList& params, const FileLoc& loc) = 0;
    virtual void ShadingRate(float size, const FileLoc& loc) = 0;
    virtual void ShadingInterpolation(const std::string& type, const FileLoc& loc) = 0;
    virtual void Matte(bool on, const FileLoc& loc) = 0;
    virtual void Bound(const std::vector<float>& bound6, const FileLoc& loc) = 0;
    virtual void Detail(const std::vector<float>& bound6, const FileLoc& loc) = 0;
    virtual void DetailRange(float minVisible, float lowerTransition, float upperTransition,
                             float maxVisible, const FileLoc& loc) = 0;
    virtual void GeometricApproximation(const std::string& type, float value,
                                        const FileLoc& loc) = 0;
    virtual void Orientation(const std::string& orientation, const FileLoc& loc) = 0;
    virtual void ReverseOrientation(const FileLoc& loc) = 0;
    virtual void Sides(int sides, const FileLoc& loc) = 0;
    virtual void Attribute(const std::string& name, const ParamList& params,
                           const FileLoc& loc) = 0;
    virtual void Basis(const RtBasis& ubasis, int ustep, const RtBasis& vbasis, int vstep,
                       const FileLoc& loc) = 0;
    virtual void TrimCurve(const std::vector<int>& ncurves, const std::vector<int>& order,
                           const std::vector<float>& knot, const std::vector<float>& min,
                           const std::vector<float>& max, const std::vector<int>& n,
                           const std::vector<float>& u, const std::vector<float>& v,
                           const std::vector<float>& w, const FileLoc& loc) = 0;

    // Transformations (RISpec §4.3).
    virtual void Identity(const FileLoc& loc) = 0;
    virtual void Transform(const RtMatrix& m, const FileLoc& loc) = 0;
    virtual void ConcatTransform(const RtMatrix& m, const FileLoc& loc) = 0;
    virtual void Perspective(float fov, const FileLoc& loc) = 0;
    virtual void Translate(float dx, float dy, float dz, const FileLoc& loc) = 0;
    virtual void Rotate(float angle, float dx, float dy, float dz, const FileLoc& loc) = 0;
    virtual void Scale(float sx, float sy, float sz, const FileLoc& loc) = 0;
    virtual void Skew(float angle, float dx1, float dy1, float dz1, float dx2, float dy2, float dz2,
                      const FileLoc& loc) = 0;
    virtual void CoordinateSystem(const std::string& space, const FileLoc& loc) = 0;
    virtual void ScopedCoordinateSystem(const std::string& space, const FileLoc& loc) = 0;
    virtual void CoordSysTransform(const std::string& space, const FileLoc& loc) = 0;

    // Geometric primitives (RISpec §5).
    virtual void Polygon(const ParamList& params, const FileLoc& loc) = 0;
    virtual void GeneralPolygon(const std::vector<int>& nverts, const ParamList& params,
                                const FileLoc& loc) = 0;
    virtual void PointsPolygons(const std::vector<int>& nverts, const std::vector<int>& verts,
                                const ParamList& params, const FileLoc& loc) = 0;
    virtual void PointsGeneralPolygons(const std::vector<int>& nloops,
                                       const std::vector<int>& nverts,
                                       const std::vector<int>& verts, const ParamList& params,
                                       const FileLoc& loc) = 0;
    virtual void Patch(const std::string& type, const ParamList& params, const FileLoc& loc) = 0;
    virtual void PatchMesh(const std::string& type, int nu, const std::string& uwrap, int nv,
                           const std::string& vwrap, const ParamList& params,
                           const FileLoc& loc) = 0;
    virtual void NuPatch(int nu, int uorder, const std::vector<float>& uknot, float umin,
                         float umax, int nv, int vorder, const std::vector<float>& vknot,
                         float vmin, float vmax, const ParamList& params, const FileLoc& loc) = 0;
    virtual void SubdivisionMesh(const std::string& scheme, const std::vector<int>& nverts,
                                 const std::vector<int>& verts,
                                 const std::vector<std::string>& tags,
                                 const std::vector<int>& nargs, const std::vector<int>& intargs,
                                 const std::vector<float>& floatargs, const ParamList& params,
                                 const FileLoc& loc) = 0;
    virtual void Sphere(float radius, float zmin, float zmax, float thetamax,
                        const ParamList& params, const FileLoc& loc) = 0;
    virtual void Cone(float height, float radius, float thetamax, const ParamList& params,
                      const FileLoc& loc) = 0;
    virtual void Cylinder(float radius, float zmin, float zmax, float thetamax,
                          const ParamList& params, const FileLoc& loc) = 0;
    virtual void Hyperboloid(float x1, float y1, float z1, float x2, float y2, float z2,
                             float thetamax, const ParamList& params, const FileLoc& loc) = 0;
    virtual void Paraboloid(float rmax, float zmin, float zmax, float thetamax,
                            const ParamList& params, const FileLoc& loc) = 0;
    virtual void Disk(float height, float radius, float thetamax, const ParamList& params,
                      const FileLoc& loc) = 0;
    virtual void Torus(float majorRadius, float minorRadius, float phimin, float phimax,
                       float thetamax, const ParamList& params, const FileLoc& loc) = 0;
    virtual void Points(const ParamList& params, const FileLoc& loc) = 0;
    virtual void Curves(const std::string& type, const std::vector<int>& nvertices,
                        const std::string& wrap, const ParamList& params, const FileLoc& loc) = 0;
    virtual void Blobby(int nleaf, const std::vector<int>& code, const std::vector<float>& floats,
                        const std::vector<std::string>& strings, const ParamList& params,
                        const FileLoc& loc) = 0;
    virtual void Procedural(const std::string& name, const std::vector<std::string>& args,
                            const std::vector<float>& bound6, ProceduralReader& reader,
                            const FileLoc& loc) = 0;
    virtual void Geometry(const std::string& type, const ParamList& params, const FileLoc& loc) = 0;

    // External resources (RISpec §7).
    virtual void MakeTexture(const std::string& picture, const std::string& texture,
                             const std::string& swrap, const std::string& twrap,
                             const std::string& filter, float swidth, float twidth,
                             const ParamList& params, const FileLoc& loc) = 0;
    virtual void MakeLatLongEnvironment(const std::string& picture, const std::string& texture,
                                        const std::string& filter, float swidth, float twidth,
                                        const ParamList& params, const FileLoc& loc) = 0;
    virtual void MakeCubeFaceEnvironment(const std::vector<std::string>& faces,
                                         const std::string& texture, float fov,
                                         const std::string& filter, float swidth, float twidth,
                                         const ParamList& params, const FileLoc& loc) = 0;
    virtual void MakeShadow(const std::string& picture, const std::string& texture,
                            const ParamList& params, const FileLoc& loc) = 0;
    virtual void ErrorHandler(const std::string& handler, const FileLoc& loc) = 0;
};

}  // namespace gonio
