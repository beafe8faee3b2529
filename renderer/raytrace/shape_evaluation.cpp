#include "renderer/raytrace/shape_evaluation.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/geometry/basis.h"
#include "renderer/raytrace/transforms.h"

namespace gonio {
namespace {

Stencil Corners3(const uint32_t* idx, float b1, float b2) {
    Stencil s;
    s.count = 3;
    s.index[0] = idx[0], s.index[1] = idx[1], s.index[2] = idx[2];
    s.weight[0] = 1 - b1 - b2, s.weight[1] = b1, s.weight[2] = b2;
    return s;
}

// RISpec: varying and vertex values of a quadric sit at its four (u,v) corners.
Stencil Bilinear4(float u, float v) {
    Stencil s;
    s.count = 4;
    for (int i = 0; i < 4; ++i) s.index[i] = i;
    s.weight[0] = (1 - u) * (1 - v), s.weight[1] = u * (1 - v);
    s.weight[2] = (1 - u) * v, s.weight[3] = u * v;
    return s;
}

Stencil Single(int index) {
    Stencil s;
    s.count = 1;
    s.index[0] = index;
    s.weight[0] = 1;
    return s;
}

// A curve segment's centre, tangent and radius at its parameter t (geometry/shape.h: four
// control points a cubic segment, two a linear one, in the Embree vertex buffer's basis).
struct CurveFrame {
    V3f centre = V3f(0), tangent = V3f(0);
    float radius = 0;
};

CurveFrame SegmentFrame(const CurveSet& curves, unsigned primID, float t) {
    const uint32_t first = curves.segmentFirst[primID];
    CurveFrame frame;
    if (curves.basis == CurveSet::Basis::Linear) {
        const V3f& a = curves.controlPoints[first];
        const V3f& b = curves.controlPoints[first + 1];
        frame.centre = a + t * (b - a);
        frame.tangent = b - a;
        frame.radius = curves.radii[first] + t * (curves.radii[first + 1] - curves.radii[first]);
        return frame;
    }
    const PatchBasis basis = curves.basis == CurveSet::Basis::Bezier    ? BezierBasis()
                             : curves.basis == CurveSet::Basis::BSpline ? BSplineBasis()
                                                                        : CatmullRomBasis();
    const std::array<float, 4> w = BasisWeights(basis.matrix, t);
    // The derivative's weights: [3t² 2t 1 0] · M.
    std::array<float, 4> dw{};
    for (int j = 0; j < 4; ++j)
        dw[j] = 3 * t * t * basis.matrix[0][j] + 2 * t * basis.matrix[1][j] + basis.matrix[2][j];
    for (int k = 0; k < 4; ++k) {
        frame.centre += w[k] * curves.controlPoints[first + k];
        frame.tangent += dw[k] * curves.controlPoints[first + k];
        frame.radius += w[k] * curves.radii[first + k];
    }
    return frame;
}

// The ribbon turned towards the ray: Ng is the part of −dir across the tangent, and u is where
// the hit lies between the two edges (the side vector T × dir spans the visible width).
void FaceTheRay(const CurveSet& curves, unsigned primID, float t, const V3f& dir,
                SurfaceGeometry* g) {
    const CurveFrame frame = SegmentFrame(curves, primID, t);
    const V3f tangent = NormalizedOr(frame.tangent, g->Ng);
    const V3f side = NormalizedOr(tangent.cross(dir), V3f(0));
    if (side == V3f(0)) return;  // looking along the curve: no width to face
    g->Ng = NormalizedOr(side.cross(tangent), g->Ng);
    if (g->Ng.dot(dir) > 0) g->Ng = -g->Ng;
    if (frame.radius > 0)
        g->u = std::clamp(0.5f + (g->P - frame.centre).dot(side) / (2 * frame.radius), 0.f, 1.f);
}

}  // namespace

void InterpolatePrimVar(const PrimVar& var, const ClassStencils& stencils, float* out) {
    const int n = var.components;
    const Stencil* stencil = nullptr;
    Stencil single;
    switch (var.decl.cls) {
        case ParamClass::Constant:
            single = Single(0), stencil = &single;
            break;
        case ParamClass::Uniform:
            single = Single(stencils.uniform), stencil = &single;
            break;
        case ParamClass::Varying:
            stencil = &stencils.varying;
            break;
        case ParamClass::Vertex:
            stencil = &stencils.vertex;
            break;
        case ParamClass::FaceVarying:
        case ParamClass::FaceVertex:
            stencil = &stencils.faceVarying;
            break;
    }
    for (int c = 0; c < n; ++c) out[c] = 0;
    const int count = var.ValueCount();
    for (int k = 0; k < stencil->count; ++k) {
        const int i = stencil->index[k];
        if (i < 0 || i >= count) continue;
        const float* value = var.Value(i);
        for (int c = 0; c < n; ++c) out[c] += stencil->weight[k] * value[c];
    }
}

ObjectHit EvaluateMeshNormals(const TriangleMesh& mesh, unsigned primID, float b1, float b2) {
    const uint32_t* idx = &mesh.indices[3 * primID];
    const V3f& p0 = mesh.positions[idx[0]];
    const V3f& p1 = mesh.positions[idx[1]];
    const V3f& p2 = mesh.positions[idx[2]];
    const float b0 = 1 - b1 - b2;
    ObjectHit hit;
    SurfaceGeometry& g = hit.geometry;
    g.P = g.dPdu = g.dPdv = V3f(0);
    hit.stencils.uniform = MeshFace(mesh, primID);
    g.Ng = NormalizedOr((p1 - p0).cross(p2 - p0), V3f(0, 0, 1));
    hit.N = g.Ng;
    if (!mesh.cornerNormals.empty()) {
        const V3f* n = &mesh.cornerNormals[3 * primID];
        hit.N = NormalizedOr(b0 * n[0] + b1 * n[1] + b2 * n[2], g.Ng);
    } else if (!mesh.normals.empty()) {
        hit.N = NormalizedOr(
            b0 * mesh.normals[idx[0]] + b1 * mesh.normals[idx[1]] + b2 * mesh.normals[idx[2]],
            g.Ng);
    }
    return hit;
}

void EvaluateMeshParameters(const TriangleMesh& mesh, unsigned primID, float b1, float b2,
                            ObjectHit* out) {
    ObjectHit& hit = *out;
    const uint32_t* idx = &mesh.indices[3 * primID];
    const V3f& p0 = mesh.positions[idx[0]];
    const V3f& p1 = mesh.positions[idx[1]];
    const V3f& p2 = mesh.positions[idx[2]];
    const float b0 = 1 - b1 - b2;
    SurfaceGeometry& g = hit.geometry;
    g.P = b0 * p0 + b1 * p1 + b2 * p2;
    g.dPdu = g.dPdv = V3f(0);  // where the triangle's (u, v) are degenerate
    if (!mesh.uv.empty()) {
        const V2f& t0 = mesh.uv[idx[0]];
        const V2f& t1 = mesh.uv[idx[1]];
        const V2f& t2 = mesh.uv[idx[2]];
        const V2f uv = b0 * t0 + b1 * t1 + b2 * t2;
        g.u = uv.x, g.v = uv.y;
        // Solve dP = dPdu·du + dPdv·dv over the triangle's two edges.
        const V2f d1 = t1 - t0, d2 = t2 - t0;
        const float det = d1.x * d2.y - d1.y * d2.x;
        if (std::fabs(det) > 1e-20f) {
            const V3f e1 = p1 - p0, e2 = p2 - p0;
            g.dPdu = (e1 * d2.y - e2 * d1.y) / det;
            g.dPdv = (e2 * d1.x - e1 * d2.x) / det;
        }
    } else {
        g.u = b1, g.v = b2;
        g.dPdu = p1 - p0, g.dPdv = p2 - p0;
    }
    ClassStencils& s = hit.stencils;
    s.varying = s.vertex = Corners3(idx, b1, b2);
    const uint32_t corners[3] = {3 * primID, 3 * primID + 1, 3 * primID + 2};
    s.faceVarying = Corners3(corners, b1, b2);
}

ObjectHit EvaluateMesh(const TriangleMesh& mesh, unsigned primID, float b1, float b2) {
    ObjectHit hit = EvaluateMeshNormals(mesh, primID, b1, b2);
    EvaluateMeshParameters(mesh, primID, b1, b2, &hit);
    return hit;
}

ObjectHit EvaluateQuadricAt(const QuadricShape& shape, const Imath::V3f& objectP,
                            const PrimVar* normals) {
    ObjectHit hit;
    hit.geometry = shape.quadric->EvaluateAt(objectP);
    hit.N = hit.geometry.Ng;
    // The primitive's N, where it gives one, and everything else through the bilinear stencils
    // of the four (u, v) corners.
    hit.stencils.varying = hit.stencils.vertex = hit.stencils.faceVarying =
        Bilinear4(hit.geometry.u, hit.geometry.v);
    if (normals) {
        float value[3];
        InterpolatePrimVar(*normals, hit.stencils, value);
        hit.N = NormalizedOr(V3f(value[0], value[1], value[2]), hit.N);
    }
    return hit;
}

ObjectHit EvaluateCurve(const CurveSet& curves, unsigned primID, float u, float v,
                        const Imath::V3f& objectP, const Imath::V3f& objectNg,
                        const Imath::V3f& objectDir) {
    ObjectHit hit;
    SurfaceGeometry& g = hit.geometry;
    g.P = objectP;
    g.Ng = NormalizedOr(objectNg, V3f(0, 0, 1));
    // Embree's u runs along the segment; RenderMan's v runs along the whole curve.
    const float v0 = primID < curves.segmentV0.size() ? curves.segmentV0[primID] : 0;
    const float v1 = primID < curves.segmentV1.size() ? curves.segmentV1[primID] : 1;
    g.v = v0 + u * (v1 - v0);
    g.u = v;
    if (FacesTheRay(curves) && primID < curves.segmentFirst.size())
        FaceTheRay(curves, primID, u, objectDir, &g);
    hit.N = g.Ng;
    ClassStencils& s = hit.stencils;
    s.uniform = primID < curves.curveOfSegment.size() ? curves.curveOfSegment[primID] : 0;
    // Curve variables are stored per segment, at its two ends (geometry/curves.h).
    Stencil ends;
    ends.count = 2;
    ends.index[0] = static_cast<int>(2 * primID);
    ends.index[1] = ends.index[0] + 1;
    ends.weight[0] = 1 - u, ends.weight[1] = u;
    s.varying = s.vertex = s.faceVarying = ends;
    return hit;
}

ObjectHit EvaluatePoint(unsigned primID, const Imath::V3f& objectP, const Imath::V3f& objectNg) {
    ObjectHit hit;
    hit.geometry.P = objectP;
    hit.geometry.Ng = NormalizedOr(objectNg, V3f(0, 0, 1));
    hit.N = hit.geometry.Ng;
    hit.stencils.uniform = 0;
    hit.stencils.varying = hit.stencils.vertex = hit.stencils.faceVarying =
        Single(static_cast<int>(primID));
    return hit;
}

PrimVarSet MeshPrimVars(const TriangleMesh& mesh) {
    PrimVarSet set;
    for (const MeshVar& mv : mesh.vars) {
        PrimVar var = mv.var;
        switch (mv.rate) {
            case MeshRate::Constant:
                var.decl.cls = ParamClass::Constant;
                break;
            case MeshRate::PerFace:
                var.decl.cls = ParamClass::Uniform;
                break;
            case MeshRate::PerVertex:
                var.decl.cls = ParamClass::Vertex;
                break;
            case MeshRate::PerCorner:
                var.decl.cls = ParamClass::FaceVarying;
                break;
        }
        set.vars.push_back(std::move(var));
    }
    return set;
}

}  // namespace gonio
