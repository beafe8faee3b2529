// Embree geometry built from a Frame's shapes: triangle meshes, quadrics (user geometry that
// calls back into Quadric), subdivision cages, curves and points, with their deformation steps
// and trim filters.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "base/overloaded.h"
#include "renderer/geometry/trim_curves.h"
#include "renderer/raytrace/ray_scene_impl.h"
#include "renderer/raytrace/transforms.h"

namespace gonio {
namespace {

using Imath::M44f;
using Imath::V3f;

// Width scales with the cube root of the volume change: exact for similarity transforms.
float LengthScale(const M44f& m) { return std::cbrt(std::fabs(m.determinant())); }

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
// Always inline: the packet callback makes one call per ray, which GCC would keep.
[[gnu::always_inline]] inline bool IntersectQuadricRay(const QuadricGeometry* q, RTCRayN* rays,
                                                       unsigned N, unsigned i, float* t,
                                                       V3f* objectP) {
    const M44f& m = q->objectFromSpace;
    const float ox = RTCRayN_org_x(rays, N, i), oy = RTCRayN_org_y(rays, N, i),
                oz = RTCRayN_org_z(rays, N, i);
    const float dx = RTCRayN_dir_x(rays, N, i), dy = RTCRayN_dir_y(rays, N, i),
                dz = RTCRayN_dir_z(rays, N, i);
    // An affine map keeps the ray parameter: t is the same in object space.
    const V3f org = q->translationOnly ? V3f(ox + m[3][0], oy + m[3][1], oz + m[3][2])
                                       : AffinePoint(m, ox, oy, oz);
    const V3f dir = q->translationOnly ? V3f(dx, dy, dz) : AffineVector(m, dx, dy, dz);
    const float tnear = RTCRayN_tnear(rays, N, i), tfar = RTCRayN_tfar(rays, N, i);
    // The whole sphere, most quadrics, without the virtual call (the same test).
    if (q->sphere) return q->sphere->Intersect(org, dir, tnear, tfar, t, objectP);
    return q->quadric->IntersectPoint(org, dir, tnear, tfar, t, objectP);
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

}  // namespace

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
    const M44f& m = record.objectFromSpace;
    bool translationOnly = true;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) translationOnly &= m[r][c] == (r == c ? 1.f : 0.f);
    record.quadric = std::make_unique<QuadricGeometry>(
        QuadricGeometry{shape.quadric.get(), record.objectFromSpace, record.spaceFromObject,
                        translationOnly, shape.quadric->AsCompleteSphere()});
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
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
        const bool noNormals = mesh->normals.empty() && mesh->cornerNormals.empty();
        record->flatMesh = noNormals && record->cs < 0;
        const float det = record->spaceFromObject.determinant();
        if (noNormals && shape.deformPositions.empty() && det != 0)
            record->embreeNgSign = det > 0 ? 1.f : -1.f;
    }
    if (const auto* quadric = std::get_if<QuadricShape>(&shape.geometry)) {
        if (const PrimVar* n = quadric->vars.Find("N"))
            record->quadricN = static_cast<int>(n - vars.data());
        record->plainQuadric = record->quadricN < 0 && record->cs < 0;
    }
    Attach(level, g, std::move(record));
}

}  // namespace gonio
