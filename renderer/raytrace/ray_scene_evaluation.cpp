// A RayScene hit evaluated into a SurfacePoint (every primitive variable, for shading) or a
// LeanSurfacePoint (point, normals and colour, for the photon tracer).

#include <string>
#include <vector>

#include "base/overloaded.h"
#include "renderer/raytrace/motion.h"
#include "renderer/raytrace/ray_scene_impl.h"
#include "renderer/raytrace/transforms.h"

namespace gonio {

using Imath::M44f;
using Imath::V3f;

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

namespace {

// The record's space at the top level (a namespace constant: a function's static would be
// tested for its initialisation at every hit).
const M44f kWorldIsSpace;

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

}  // namespace

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
    // At the top level the record's space is the world: only an instance's hit has transforms
    // to make (every camera hit comes here, so the identities are not built and copied).
    M44f worldFromSpace(Imath::UNINITIALIZED), spaceFromWorld(Imath::UNINITIALIZED);
    M44f objectFromPlaced(Imath::UNINITIALIZED);
    SurfacePoint& sp = *out;
    if (resolved.placement) {
        Impl::SpaceTransforms(resolved.placement, hit.time, &worldFromSpace, &spaceFromWorld);
        sp.worldFromObject = record->spaceFromObject * worldFromSpace;
        objectFromPlaced = spaceFromWorld * record->objectFromSpace;
    } else {
        sp.worldFromObject = record->spaceFromObject;
    }
    const M44f& objectFromWorld = resolved.placement ? objectFromPlaced : record->objectFromSpace;
    const V3f worldP = org + hit.t * dir;
    // A quadric without an N of its own may give its normal without (u, v) and the tangents,
    // which cost inverse trigonometry, and a mesh its normals without (u, v), the tangents and
    // the stencils: they wait for FinishEvaluate, which with ShadingRate sharing only one
    // camera hit in about xsamples·ysamples gets.
    const V3f pointNormal = record->quadric && record->quadricN < 0
                                ? record->quadric->quadric->OrientedNormalAt(hit.objectP)
                                : V3f(0);
    const auto* mesh = std::get_if<TriangleMesh>(&record->shape->geometry);
    sp.shape = record->shape;
    sp.P = worldP;
    sp.record = record;
    sp.primID = hit.primID;
    sp.hitU = hit.u, sp.hitV = hit.v;
    sp.attributes = resolved.attributes;
    sp.objectP = hit.objectP;
    const float flip = record->shape->flipNormals != hit.flipNormal ? -1.f : 1.f;
    // A flat mesh's normal is Embree's, which it found with the hit, and a plain quadric's its
    // point's: such a hit has its normals now, and (u, v), the tangents and the stencils but
    // the uniform one (a flat mesh's face) wait for FinishEvaluate.
    if (pointNormal != V3f(0) || (mesh && record->embreeNgSign != 0)) {
        const V3f spaceNg = record->embreeNgSign * hit.Ng;
        const V3f worldNg = pointNormal != V3f(0) ? TransformNormal(objectFromWorld, pointNormal)
                            : resolved.placement  ? TransformNormal(spaceFromWorld, spaceNg)
                                                  : spaceNg;
        sp.pending = mesh ? SurfacePoint::Pending::kMesh : SurfacePoint::Pending::kQuadric;
        sp.Ng = sp.N = flip * Normalized(worldNg);
        sp.stencils.uniform = mesh ? MeshFace(*mesh, hit.primID) : 0;
        return;
    }
    sp.pending = mesh ? SurfacePoint::Pending::kMesh : SurfacePoint::Pending::kNothing;
    const ObjectHit object =
        mesh ? EvaluateMeshNormals(*mesh, hit.primID, hit.u, hit.v)
             : s.EvaluateObject(*record, hit, worldP, dir,
                                resolved.placement ? spaceFromWorld : kWorldIsSpace);
    sp.dPdu = object.geometry.dPdu;  // object space until FinishEvaluate
    sp.dPdv = object.geometry.dPdv;
    sp.Ng = flip * Normalized(TransformNormal(objectFromWorld, object.geometry.Ng));
    // N is Ng unless the primitive gives normals.
    sp.N = object.N == object.geometry.Ng
               ? sp.Ng
               : flip * Normalized(TransformNormal(objectFromWorld, object.N));
    sp.u = object.geometry.u, sp.v = object.geometry.v;
    // A pending mesh hit's other stencils come with FinishEvaluate.
    if (mesh)
        sp.stencils.uniform = object.stencils.uniform;
    else
        sp.stencils = object.stencils;
}

void RayScene::FinishEvaluate(SurfacePoint* out) const {
    SurfacePoint& sp = *out;
    const GeometryRecord* record = sp.record;
    if (sp.pending != SurfacePoint::Pending::kNothing) {
        const ShapeGeometry& geometry = record->shape->geometry;
        ObjectHit object;
        if (sp.pending == SurfacePoint::Pending::kQuadric)
            object = EvaluateQuadricAt(std::get<QuadricShape>(geometry), sp.objectP, nullptr);
        else
            EvaluateMeshParameters(std::get<TriangleMesh>(geometry), sp.primID, sp.hitU, sp.hitV,
                                   &object);
        sp.u = object.geometry.u, sp.v = object.geometry.v;
        sp.dPdu = object.geometry.dPdu, sp.dPdv = object.geometry.dPdv;
        // The uniform stencil came with the normals.
        sp.stencils.varying = object.stencils.varying;
        sp.stencils.vertex = object.stencils.vertex;
        sp.stencils.faceVarying = object.stencils.faceVarying;
        sp.pending = SurfacePoint::Pending::kNothing;
    }
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
