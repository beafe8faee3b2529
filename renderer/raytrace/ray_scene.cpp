// The one file that includes Embree (STYLE.md habit 3).

#include "renderer/raytrace/ray_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "base/overloaded.h"
#include "renderer/geometry/trim_curves.h"
#include "renderer/raytrace/motion.h"
#include "renderer/raytrace/shape_evaluation.h"
#include "renderer/raytrace/solid_tree.h"
#include "renderer/raytrace/transforms.h"
#include "renderer/raytrace/transparent_layers.h"

namespace gonio {
namespace {

using Imath::M44f;
using Imath::V3f;

// RayHit::instID of a hit on a solid's surface, which lies in Impl::solids, not in `top`.
constexpr unsigned kSolidLevel = RTC_INVALID_GEOMETRY_ID - 1;
// Crossings of solids' surfaces one ray collects at most; a ray through more sees the rest as
// empty space.
constexpr size_t kMaxSolidCrossings = 1024;

// Width scales with the cube root of the volume change: exact for similarity transforms.
float LengthScale(const M44f& m) { return std::cbrt(std::fabs(m.determinant())); }

// A quadric placed in a scene: Embree user geometry calls back into it.
struct QuadricGeometry {
    const Quadric* quadric;
    M44f objectFromSpace;
    M44f spaceFromObject;
};

// p·M for an affine M (Imath's multVecMatrix also divides by w, which costs a division per ray).
V3f AffinePoint(const M44f& m, float x, float y, float z) {
    return V3f(x * m[0][0] + y * m[1][0] + z * m[2][0] + m[3][0],
               x * m[0][1] + y * m[1][1] + z * m[2][1] + m[3][1],
               x * m[0][2] + y * m[1][2] + z * m[2][2] + m[3][2]);
}

V3f AffineVector(const M44f& m, float x, float y, float z) {
    return V3f(x * m[0][0] + y * m[1][0] + z * m[2][0], x * m[0][1] + y * m[1][1] + z * m[2][1],
               x * m[0][2] + y * m[1][2] + z * m[2][2]);
}

void QuadricBounds(const RTCBoundsFunctionArguments* args) {
    const auto* q = static_cast<const QuadricGeometry*>(args->geometryUserPtr);
    const Box3f box = q->quadric->Bounds();
    Box3f out;
    for (int i = 0; i < 8; ++i) {
        const V3f corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                         (i & 4) ? box.max.z : box.min.z);
        out.extendBy(TransformPoint(q->spaceFromObject, corner));
    }
    RTCBounds* b = args->bounds_o;
    b->lower_x = out.min.x, b->lower_y = out.min.y, b->lower_z = out.min.z;
    b->upper_x = out.max.x, b->upper_y = out.max.y, b->upper_z = out.max.z;
}

// Only t and the object-space hit point: (u, v) follow in Evaluate for the hit that is shaded.
bool IntersectQuadricRay(const QuadricGeometry* q, RTCRayN* rays, unsigned N, unsigned i, float* t,
                         V3f* objectP) {
    const M44f& m = q->objectFromSpace;
    // An affine map keeps the ray parameter: t is the same in object space.
    return q->quadric->IntersectPoint(
        AffinePoint(m, RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i),
                    RTCRayN_org_z(rays, N, i)),
        AffineVector(m, RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i),
                     RTCRayN_dir_z(rays, N, i)),
        RTCRayN_tnear(rays, N, i), RTCRayN_tfar(rays, N, i), t, objectP);
}

void QuadricIntersect(const RTCIntersectFunctionNArguments* args) {
    const auto* q = static_cast<const QuadricGeometry*>(args->geometryUserPtr);
    const unsigned N = args->N;
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, N);
    for (unsigned i = 0; i < N; ++i) {
        if (!args->valid[i]) continue;
        float t;
        V3f p;
        if (!IntersectQuadricRay(q, rays, N, i, &t, &p)) continue;
        RTCRayN_tfar(rays, N, i) = t;
        // Embree's hit has no field for the object-space point, so it rides in Ng until
        // RayScene::Intersect moves it to RayHit::objectP; (u, v) are not known yet.
        RTCHitN_u(hits, N, i) = 0;
        RTCHitN_v(hits, N, i) = 0;
        RTCHitN_Ng_x(hits, N, i) = p.x;
        RTCHitN_Ng_y(hits, N, i) = p.y;
        RTCHitN_Ng_z(hits, N, i) = p.z;
        RTCHitN_primID(hits, N, i) = args->primID;
        RTCHitN_geomID(hits, N, i) = args->geomID;
        RTCHitN_instID(hits, N, i, 0) = args->context->instID[0];
    }
}

void QuadricOccluded(const RTCOccludedFunctionNArguments* args) {
    const auto* q = static_cast<const QuadricGeometry*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        float t;
        V3f p;
        if (IntersectQuadricRay(q, args->ray, args->N, i, &t, &p))
            RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
    }
}

void ReportEmbreeError(void* userPtr, RTCError code, const char* message) {
    auto* diagnostics = static_cast<Diagnostics*>(userPtr);
    diagnostics->Error(FileLoc{}, "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                                      (message ? message : ""));
}

}  // namespace

// What we keep for each Embree geometry, to evaluate its hits.
struct GeometryRecord {
    const SceneShape* shape = nullptr;  // null for an instance
    M44f spaceFromObject, objectFromSpace;
    PrimVarSet meshVars;  // a TriangleMesh's variables as classes
    const PrimVarSet* vars = nullptr;
    std::unique_ptr<QuadricGeometry> quadric;
    RTCGeometry geometry = nullptr;  // kept for rtcInterpolate on subdivision surfaces
    int instance = -1;               // index into Impl::instances for instance geometries
    // Subdivision surfaces: the vertex-attribute slot of each vertex, varying or facevarying
    // variable (by index into *vars), -1 for the others.
    std::vector<int> attributeSlot;
    // Indices into *vars of the standard variables, -1 when absent.
    int cs = -1, os = -1, st = -1, s = -1, t = -1;
    int quadricN = -1;  // a quadric's N (the one EvaluateQuadricAt interpolates)
    // A triangle mesh whose normal is Embree's Ng, or a quadric whose normal is that of its
    // implicit equation, and whose colour is its attributes' (no N, no Cs primitive
    // variable): EvaluateLean needs nothing else.
    bool flatMesh = false;
    bool plainQuadric = false;
};

struct SceneLevel {
    RTCScene scene = nullptr;
    std::vector<std::unique_ptr<GeometryRecord>> records;  // indexed by geomID
};

struct InstancePlacement {
    int level;  // index into Impl::definitions
    M44f worldFromDefinition, definitionFromWorld;
    const ObjectInstanceUse* use;  // null for a moving shape placed on its own
    // A moving placement: worldFromDefinition at these times.
    std::vector<float> motionTimes;
    std::vector<M44f> motion;
};

struct RayScene::Impl {
    Diagnostics& diagnostics;
    int colorComponents;
    std::vector<float> defaultCs, defaultOs;
    RTCDevice device = nullptr;
    SceneLevel top;
    // The surfaces of solids (Frame::solids) in world space, apart from `top`: a ray finds its
    // crossings with them here and SolidTrees combines them. Null scene: the frame has none.
    SceneLevel solids;
    std::unique_ptr<SolidTrees> trees;
    std::vector<SceneLevel> definitions;
    std::vector<InstancePlacement> instances;

    RTCSceneFlags sceneFlags = RTC_SCENE_FLAG_ROBUST;  // of every Embree scene it makes
    explicit Impl(Diagnostics& d) : diagnostics(d) {}
    ~Impl() {
        for (SceneLevel& level : definitions) rtcReleaseScene(level.scene);
        if (top.scene) rtcReleaseScene(top.scene);
        if (solids.scene) rtcReleaseScene(solids.scene);
        if (device) rtcReleaseDevice(device);
    }

    void AddShape(SceneLevel& level, const SceneShape& shape, const M44f& spaceFromObject);
    void Place(int level, const M44f& worldFromDefinition, const ObjectInstanceUse* use,
               const std::vector<float>& motionTimes, const std::vector<M44f>& motion);
    // A scene of its own for shapes placed by Place: in their definition space, or, for one
    // moving shape (`inObjectSpace`), in its object space.
    int NewLevel(const std::vector<const SceneShape*>& shapes, bool inObjectSpace);
    float EmbreeTime(float time) const {
        return shutterClose > shutterOpen ? (time - shutterOpen) / (shutterClose - shutterOpen)
                                          : 0.f;
    }
    float shutterOpen = 0, shutterClose = 0;
    RTCRay MakeRay(const V3f& org, const V3f& dir, float tnear, float tfar, float time) const {
        RTCRay ray;
        ray.org_x = org.x, ray.org_y = org.y, ray.org_z = org.z;
        ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
        ray.tnear = tnear;
        ray.tfar = tfar;
        ray.time = EmbreeTime(time);
        ray.mask = ~0u;
        ray.id = 0;
        ray.flags = 0;
        return ray;
    }
    // A deforming mesh or cage: its vertex buffer at each of Embree's time steps, which divide
    // the shutter interval. `floatsPerVertex` is 3, or 4 for subdivision (see MakeSubdivision).
    void SetDeformationSteps(RTCGeometry g, const SceneShape& shape, const M44f& m,
                             unsigned floatsPerVertex) const;
    void Attach(SceneLevel& level, RTCGeometry geometry, std::unique_ptr<GeometryRecord> record);
    RTCGeometry MakeMesh(const TriangleMesh& mesh, const M44f& m);
    RTCGeometry MakeQuadric(GeometryRecord& record, const QuadricShape& shape);
    RTCGeometry MakeSubdivision(GeometryRecord& record, const SubdivisionCage& cage, const M44f& m);
    RTCGeometry MakeCurves(const CurveSet& curves, const M44f& m);
    RTCGeometry MakePoints(const PointSet& points, const M44f& m);
    ObjectHit EvaluateSubdivision(const GeometryRecord& record, const RayHit& hit,
                                  const V3f& objectP) const;
    // worldP, worldDir: the hit point and the ray's direction, which spaceFromWorld takes to
    // the record's space.
    ObjectHit EvaluateObject(const GeometryRecord& record, const RayHit& hit, const V3f& worldP,
                             const V3f& worldDir, const M44f& spaceFromWorld) const;
    // The record of a hit's geometry, its attributes (an instance's for the shape, or the
    // shape's own) and the instance that placed it (null at the top level).
    struct ResolvedHit {
        const GeometryRecord* record;
        const Attributes* attributes;
        const InstancePlacement* placement;
    };
    ResolvedHit Resolve(const RayHit& hit) const;
    // The nearest hit in one level's Embree scene (`top` or `solids`).
    bool Trace(const SceneLevel& level, const V3f& org, const V3f& dir, float tnear, float tfar,
               float time, RayHit* hit) const;
    // The nearest point of a combined solid's surface within [tnear, tfar].
    bool IntersectSolids(const V3f& org, const V3f& dir, float tnear, float tfar, float time,
                         RayHit* hit) const;
    // Whether a ray enters the surface it crossed at `hit` (a hit in `solids`).
    bool Enters(const RayHit& hit, const V3f& org, const V3f& dir) const;
    // The hit geometry's record alone (Resolve without the attributes).
    const GeometryRecord& RecordOf(const RayHit& hit) const;
    // The transforms between the world and the space the hit's geometry was built in (the
    // world itself at the top level, an object definition's space in an instance).
    static void SpaceTransforms(const InstancePlacement* placement, float time,
                                M44f* worldFromSpace, M44f* spaceFromWorld);
};

void RayScene::Impl::Attach(SceneLevel& level, RTCGeometry geometry,
                            std::unique_ptr<GeometryRecord> record) {
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(level.scene, geometry);
    record->geometry = geometry;
    if (level.records.size() <= id) level.records.resize(id + 1);
    level.records[id] = std::move(record);
    rtcReleaseGeometry(geometry);  // the scene holds it now
}

namespace {

// A trimmed NuPatch (TrimCurve): hits whose surface (u,v) lies outside the trim loops are no hits.
void TrimFilter(const RTCFilterFunctionNArguments* args) {
    const auto* shape = static_cast<const SceneShape*>(args->geometryUserPtr);
    const auto* mesh = &std::get<TriangleMesh>(shape->geometry);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const uint32_t* t = &mesh->indices[3 * RTCHitN_primID(args->hit, args->N, i)];
        const float b1 = RTCHitN_u(args->hit, args->N, i), b2 = RTCHitN_v(args->hit, args->N, i);
        const V2f uv = (1 - b1 - b2) * mesh->uv[t[0]] + b1 * mesh->uv[t[1]] + b2 * mesh->uv[t[2]];
        if (!shape->trim->Contains(uv)) args->valid[i] = 0;
    }
}

void SetTrimFilter(RTCGeometry g, const SceneShape& shape) {
    const auto& mesh = std::get<TriangleMesh>(shape.geometry);
    if (mesh.uv.size() != mesh.positions.size()) return;
    rtcSetGeometryUserData(g, const_cast<SceneShape*>(&shape));
    rtcSetGeometryIntersectFilterFunction(g, TrimFilter);
    rtcSetGeometryOccludedFilterFunction(g, TrimFilter);
}

}  // namespace

RTCGeometry RayScene::Impl::MakeMesh(const TriangleMesh& mesh, const M44f& m) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const V3f p = TransformPoint(m, mesh.positions[i]);
        v[3 * i] = p.x, v[3 * i + 1] = p.y, v[3 * i + 2] = p.z;
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.TriangleCount()));
    std::memcpy(idx, mesh.indices.data(), mesh.indices.size() * sizeof(unsigned));
    return g;
}

RTCGeometry RayScene::Impl::MakeQuadric(GeometryRecord& record, const QuadricShape& shape) {
    record.quadric = std::make_unique<QuadricGeometry>(
        QuadricGeometry{shape.quadric.get(), record.objectFromSpace, record.spaceFromObject});
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, 1);
    rtcSetGeometryUserData(g, record.quadric.get());
    rtcSetGeometryBoundsFunction(g, QuadricBounds, nullptr);
    rtcSetGeometryIntersectFunction(g, QuadricIntersect);
    rtcSetGeometryOccludedFunction(g, QuadricOccluded);
    return g;
}

namespace {

// The topology of a subdivision geometry that facevarying variables are interpolated on.
constexpr unsigned kCornerTopology = 1;

// Adds kCornerTopology: face corner k is vertex k, every vertex pinned (see MakeSubdivision).
void AddCornerTopology(RTCGeometry g, size_t corners) {
    rtcSetGeometryTopologyCount(g, kCornerTopology + 1);
    auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, kCornerTopology, RTC_FORMAT_UINT, sizeof(unsigned), corners));
    for (size_t k = 0; k < corners; ++k) index[k] = static_cast<unsigned>(k);
    rtcSetGeometrySubdivisionMode(g, kCornerTopology, RTC_SUBDIVISION_MODE_PIN_ALL);
}

}  // namespace

RTCGeometry RayScene::Impl::MakeSubdivision(GeometryRecord& record, const SubdivisionCage& cage,
                                            const M44f& m) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SUBDIVISION);
    auto copy = [&](RTCBufferType type, RTCFormat format, size_t elementSize, const void* data,
                    size_t count) {
        if (count == 0) return;
        void* dst = rtcSetNewGeometryBuffer(g, type, 0, format, elementSize, count);
        std::memcpy(dst, data, elementSize * count);
    };
    // Embree evaluates subdivision surfaces with 4-wide loads and checks every lane for valid
    // numbers, so each vertex gets a fourth float, set to zero (with a packed buffer the last
    // vertex's fourth lane is uninitialised padding, which failed that check at random).
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float), cage.positions.size()));
    for (size_t i = 0; i < cage.positions.size(); ++i) {
        const V3f p = TransformPoint(m, cage.positions[i]);
        v[4 * i] = p.x, v[4 * i + 1] = p.y, v[4 * i + 2] = p.z, v[4 * i + 3] = 0;
    }
    copy(RTC_BUFFER_TYPE_FACE, RTC_FORMAT_UINT, sizeof(unsigned), cage.faceVertexCounts.data(),
         cage.faceVertexCounts.size());
    copy(RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT, sizeof(unsigned), cage.indices.data(),
         cage.indices.size());
    copy(RTC_BUFFER_TYPE_EDGE_CREASE_INDEX, RTC_FORMAT_UINT2, 2 * sizeof(unsigned),
         cage.creaseEdges.data(), cage.creaseEdges.size() / 2);
    copy(RTC_BUFFER_TYPE_EDGE_CREASE_WEIGHT, RTC_FORMAT_FLOAT, sizeof(float),
         cage.creaseWeights.data(), cage.creaseWeights.size());
    copy(RTC_BUFFER_TYPE_VERTEX_CREASE_INDEX, RTC_FORMAT_UINT, sizeof(unsigned),
         cage.cornerVertices.data(), cage.cornerVertices.size());
    copy(RTC_BUFFER_TYPE_VERTEX_CREASE_WEIGHT, RTC_FORMAT_FLOAT, sizeof(float),
         cage.cornerWeights.data(), cage.cornerWeights.size());
    copy(RTC_BUFFER_TYPE_HOLE, RTC_FORMAT_UINT, sizeof(unsigned), cage.holeFaces.data(),
         cage.holeFaces.size());
    rtcSetGeometrySubdivisionMode(g, 0,
                                  cage.interpolateBoundary ? RTC_SUBDIVISION_MODE_PIN_CORNERS
                                                           : RTC_SUBDIVISION_MODE_NO_BOUNDARY);
    // Vertex and varying variables ride along as vertex attributes, so that rtcInterpolate
    // evaluates them on the limit surface like P. Facevarying ones (one value per face corner)
    // use a second topology in which every corner is a vertex of its own: all its vertices are
    // then boundary corners, and pinning them all makes each face interpolate its corners
    // bilinearly, with jumps between faces (RISpec §4.2: facevarying is interpolated like
    // varying, but per face).
    const size_t corners = cage.indices.size();
    record.attributeSlot.assign(cage.vars.vars.size(), -1);
    unsigned slots = 0;
    bool faceVarying = false;
    for (size_t i = 0; i < cage.vars.vars.size(); ++i) {
        const PrimVar& var = cage.vars.vars[i];
        const bool perVertex =
            (var.decl.cls == ParamClass::Vertex || var.decl.cls == ParamClass::Varying) &&
            var.ValueCount() == int(cage.positions.size());
        const bool perCorner =
            var.decl.cls == ParamClass::FaceVarying && size_t(var.ValueCount()) == corners;
        if (!(perVertex || perCorner) || var.components > 16) continue;
        record.attributeSlot[i] = static_cast<int>(slots++);
        faceVarying |= perCorner;
    }
    if (faceVarying) AddCornerTopology(g, corners);
    rtcSetGeometryVertexAttributeCount(g, slots);
    for (size_t i = 0; i < cage.vars.vars.size(); ++i) {
        if (record.attributeSlot[i] < 0) continue;
        const PrimVar& var = cage.vars.vars[i];
        const unsigned slot = static_cast<unsigned>(record.attributeSlot[i]);
        // Padded to a multiple of 4 floats: Embree reads attributes 4 lanes at a time.
        const size_t stride = ((var.components + 3) / 4) * 4;
        auto* dst = static_cast<float*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, slot,
                                    static_cast<RTCFormat>(RTC_FORMAT_FLOAT + var.components - 1),
                                    stride * sizeof(float), var.ValueCount()));
        for (int v = 0; v < var.ValueCount(); ++v)
            for (size_t c = 0; c < stride; ++c)
                dst[v * stride + c] = c < size_t(var.components) ? var.Value(v)[c] : 0.f;
        if (var.decl.cls == ParamClass::FaceVarying)
            rtcSetGeometryVertexAttributeTopology(g, slot, kCornerTopology);
    }
    rtcSetGeometryTessellationRate(g, 16.f);
    return g;
}

RTCGeometry RayScene::Impl::MakeCurves(const CurveSet& curves, const M44f& m) {
    static const RTCGeometryType kRound[] = {
        RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE, RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE,
        RTC_GEOMETRY_TYPE_FLAT_BSPLINE_CURVE, RTC_GEOMETRY_TYPE_FLAT_CATMULL_ROM_CURVE};
    static const RTCGeometryType kOriented[] = {
        RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE, RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE,
        RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BSPLINE_CURVE,
        RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_CATMULL_ROM_CURVE};
    const int basis = static_cast<int>(curves.basis);
    const bool oriented = !FacesTheRay(curves);
    RTCGeometry g = rtcNewGeometry(device, oriented ? kOriented[basis] : kRound[basis]);
    const float scale = LengthScale(m);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                          curves.controlPoints.size()));
    for (size_t i = 0; i < curves.controlPoints.size(); ++i) {
        const V3f p = TransformPoint(m, curves.controlPoints[i]);
        v[4 * i] = p.x, v[4 * i + 1] = p.y, v[4 * i + 2] = p.z;
        v[4 * i + 3] = curves.radii[i] * scale;
    }
    if (oriented) {
        auto* n = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_NORMAL, 0,
                                                              RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                              curves.normals.size()));
        const M44f inv = m.inverse();
        for (size_t i = 0; i < curves.normals.size(); ++i) {
            const V3f nn = Normalized(TransformNormal(inv, curves.normals[i]));
            n[3 * i] = nn.x, n[3 * i + 1] = nn.y, n[3 * i + 2] = nn.z;
        }
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                                               RTC_FORMAT_UINT, sizeof(unsigned),
                                                               curves.segmentFirst.size()));
    std::memcpy(idx, curves.segmentFirst.data(), curves.segmentFirst.size() * sizeof(unsigned));
    // Embree draws flat curves as a few straight pieces per segment by default (4), which shows
    // as corners on long segments; 32 is smooth at any size we render.
    rtcSetGeometryTessellationRate(g, 32.f);
    return g;
}

RTCGeometry RayScene::Impl::MakePoints(const PointSet& points, const M44f& m) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_DISC_POINT);
    const float scale = LengthScale(m);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), points.centers.size()));
    for (size_t i = 0; i < points.centers.size(); ++i) {
        const V3f p = TransformPoint(m, points.centers[i]);
        v[4 * i] = p.x, v[4 * i + 1] = p.y, v[4 * i + 2] = p.z;
        v[4 * i + 3] = points.radii[i] * scale;
    }
    return g;
}

void RayScene::Impl::SetDeformationSteps(RTCGeometry g, const SceneShape& shape, const M44f& m,
                                         unsigned floatsPerVertex) const {
    const std::vector<float>& times = shape.deformTimes;
    const std::vector<std::vector<V3f>>& samples = shape.deformPositions;
    const unsigned steps = std::max<unsigned>(2, samples.size());
    const size_t count = samples[0].size();
    rtcSetGeometryTimeStepCount(g, steps);
    for (unsigned step = 0; step < steps; ++step) {
        const float time = shutterOpen + (shutterClose - shutterOpen) * step / (steps - 1);
        size_t i1 = 0;
        while (i1 + 1 < times.size() && times[i1] < time) ++i1;
        const size_t i0 = i1 > 0 ? i1 - 1 : 0;
        const float w = times[i1] > times[i0]
                            ? std::clamp((time - times[i0]) / (times[i1] - times[i0]), 0.f, 1.f)
                            : 1.f;
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT3,
                                    floatsPerVertex * sizeof(float), count));
        for (size_t k = 0; k < count; ++k) {
            const V3f p = TransformPoint(m, (1 - w) * samples[i0][k] + w * samples[i1][k]);
            float* out = v + floatsPerVertex * k;
            out[0] = p.x, out[1] = p.y, out[2] = p.z;
            if (floatsPerVertex == 4) out[3] = 0;
        }
    }
}

void RayScene::Impl::AddShape(SceneLevel& level, const SceneShape& shape,
                              const M44f& spaceFromObject) {
    auto record = std::make_unique<GeometryRecord>();
    record->shape = &shape;
    record->spaceFromObject = spaceFromObject;
    record->objectFromSpace = spaceFromObject.inverse();
    const M44f& m = record->spaceFromObject;
    // Null for an empty shape: nothing to attach.
    const RTCGeometry g = std::visit(Overloaded{
                                         [&](const TriangleMesh& mesh) -> RTCGeometry {
                                             if (mesh.TriangleCount() == 0) return nullptr;
                                             record->meshVars = MeshPrimVars(mesh);
                                             record->vars = &record->meshVars;
                                             RTCGeometry made = MakeMesh(mesh, m);
                                             if (!shape.deformPositions.empty())
                                                 SetDeformationSteps(made, shape, m, 3);
                                             if (shape.trim) SetTrimFilter(made, shape);
                                             return made;
                                         },
                                         [&](const QuadricShape& quadric) -> RTCGeometry {
                                             record->vars = &quadric.vars;
                                             return MakeQuadric(*record, quadric);
                                         },
                                         [&](const SubdivisionCage& cage) -> RTCGeometry {
                                             if (cage.faceVertexCounts.empty()) return nullptr;
                                             record->vars = &cage.vars;
                                             RTCGeometry made = MakeSubdivision(*record, cage, m);
                                             if (!shape.deformPositions.empty())
                                                 SetDeformationSteps(made, shape, m, 4);
                                             return made;
                                         },
                                         [&](const CurveSet& curves) -> RTCGeometry {
                                             if (curves.segmentFirst.empty()) return nullptr;
                                             record->vars = &curves.vars;
                                             return MakeCurves(curves, m);
                                         },
                                         [&](const PointSet& points) -> RTCGeometry {
                                             if (points.centers.empty()) return nullptr;
                                             record->vars = &points.vars;
                                             return MakePoints(points, m);
                                         },
                                     },
                                     shape.geometry);
    if (!g) return;
    const std::vector<PrimVar>& vars = record->vars->vars;
    for (size_t i = 0; i < vars.size(); ++i) {
        const std::string& name = vars[i].decl.name;
        int* index = name == "Cs"   ? &record->cs
                     : name == "Os" ? &record->os
                     : name == "st" ? &record->st
                     : name == "s"  ? &record->s
                     : name == "t"  ? &record->t
                                    : nullptr;
        if (index) *index = static_cast<int>(i);
    }
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry))
        record->flatMesh = mesh->normals.empty() && mesh->cornerNormals.empty() && record->cs < 0;
    if (const auto* quadric = std::get_if<QuadricShape>(&shape.geometry)) {
        if (const PrimVar* n = quadric->vars.Find("N"))
            record->quadricN = static_cast<int>(n - vars.data());
        record->plainQuadric = record->quadricN < 0 && record->cs < 0;
    }
    Attach(level, g, std::move(record));
}

RayScene::RayScene(const Frame& frame, Diagnostics& diagnostics, Traversal traversal)
    : impl_(std::make_unique<Impl>(diagnostics)) {
    Impl& s = *impl_;
    s.sceneFlags = traversal == Traversal::kRobust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
    s.colorComponents = frame.options.colorComponents;
    s.shutterOpen = frame.options.shutterOpen;
    s.shutterClose = std::max(frame.options.shutterClose, frame.options.shutterOpen);
    // A frame with nothing in it (start-up benchmarks, a scene still being written) needs no
    // Embree: its device and an empty scene's commit start oneTBB's workers and allocator, the
    // larger part of such a render's time. Every ray then misses (Trace, Occluded).
    if (frame.shapes.empty() && frame.instances.empty()) return;
    s.device = rtcNewDevice(nullptr);
    rtcSetDeviceErrorFunction(s.device, ReportEmbreeError, &diagnostics);
    s.top.scene = rtcNewScene(s.device);
    rtcSetSceneFlags(s.top.scene, s.sceneFlags);
    if (!frame.solids.empty()) {
        s.solids.scene = rtcNewScene(s.device);
        rtcSetSceneFlags(s.solids.scene, s.sceneFlags);
        s.trees = std::make_unique<SolidTrees>(frame.solids);
    }
    for (const SceneShape& shape : frame.shapes) {
        if (shape.solid >= 0) {
            // The builder keeps solids' surfaces static (builder_solids.cpp).
            s.AddShape(s.solids, shape, shape.worldFromObject);
        } else if (shape.worldFromObjectMotion.empty()) {
            s.AddShape(s.top, shape, shape.worldFromObject);
        } else {
            // A moving shape is placed like an object instance whose placement moves.
            s.Place(s.NewLevel({&shape}, true), M44f(), nullptr, shape.motionTimes,
                    shape.worldFromObjectMotion);
        }
    }
    // Each object definition becomes one Embree scene, placed by instance geometries.
    std::map<const ObjectDefinition*, int> levelOf;
    for (const ObjectInstanceUse& use : frame.instances) {
        auto it = levelOf.find(use.definition.get());
        if (it == levelOf.end()) {
            std::vector<const SceneShape*> shapes;
            for (const SceneShape& shape : use.definition->shapes) shapes.push_back(&shape);
            it = levelOf.emplace(use.definition.get(), s.NewLevel(shapes, false)).first;
        }
        s.Place(it->second, use.worldFromDefinition, &use, use.motionTimes,
                use.worldFromDefinitionMotion);
    }
    rtcCommitScene(s.top.scene);
    if (s.solids.scene) rtcCommitScene(s.solids.scene);
}

int RayScene::Impl::NewLevel(const std::vector<const SceneShape*>& shapes, bool inObjectSpace) {
    SceneLevel level;
    level.scene = rtcNewScene(device);
    rtcSetSceneFlags(level.scene, sceneFlags);
    for (const SceneShape* shape : shapes)
        AddShape(level, *shape, inObjectSpace ? M44f() : shape->worldFromObject);
    rtcCommitScene(level.scene);
    definitions.push_back(std::move(level));
    return static_cast<int>(definitions.size()) - 1;
}

void RayScene::Impl::Place(int level, const M44f& worldFromDefinition, const ObjectInstanceUse* use,
                           const std::vector<float>& motionTimes, const std::vector<M44f>& motion) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, definitions[level].scene);
    // Imath's row-vector matrix, read column-major, is the column-vector matrix Embree wants.
    if (motion.empty()) {
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                                worldFromDefinition.getValue());
    } else {
        // Embree's time steps divide its time [0, 1], which is our shutter interval.
        const unsigned steps = std::max<unsigned>(2, motion.size());
        rtcSetGeometryTimeStepCount(g, steps);
        for (unsigned i = 0; i < steps; ++i) {
            const float time = shutterOpen + (shutterClose - shutterOpen) * i / (steps - 1);
            rtcSetGeometryTransform(g, i, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                                    TransformAt(motionTimes, motion, time).getValue());
        }
    }
    auto record = std::make_unique<GeometryRecord>();
    record->instance = static_cast<int>(instances.size());
    instances.push_back(
        {level, worldFromDefinition, worldFromDefinition.inverse(), use, motionTimes, motion});
    Attach(top, g, std::move(record));
}

RayScene::~RayScene() = default;

size_t RayScene::GeometryCount() const {
    size_t n = impl_->top.records.size() + impl_->solids.records.size();
    for (const SceneLevel& level : impl_->definitions) n += level.records.size();
    return n;
}

bool RayScene::Impl::Trace(const SceneLevel& level, const V3f& org, const V3f& dir, float tnear,
                           float tfar, float time, RayHit* hit) const {
    if (!level.scene) return false;  // an empty frame's
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = MakeRay(org, dir, tnear, tfar, time);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(level.scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit->t = rh.ray.tfar;
    hit->time = time;
    hit->geomID = rh.hit.geomID;
    hit->primID = rh.hit.primID;
    hit->instID = &level == &solids ? kSolidLevel : rh.hit.instID[0];
    hit->u = rh.hit.u;
    hit->v = rh.hit.v;
    hit->flipNormal = false;
    const V3f ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    const bool quadric = RecordOf(*hit).quadric != nullptr;
    hit->Ng = quadric ? V3f(0) : ng;
    hit->objectP = quadric ? ng : V3f(0);  // QuadricIntersect's point
    return true;
}

bool RayScene::Impl::Enters(const RayHit& hit, const V3f& org, const V3f& dir) const {
    const GeometryRecord& record = RecordOf(hit);
    const ObjectHit object = EvaluateObject(record, hit, org + hit.t * dir, dir, M44f());
    const V3f worldNg = TransformNormal(record.objectFromSpace, object.geometry.Ng);
    return (worldNg.dot(dir) < 0) != record.shape->flipNormals;
}

bool RayScene::Impl::IntersectSolids(const V3f& org, const V3f& dir, float tnear, float tfar,
                                     float time, RayHit* hit) const {
    // Every crossing to the end of the ray: those beyond tfar say where the ray starts.
    thread_local std::vector<SolidCrossing> crossings;
    thread_local std::vector<RayHit> hits;
    crossings.clear();
    hits.clear();
    RayHit next;
    float from = tnear;
    while (crossings.size() < kMaxSolidCrossings &&
           Trace(solids, org, dir, from, std::numeric_limits<float>::infinity(), time, &next)) {
        crossings.push_back({next.t, RecordOf(next).shape->solid, Enters(next, org, dir)});
        hits.push_back(next);
        from = ContinuePast(next.t);
    }
    if (crossings.empty()) return false;
    bool flip = false;
    const int first = trees->FirstBoundary(crossings, tfar, &flip);
    if (first < 0) return false;
    *hit = hits[size_t(first)];
    hit->flipNormal = flip;
    return true;
}

bool RayScene::Intersect(const V3f& org, const V3f& dir, float tnear, float tfar, float time,
                         RayHit* hit) const {
    const bool found = impl_->Trace(impl_->top, org, dir, tnear, tfar, time, hit);
    // Frames without solids pay this one test.
    if (!impl_->trees) return found;
    RayHit solid;
    if (!impl_->IntersectSolids(org, dir, tnear, found ? hit->t : tfar, time, &solid)) return found;
    *hit = solid;
    return true;
}

bool RayScene::Occluded(const V3f& org, const V3f& dir, float tnear, float tfar, float time) const {
    if (!impl_->top.scene) return false;  // an empty frame's
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = impl_->MakeRay(org, dir, tnear, tfar, time);
    rtcOccluded1(impl_->top.scene, &context, &ray);
    if (ray.tfar < 0) return true;
    RayHit solid;
    return impl_->trees && impl_->IntersectSolids(org, dir, tnear, tfar, time, &solid);
}

ObjectHit RayScene::Impl::EvaluateObject(const GeometryRecord& record, const RayHit& hit,
                                         const V3f& worldP, const V3f& worldDir,
                                         const M44f& spaceFromWorld) const {
    // The hit point and normal in object space, for the kinds Embree gives them in world space.
    auto objectP = [&] {
        return TransformPoint(record.objectFromSpace, TransformPoint(spaceFromWorld, worldP));
    };
    auto objectNg = [&] { return TransformNormal(record.spaceFromObject, hit.Ng); };
    return std::visit(
        Overloaded{
            [&](const TriangleMesh& mesh) { return EvaluateMesh(mesh, hit.primID, hit.u, hit.v); },
            [&](const QuadricShape& quadric) {
                const PrimVar* normals =
                    record.quadricN >= 0 ? &record.vars->vars[record.quadricN] : nullptr;
                return EvaluateQuadricAt(quadric, hit.objectP, normals);
            },
            [&](const CurveSet& curves) {
                const V3f objectDir = TransformVector(record.objectFromSpace,
                                                      TransformVector(spaceFromWorld, worldDir));
                return EvaluateCurve(curves, hit.primID, hit.u, hit.v, objectP(), objectNg(),
                                     objectDir);
            },
            [&](const PointSet&) { return EvaluatePoint(hit.primID, objectP(), objectNg()); },
            [&](const SubdivisionCage&) { return EvaluateSubdivision(record, hit, objectP()); },
        },
        record.shape->geometry);
}

// A subdivision surface: the limit surface through Embree, already in the record's space.
ObjectHit RayScene::Impl::EvaluateSubdivision(const GeometryRecord& record, const RayHit& hit,
                                              const V3f& objectP) const {
    float P[3], dPdu[3], dPdv[3];
    rtcInterpolate1(record.geometry, hit.primID, hit.u, hit.v, RTC_BUFFER_TYPE_VERTEX, 0, P, dPdu,
                    dPdv, 3);
    ObjectHit out;
    out.geometry.P = objectP;
    out.geometry.dPdu = TransformVector(record.objectFromSpace, V3f(dPdu[0], dPdu[1], dPdu[2]));
    out.geometry.dPdv = TransformVector(record.objectFromSpace, V3f(dPdv[0], dPdv[1], dPdv[2]));
    out.geometry.Ng = Normalized(out.geometry.dPdu.cross(out.geometry.dPdv));
    out.geometry.u = hit.u, out.geometry.v = hit.v;
    out.N = out.geometry.Ng;
    out.stencils.uniform = static_cast<int>(hit.primID);
    return out;
}

// One variable of a record at a hit: through Embree for a subdivision surface's per-vertex
// data, through the stencils for everything else.
void InterpolateRecordVar(const GeometryRecord& record, int index, const SurfacePoint& sp,
                          float* out) {
    const PrimVar& var = record.vars->vars[index];
    if (!record.attributeSlot.empty() && record.attributeSlot[index] >= 0) {
        rtcInterpolate0(record.geometry, sp.primID, sp.hitU, sp.hitV,
                        RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, record.attributeSlot[index], out,
                        var.components);
        return;
    }
    InterpolatePrimVar(var, sp.stencils, out);
}

bool RayScene::InterpolatePrimVar(const SurfacePoint& sp, const std::string& name,
                                  std::vector<float>* out) const {
    if (!sp.record) return false;
    const std::vector<PrimVar>& vars = sp.record->vars->vars;
    for (size_t i = 0; i < vars.size(); ++i) {
        if (vars[i].decl.name != name || vars[i].decl.type == ParamType::String) continue;
        out->assign(vars[i].components, 0.f);
        InterpolateRecordVar(*sp.record, static_cast<int>(i), sp, out->data());
        return true;
    }
    return false;
}

const GeometryRecord& RayScene::Impl::RecordOf(const RayHit& hit) const {
    if (hit.instID == RTC_INVALID_GEOMETRY_ID) return *top.records[hit.geomID];
    if (hit.instID == kSolidLevel) return *solids.records[hit.geomID];
    const InstancePlacement& placement = instances[top.records[hit.instID]->instance];
    return *definitions[placement.level].records[hit.geomID];
}

RayScene::Impl::ResolvedHit RayScene::Impl::Resolve(const RayHit& hit) const {
    const GeometryRecord* record = &RecordOf(hit);
    if (hit.instID == RTC_INVALID_GEOMETRY_ID || hit.instID == kSolidLevel)
        return {record, record->shape->attributes.get(), nullptr};
    const InstancePlacement& placement = instances[top.records[hit.instID]->instance];
    const Attributes* attributes = record->shape->attributes.get();
    if (const ObjectInstanceUse* use = placement.use)
        attributes = use->shapeAttributes[record->shape - use->definition->shapes.data()].get();
    return {record, attributes, &placement};
}

void RayScene::Impl::SpaceTransforms(const InstancePlacement* placement, float time,
                                     M44f* worldFromSpace, M44f* spaceFromWorld) {
    if (!placement) {
        worldFromSpace->makeIdentity();
        spaceFromWorld->makeIdentity();
    } else if (placement->motion.empty()) {
        *worldFromSpace = placement->worldFromDefinition;
        *spaceFromWorld = placement->definitionFromWorld;
    } else {
        *worldFromSpace = TransformAt(placement->motionTimes, placement->motion, time);
        *spaceFromWorld = worldFromSpace->inverse();
    }
}

void RayScene::EvaluateLean(const V3f& org, const V3f& dir, const RayHit& hit,
                            LeanSurfacePoint* out) const {
    const Impl::ResolvedHit resolved = impl_->Resolve(hit);
    const GeometryRecord& record = *resolved.record;
    V3f objectN(0);  // a quadric's normal in its object space
    if (record.plainQuadric)
        objectN = std::get<QuadricShape>(record.shape->geometry).quadric->NormalAt(hit.objectP);
    if (!record.flatMesh && objectN == V3f(0)) {
        SurfacePoint& sp = out->scratch;
        Evaluate(org, dir, hit, &sp);
        out->P = sp.P, out->N = sp.N, out->Ng = sp.Ng;
        out->Cs.assign(sp.Cs.begin(), sp.Cs.end());
        out->shape = sp.shape;
        out->attributes = sp.attributes;
        return;
    }
    // Embree's Ng is in the space the mesh was built in, a quadric's normal in its object
    // space; a normal goes to the world by the inverse transpose of worldFromSpace.
    out->P = org + hit.t * dir;
    const bool quadric = !record.flatMesh;
    if (resolved.placement) {
        M44f worldFromSpace, spaceFromWorld;
        Impl::SpaceTransforms(resolved.placement, hit.time, &worldFromSpace, &spaceFromWorld);
        out->Ng =
            Normalized(quadric ? TransformNormal(spaceFromWorld * record.objectFromSpace, objectN)
                               : TransformNormal(spaceFromWorld, hit.Ng));
    } else {
        out->Ng = Normalized(quadric ? TransformNormal(record.objectFromSpace, objectN) : hit.Ng);
    }
    out->N = out->Ng;
    out->shape = record.shape;
    out->attributes = resolved.attributes;
    out->Cs.assign(resolved.attributes->color.begin(), resolved.attributes->color.end());
}

SurfacePoint RayScene::Evaluate(const V3f& org, const V3f& dir, const RayHit& hit) const {
    SurfacePoint sp;
    Evaluate(org, dir, hit, &sp);
    return sp;
}

void RayScene::Evaluate(const V3f& org, const V3f& dir, const RayHit& hit,
                        SurfacePoint* out) const {
    EvaluateGeometry(org, dir, hit, out);
    FinishEvaluate(out);
}

void RayScene::EvaluateGeometry(const V3f& org, const V3f& dir, const RayHit& hit,
                                SurfacePoint* out) const {
    const Impl& s = *impl_;
    const Impl::ResolvedHit resolved = s.Resolve(hit);
    const GeometryRecord* record = resolved.record;
    M44f worldFromSpace, spaceFromWorld;
    Impl::SpaceTransforms(resolved.placement, hit.time, &worldFromSpace, &spaceFromWorld);
    const V3f worldP = org + hit.t * dir;
    const ObjectHit object = s.EvaluateObject(*record, hit, worldP, dir, spaceFromWorld);

    // At the top level the record's space is the world (SpaceTransforms gives identities).
    M44f placedWorldFromObject, placedObjectFromWorld;
    if (resolved.placement) {
        placedWorldFromObject = record->spaceFromObject * worldFromSpace;
        placedObjectFromWorld = spaceFromWorld * record->objectFromSpace;
    }
    const M44f& worldFromObject =
        resolved.placement ? placedWorldFromObject : record->spaceFromObject;
    const M44f& objectFromWorld =
        resolved.placement ? placedObjectFromWorld : record->objectFromSpace;
    SurfacePoint& sp = *out;
    sp.shape = record->shape;
    sp.P = worldP;
    sp.dPdu = object.geometry.dPdu;  // object space until FinishEvaluate
    sp.dPdv = object.geometry.dPdv;
    const float flip = record->shape->flipNormals != hit.flipNormal ? -1.f : 1.f;
    sp.Ng = flip * Normalized(TransformNormal(objectFromWorld, object.geometry.Ng));
    // N is Ng unless the primitive gives normals.
    sp.N = object.N == object.geometry.Ng
               ? sp.Ng
               : flip * Normalized(TransformNormal(objectFromWorld, object.N));
    sp.u = object.geometry.u, sp.v = object.geometry.v;

    sp.worldFromObject = worldFromObject;
    sp.record = record;
    sp.primID = hit.primID;
    sp.hitU = hit.u, sp.hitV = hit.v;
    sp.stencils = object.stencils;
    sp.attributes = resolved.attributes;
}

void RayScene::FinishEvaluate(SurfacePoint* out) const {
    SurfacePoint& sp = *out;
    const GeometryRecord* record = sp.record;
    sp.dPdu = TransformVector(sp.worldFromObject, sp.dPdu);
    sp.dPdv = TransformVector(sp.worldFromObject, sp.dPdv);
    const Attributes& attributes = *sp.attributes;
    sp.Cs = attributes.color;
    sp.Os = attributes.opacity;
    const std::vector<PrimVar>& vars = record->vars->vars;
    auto fetch = [&](int index, int components, float* out) {
        if (index >= 0 && vars[index].components == components)
            InterpolateRecordVar(*record, index, sp, out);
    };
    fetch(record->cs, static_cast<int>(sp.Cs.size()), sp.Cs.data());
    fetch(record->os, static_cast<int>(sp.Os.size()), sp.Os.data());
    // s, t: from primitive variables, else the TextureCoordinates mapped over (u, v).
    const std::vector<float>& tc = attributes.textureCoordinates;
    const float u = sp.u, v = sp.v;
    sp.s = (1 - u) * (1 - v) * tc[0] + u * (1 - v) * tc[2] + (1 - u) * v * tc[4] + u * v * tc[6];
    sp.t = (1 - u) * (1 - v) * tc[1] + u * (1 - v) * tc[3] + (1 - u) * v * tc[5] + u * v * tc[7];
    float st[2] = {sp.s, sp.t};
    fetch(record->st, 2, st);
    sp.s = st[0], sp.t = st[1];
    fetch(record->s, 1, &sp.s);
    fetch(record->t, 1, &sp.t);
}

}  // namespace gonio
