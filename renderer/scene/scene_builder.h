#pragma once
// The RiTarget that keeps the RenderMan graphics state (options, attribute and transform stacks,
// object definitions, lights) and turns every primitive into a SceneShape. At each WorldEnd it
// hands the finished Frame to a callback: the image renderer or the photon tracer.
// Scope rules (options only outside the world, primitives only inside, balanced blocks) are
// checked here and reported with the request's location. Texture-making requests (MakeTexture,
// MakeLatLongEnvironment, MakeCubeFaceEnvironment) go, checked, to a second callback at once,
// so that a texture is made before the frames after it in the RIB are rendered.

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "renderer/geometry/geometry_result.h"
#include "renderer/rib/declarations.h"
#include "renderer/rib/ri_target.h"
#include "renderer/scene/color_plan.h"
#include "renderer/scene/frame.h"
#include "renderer/scene/texture_request.h"

namespace gonio::spectral {
struct RenderColorSpace;
}

namespace gonio {

class SceneBuilder : public RiTarget {
  public:
    using FrameHandler = std::function<void(const Frame&)>;
    using TextureHandler = std::function<void(const TextureRequest&)>;

    SceneBuilder(std::string sceneFile, Diagnostics& diagnostics, FrameHandler onFrame);
    ~SceneBuilder() override;

    // Reports blocks left open at the end of the input.
    void Finish(const FileLoc& endOfInput);
    // The colour spaces of the frames that ask for Option "spectral" "basis" "bands" or "svd",
    // chosen by a first build of the scene (BuildScene, scene_file.h).
    void SetColorPlan(ColorPlan plan);
    // Where texture-making requests go; without a handler they are noted and ignored.
    void SetTextureHandler(TextureHandler onTexture);
    // The DelayedReadArchives out of view that frame `ordinal` reads after all, by their keys
    // (lazy_procedurals.h): those some ray of an earlier rendering of it reached. The messages
    // of the archives in `firstRead` (read in no earlier reading) also go to `report`.
    struct LazyExpansion {
        std::set<std::string> keys, firstRead;
        Diagnostics* report = nullptr;
    };
    void SetLazyExpansion(int ordinal, LazyExpansion expansion);

    void Declare(const std::string& name, const std::string& declaration,
                 const FileLoc& loc) override;

    // Block structure (RISpec §4).
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

    // Options (RISpec §4.1).
    void Format(int xres, int yres, float pixelAspect, const FileLoc& loc) override;
    void FrameAspectRatio(float ratio, const FileLoc& loc) override;
    void ScreenWindow(float left, float right, float bottom, float top,
                      const FileLoc& loc) override;
    void CropWindow(float xmin, float xmax, float ymin, float ymax, const FileLoc& loc) override;
    void Projection(const std::string& name, const ParamList& params, const FileLoc& loc) override;
    void Clipping(float nearPlane, float farPlane, const FileLoc& loc) override;
    void ClippingPlane(float x, float y, float z, float nx, float ny, float nz,
                       const FileLoc& loc) override;
    // With no arguments in the RIB, fstop is +infinity (a pinhole camera).
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

    // Attributes (RISpec §4.2).
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

    // Transformations (RISpec §4.3).
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

    // Geometric primitives (RISpec §5).
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
    // Reads the procedural in an attribute block of its own unless its bound lies outside the
    // viewing frustum (builder_procedural.cpp).
    void Procedural(const std::string& name, const std::vector<std::string>& args,
                    const std::vector<float>& bound6, ProceduralReader& reader,
                    const FileLoc& loc) override;
    void Geometry(const std::string& type, const ParamList& params, const FileLoc& loc) override;

    // External resources (RISpec §7).
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
    struct State;
    enum class Block { Frame, World, Attribute, Transform, Object, Motion, Solid };

    bool RequireWorld(const char* request, const FileLoc& loc);
    // Inside MotionBegin/End: the time sample the request gives (0, 1, ...); -1 outside.
    int MotionSampleIndex();
    // Sets (or, with `concatenate`, concatenates) the transform, at one time inside a
    // motion block or at every time outside.
    void ChangeTransform(const M44f& m, bool concatenate);
    void SaveTransform();
    void RestoreTransform();
    bool RequireOptions(const char* request, const FileLoc& loc);
    void PushBlock(Block block, const FileLoc& loc);
    bool PopBlock(Block block, const char* request, const FileLoc& loc);
    void IgnoredRequest(const char* request, const FileLoc& loc);
    // Completes a texture-making request (its search path) and hands it to the handler
    // (builder_textures.cpp).
    void SubmitTextureRequest(TextureRequest request);
    // Option "spectral": the frame's colour components become samples of the spectrum
    // (builder_spectral.cpp).
    void SpectralOption(const ParamDict& params, const FileLoc& loc);
    void CheckTransmission(const ParamDict& visibility, const FileLoc& loc);
    void SpectralAttribute(const ParamDict& params);
    bool IsSpectralColor(const Param& param) const;
    // Sets the colour components (and their RGB matrices), resets Color and Opacity to 1 and
    // leaves no fitted representation (bands, svd): ColorSamples fixes the components.
    void SetColorComponents(int n, std::vector<float> toRgb, std::vector<float> fromRgb,
                            std::vector<double> wavelengths);
    // The same for a spectral colour space.
    void SetColorSpace(const spectral::RenderColorSpace& space);
    // At WorldBegin of a frame that asks for bands or svd: its colour space from the plan, or
    // sampled until it is chosen.
    void ApplyColorPlan(int ordinal);
    // Under "svd", a light's colour is the one the plan gives it (ColorChoice::lightColors).
    void ApplyPlannedLightColor(int index, LightInstance* light) const;
    void ConcatTransform(const M44f& m);
    void SetShader(ShaderInstance* shader, const std::string& name, const ParamList& params,
                   const FileLoc& loc);
    int LightIndex(const RtHandle& handle, const FileLoc& loc);
    void AddLight(SceneLight light);
    // Types a parameter of Option or Attribute `name` (inline declaration, Declare, or the
    // standard table); false, after a message, if it cannot be typed.
    bool TypeOptionParam(const std::string& request, const std::string& name, const Param& param,
                         TypedParam* out);
    // The attribute state for writing: primitives after the change get a new snapshot.
    Attributes& MutableAttributes();
    // Adds a primitive's shape with the current attributes and transform (and, for a NuPatch,
    // the current trim curves).
    void AddShape(ShapeGeometry geometry, const FileLoc& loc,
                  std::shared_ptr<const TrimRegion> trim = nullptr);
    void JoinAreaLight(const FileLoc& loc);
    bool TypeVars(const ParamList& params, PrimVarSet* vars);
    template <class T>
    void AddGeometry(const char* request, GeometryResult<T> result, const FileLoc& loc);
    // `closed`: the quadric encloses a volume by itself (QuadricShape::closed).
    void AddQuadric(const char* request, std::unique_ptr<Quadric> quadric, const ParamList& params,
                    const FileLoc& loc, bool closed = false);
    // CSG (builder_solids.cpp): a shape added inside SolidBegin becomes the surface of the
    // innermost "primitive" solid, or a primitive solid of its own (inside ObjectBegin solids
    // are not kept: SolidBegin warns).
    void JoinSolid(SceneShape* shape);
    // Warns about a primitive solid whose surfaces do not enclose a volume (RISpec: undefined).
    void CheckClosed(const SolidNode& node, const std::vector<const SceneShape*>& surfaces);
    bool StartPrimitive(const char* request, const FileLoc& loc);
    void AddDeformationSample(const ShapeGeometry& geometry, const FileLoc& loc);

    std::string sceneFile_;
    Diagnostics& diagnostics_;
    FrameHandler onFrame_;
    TextureHandler onTexture_;
    Declarations declarations_;
    std::unique_ptr<State> state_;
};

}  // namespace gonio
