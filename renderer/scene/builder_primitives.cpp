// SceneBuilder: the geometric primitives of RISpec §5. Each request types its parameter list,
// calls the geometry code (renderer/geometry/) for a description, and adds it as a SceneShape.

#include <Imath/ImathMatrixAlgo.h>

#include <cmath>
#include <memory>

#include "base/search_path.h"
#include "renderer/geometry/blobby.h"
#include "renderer/geometry/curves.h"
#include "renderer/geometry/nurbs.h"
#include "renderer/geometry/patches.h"
#include "renderer/geometry/points.h"
#include "renderer/geometry/polygons.h"
#include "renderer/geometry/primvar_eval.h"
#include "renderer/geometry/quadrics.h"
#include "renderer/geometry/subdivision.h"
#include "renderer/geometry/teapot.h"
#include "renderer/scene/depth_map_camera.h"
#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/search_paths.h"

namespace gonio {

bool SceneBuilder::StartPrimitive(const char* request, const FileLoc& loc) {
    if (!state_->inWorld && !state_->openObject) {
        diagnostics_.Error(loc, std::string(request) +
                                    " is a primitive and is only valid inside WorldBegin/WorldEnd");
        return false;
    }
    state_->primitiveSample = MotionSampleIndex();
    return true;
}

namespace {

// The positions a deforming primitive moves, for the kinds that can deform.
const std::vector<V3f>* DeformablePositions(const ShapeGeometry& geometry) {
    if (const auto* mesh = std::get_if<TriangleMesh>(&geometry)) return &mesh->positions;
    if (const auto* cage = std::get_if<SubdivisionCage>(&geometry)) return &cage->positions;
    return nullptr;
}

}  // namespace

// Inside a motion block the second and later primitives are the first one at later times:
// their positions become the first shape's deformation samples.
void SceneBuilder::AddDeformationSample(const ShapeGeometry& geometry, const FileLoc& loc) {
    std::vector<SceneShape>& shapes =
        state_->openObject ? state_->openObject->shapes : state_->frame.shapes;
    SceneShape* first = shapes.empty() ? nullptr : &shapes.back();
    const std::vector<V3f>* moved = DeformablePositions(geometry);
    const std::vector<V3f>* base = first ? DeformablePositions(first->geometry) : nullptr;
    if (!moved || !base || moved->size() != base->size() ||
        geometry.index() != first->geometry.index()) {
        diagnostics_.NoteOnce("deformation", loc,
                              "only polygon, patch and subdivision meshes of unchanged topology "
                              "deform in a motion block; this primitive uses its first sample");
        return;
    }
    if (first->deformPositions.empty()) {
        first->deformTimes = state_->motionTimes;
        first->deformPositions.assign(state_->motionTimes.size(), *base);
    }
    // Until later samples arrive, every later time sees this one.
    for (size_t i = state_->primitiveSample; i < first->deformPositions.size(); ++i)
        first->deformPositions[i] = *moved;
}

bool SceneBuilder::TypeVars(const ParamList& params, PrimVarSet* vars) {
    return TypePrimVars(params, declarations_, state_->options.colorComponents, diagnostics_, vars);
}

void SceneBuilder::AddShape(ShapeGeometry geometry, const FileLoc& loc,
                            std::shared_ptr<const TrimRegion> trim) {
    // Every motion sample of a primitive the level of detail hides (the attributes cannot
    // change between them).
    if (!ShownAtDetail(state_->attributes.detail, state_->attributes.detailRange)) return;
    if (state_->primitiveSample > 0) {
        AddDeformationSample(geometry, loc);
        return;
    }
    SceneShape shape;
    shape.geometry = std::move(geometry);
    if (!state_->snapshot)
        state_->snapshot = std::make_shared<const Attributes>(state_->attributes);
    shape.attributes = state_->snapshot;
    shape.worldFromObject = state_->transform;
    shape.motionTimes = state_->transformTimes;
    shape.worldFromObjectMotion = state_->transformSamples;
    shape.loc = loc;
    shape.trim = std::move(trim);
    // Handedness of camera space from object space; camera space is left-handed.
    const M44f cameraFromObject =
        state_->transform * (state_->inWorld ? state_->frame.options.cameraFromWorld : M44f());
    const bool leftHanded = cameraFromObject.determinant() > 0;
    using O = Attributes::Orientation;
    switch (state_->attributes.orientation) {
        case O::Outside:
            shape.flipNormals = false;
            break;
        case O::Inside:
            shape.flipNormals = true;
            break;
        case O::LeftHanded:
            shape.flipNormals = !leftHanded;
            break;
        case O::RightHanded:
            shape.flipNormals = leftHanded;
            break;
    }
    if (state_->openObject) {
        state_->openObject->shapes.push_back(std::move(shape));
        if (state_->attributes.areaLight >= 0)
            diagnostics_.WarningOnce("area light object", loc,
                                     "a shape inside ObjectBegin is not area light geometry: "
                                     "its instances are rendered, but do not emit");
    } else {
        JoinSolid(&shape);
        state_->frame.shapes.push_back(std::move(shape));
        JoinAreaLight(loc);
    }
}

// The shape just added becomes geometry of the block's AreaLightSource (RISpec §4.1.3), if
// it is of a kind that has a surface to sample.
void SceneBuilder::JoinAreaLight(const FileLoc& loc) {
    const int light = state_->attributes.areaLight;
    if (light < 0 || size_t(light) >= state_->frame.lights.size()) return;
    const ShapeGeometry& geometry = state_->frame.shapes.back().geometry;
    if (std::holds_alternative<CurveSet>(geometry) || std::holds_alternative<PointSet>(geometry)) {
        diagnostics_.WarningOnce("area light curves", loc,
                                 "curves and points are not area light geometry: they are "
                                 "rendered, but do not emit");
        return;
    }
    state_->frame.lights[light].shapes.push_back(state_->frame.shapes.size() - 1);
}

template <class T>
void SceneBuilder::AddGeometry(const char* request, GeometryResult<T> result, const FileLoc& loc) {
    if (!result) {
        diagnostics_.Error(loc, std::string(request) + ": " + result.Error());
        return;
    }
    AddShape(result.Take(), loc);
}

// ---- polygons -------------------------------------------------------------------------------

void SceneBuilder::Polygon(const ParamList& params, const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("Polygon", loc) || !TypeVars(params, &vars)) return;
    AddGeometry("Polygon", MakePolygon(vars), loc);
}

void SceneBuilder::GeneralPolygon(const std::vector<int>& nverts, const ParamList& params,
                                  const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("GeneralPolygon", loc) || !TypeVars(params, &vars)) return;
    AddGeometry("GeneralPolygon", MakeGeneralPolygon(nverts, vars), loc);
}

void SceneBuilder::PointsPolygons(const std::vector<int>& nverts, const std::vector<int>& verts,
                                  const ParamList& params, const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("PointsPolygons", loc) || !TypeVars(params, &vars)) return;
    AddGeometry("PointsPolygons", MakePointsPolygons(nverts, verts, vars), loc);
}

void SceneBuilder::PointsGeneralPolygons(const std::vector<int>& nloops,
                                         const std::vector<int>& nverts,
                                         const std::vector<int>& verts, const ParamList& params,
                                         const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("PointsGeneralPolygons", loc) || !TypeVars(params, &vars)) return;
    AddGeometry("PointsGeneralPolygons", MakePointsGeneralPolygons(nloops, nverts, verts, vars),
                loc);
}

// ---- patches --------------------------------------------------------------------------------

void SceneBuilder::Patch(const std::string& type, const ParamList& params, const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("Patch", loc) || !TypeVars(params, &vars)) return;
    const Attributes& a = state_->attributes;
    AddGeometry("Patch", MakePatch(type, a.ubasis, a.vbasis, vars), loc);
}

void SceneBuilder::PatchMesh(const std::string& type, int nu, const std::string& uwrap, int nv,
                             const std::string& vwrap, const ParamList& params,
                             const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("PatchMesh", loc) || !TypeVars(params, &vars)) return;
    const Attributes& a = state_->attributes;
    AddGeometry("PatchMesh", MakePatchMesh(type, nu, uwrap, nv, vwrap, a.ubasis, a.vbasis, vars),
                loc);
}

void SceneBuilder::NuPatch(int nu, int uorder, const std::vector<float>& uknot, float umin,
                           float umax, int nv, int vorder, const std::vector<float>& vknot,
                           float vmin, float vmax, const ParamList& params, const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("NuPatch", loc) || !TypeVars(params, &vars)) return;
    GeometryResult<TriangleMesh> mesh =
        MakeNuPatch(nu, uorder, uknot, umin, umax, nv, vorder, vknot, vmin, vmax, vars);
    if (!mesh) {
        diagnostics_.Error(loc, "NuPatch: " + mesh.Error());
        return;
    }
    AddShape(mesh.Take(), loc, state_->attributes.trimCurves);
}

void SceneBuilder::SubdivisionMesh(const std::string& scheme, const std::vector<int>& nverts,
                                   const std::vector<int>& verts,
                                   const std::vector<std::string>& tags,
                                   const std::vector<int>& nargs, const std::vector<int>& intargs,
                                   const std::vector<float>& floatargs, const ParamList& params,
                                   const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("SubdivisionMesh", loc) || !TypeVars(params, &vars)) return;
    std::vector<std::string> notes;
    auto cage =
        MakeSubdivisionMesh(scheme, nverts, verts, tags, nargs, intargs, floatargs, vars, &notes);
    for (const std::string& note : notes)
        diagnostics_.WarningOnce("SubdivisionMesh " + note, loc, "SubdivisionMesh: " + note);
    AddGeometry("SubdivisionMesh", std::move(cage), loc);
}

// ---- points and curves ----------------------------------------------------------------------

void SceneBuilder::Points(const ParamList& params, const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("Points", loc) || !TypeVars(params, &vars)) return;
    AddGeometry("Points", MakePoints(vars), loc);
}

void SceneBuilder::Curves(const std::string& type, const std::vector<int>& nvertices,
                          const std::string& wrap, const ParamList& params, const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("Curves", loc) || !TypeVars(params, &vars)) return;
    AddGeometry("Curves", MakeCurves(type, nvertices, wrap, state_->attributes.vbasis, vars), loc);
}

// RISpec §5.7: the types of Geometry are implementation-specific; an unknown one is skipped
// with a warning (not an error), as RiGeometry asks, naming the one gonio has.
void SceneBuilder::Geometry(const std::string& type, const ParamList&, const FileLoc& loc) {
    if (type != "teapot") {
        diagnostics_.WarningOnce(
            "Geometry " + type, loc,
            "Geometry \"" + type + "\" is not supported (gonio has only \"teapot\"): skipped");
        return;
    }
    if (!StartPrimitive("Geometry", loc)) return;
    auto patches = MakeTeapot();
    if (!patches) {
        diagnostics_.Error(loc, "Geometry \"teapot\": " + patches.Error());
        return;
    }
    for (TriangleMesh& patch : patches.Value()) AddShape(std::move(patch), loc);
}

// ---- quadrics -------------------------------------------------------------------------------

void SceneBuilder::AddQuadric(const char* request, std::unique_ptr<Quadric> quadric,
                              const ParamList& params, const FileLoc& loc, bool closed) {
    PrimVarSet vars;
    if (!StartPrimitive(request, loc) || !TypeVars(params, &vars)) return;
    // RISpec §5.4: quadrics take one uniform value and four varying/vertex values, at the
    // corners of their (u, v) square.
    ClassCounts counts;
    counts.uniform = 1;
    counts.varying = counts.vertex = counts.faceVarying = 4;
    if (std::optional<std::string> error = CheckCounts(vars, counts)) {
        diagnostics_.Error(loc, std::string(request) + ": " + *error);
        return;
    }
    AddShape(QuadricShape{std::move(quadric), std::move(vars), closed}, loc);
}

void SceneBuilder::Sphere(float radius, float zmin, float zmax, float thetamax,
                          const ParamList& params, const FileLoc& loc) {
    const bool closed =
        std::fabs(thetamax) >= 360 && zmin <= -std::fabs(radius) && zmax >= std::fabs(radius);
    AddQuadric("Sphere", MakeSphere(radius, zmin, zmax, thetamax), params, loc, closed);
}

void SceneBuilder::Cone(float height, float radius, float thetamax, const ParamList& params,
                        const FileLoc& loc) {
    AddQuadric("Cone", MakeCone(height, radius, thetamax), params, loc);
}

void SceneBuilder::Cylinder(float radius, float zmin, float zmax, float thetamax,
                            const ParamList& params, const FileLoc& loc) {
    AddQuadric("Cylinder", MakeCylinder(radius, zmin, zmax, thetamax), params, loc);
}

void SceneBuilder::Hyperboloid(float x1, float y1, float z1, float x2, float y2, float z2,
                               float thetamax, const ParamList& params, const FileLoc& loc) {
    AddQuadric("Hyperboloid", MakeHyperboloid(V3f(x1, y1, z1), V3f(x2, y2, z2), thetamax), params,
               loc);
}

void SceneBuilder::Paraboloid(float rmax, float zmin, float zmax, float thetamax,
                              const ParamList& params, const FileLoc& loc) {
    AddQuadric("Paraboloid", MakeParaboloid(rmax, zmin, zmax, thetamax), params, loc);
}

void SceneBuilder::Disk(float height, float radius, float thetamax, const ParamList& params,
                        const FileLoc& loc) {
    AddQuadric("Disk", MakeDisk(height, radius, thetamax), params, loc);
}

void SceneBuilder::Torus(float majorRadius, float minorRadius, float phimin, float phimax,
                         float thetamax, const ParamList& params, const FileLoc& loc) {
    const bool closed = std::fabs(thetamax) >= 360 && std::fabs(phimax - phimin) >= 360;
    AddQuadric("Torus", MakeTorus(majorRadius, minorRadius, phimin, phimax, thetamax), params, loc,
               closed);
}

// ---- implicit surfaces ----------------------------------------------------------------------

namespace {

// A repelling plane's depth map, found on the texture search path (as shadow() finds its maps)
// and read once per frame (`maps`), with its camera carried into the Blobby's object space:
// depth maps share world space with the frame that rendered them.
BlobbyDepthMapLookup DepthMapsFor(FileCache<DepthMapCamera>* maps,
                                  std::vector<std::string> searchPath,
                                  const M44f& worldFromObject) {
    return [maps, searchPath = std::move(searchPath), worldFromObject](
               const std::string& name, std::string* why) -> std::shared_ptr<const BlobbyDepthMap> {
        const std::string path = FindOnSearchPath(name, searchPath);
        if (path.empty()) {
            *why = "no such file on the texture search path";
            return nullptr;
        }
        const std::shared_ptr<const DepthMapCamera> map = maps->Get(path, why, ReadDepthMapCamera);
        if (!map) return nullptr;
        return std::make_shared<BlobbyDepthMap>(map->width, map->height, map->depth,
                                                worldFromObject * map->cameraFromWorld,
                                                worldFromObject * map->screenFromWorld);
    };
}

}  // namespace

// RISpec 3.2 §5.6: tessellated at a density set by ShadingRate (renderer/geometry/blobby.h).
void SceneBuilder::Blobby(int nleaf, const std::vector<int>& code, const std::vector<float>& floats,
                          const std::vector<std::string>& strings, const ParamList& params,
                          const FileLoc& loc) {
    PrimVarSet vars;
    if (!StartPrimitive("Blobby", loc) || !TypeVars(params, &vars)) return;
    BlobbyTessellation rates;
    rates.shadingRate = state_->attributes.shadingRate;
    std::vector<std::string> notes;
    auto blobby =
        MakeBlobby(nleaf, code, floats, strings, vars, rates, &notes,
                   DepthMapsFor(state_->depthMaps.get(),
                                TextureSearchPath(state_->options, sceneFile_), state_->transform));
    for (const std::string& note : notes)
        diagnostics_.WarningOnce("Blobby " + note, loc, "Blobby: " + note);
    if (!blobby) {
        diagnostics_.Error(loc, "Blobby: " + blobby.Error());
        return;
    }
    if (blobby.Value().mesh.TriangleCount() > 0) AddShape(std::move(blobby.Value().mesh), loc);
}

// ---- errors ----------------------------------------------------------------------------------

void SceneBuilder::ErrorHandler(const std::string& handler, const FileLoc& loc) {
    if (handler != "print" && handler != "ignore" && handler != "abort") {
        diagnostics_.Error(loc, "ErrorHandler must be \"print\", \"ignore\" or \"abort\", got \"" +
                                    handler + "\"");
        return;
    }
    state_->options.errorHandler = handler;
}

}  // namespace gonio
