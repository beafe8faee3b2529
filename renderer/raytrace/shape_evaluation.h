#pragma once
// The differential geometry and primitive variables at a hit, in the shape's object space, for
// the shapes whose surface we know without the ray tracer (meshes, quadrics, curves, points).
// Subdivision surfaces are evaluated by Embree in ray_scene_evaluation.cpp.

#include "renderer/geometry/shape.h"
#include "renderer/scene/frame.h"

namespace gonio {

// Which values of a primitive variable meet at a point, per storage class, and with what
// weights: the one place that knows how RIB classes interpolate.
struct Stencil {
    int count = 0;
    int index[4] = {0, 0, 0, 0};
    float weight[4] = {0, 0, 0, 0};
};

struct ClassStencils {
    int uniform = 0;
    Stencil varying, vertex, faceVarying;
};

// Interpolates `var` at the point the stencils describe into out[0 .. var.components).
void InterpolatePrimVar(const PrimVar& var, const ClassStencils& stencils, float* out);

// A hit in object space, before the transform to world space.
struct ObjectHit {
    SurfaceGeometry geometry;
    Imath::V3f N;  // shading normal (equal to geometry.Ng unless the primitive gives normals)
    ClassStencils stencils;
};

// `primID`, (b1, b2): Embree's triangle and barycentrics.
ObjectHit EvaluateMesh(const TriangleMesh& mesh, unsigned primID, float b1, float b2);
// EvaluateMesh in two parts: the normals and the uniform stencil, which is what a hit that may
// not be shaded needs (P, (u, v) and the tangents are left zero), then P, (u, v), the tangents
// and the other stencils.
ObjectHit EvaluateMeshNormals(const TriangleMesh& mesh, unsigned primID, float b1, float b2);
// The face (of a polygon mesh) that triangle primID is part of: the index of its uniform
// primitive variables.
inline int MeshFace(const TriangleMesh& mesh, unsigned primID) {
    return mesh.faceOfTriangle.empty() ? 0 : static_cast<int>(mesh.faceOfTriangle[primID]);
}
void EvaluateMeshParameters(const TriangleMesh& mesh, unsigned primID, float b1, float b2,
                            ObjectHit* hit);
// At a point the quadric's IntersectPoint reported (Quadric::EvaluateAt). `normals`: the
// shape's N primitive variable, or null where it has none (found once per shape, not per hit).
ObjectHit EvaluateQuadricAt(const QuadricShape& shape, const Imath::V3f& objectP,
                            const PrimVar* normals);
// `objectP`: the hit point; curves and points have no (u,v) surface of their own to evaluate.
// (u, v): Embree's, u along the segment. `objectDir`: the ray's direction, which a ribbon that
// faces the ray (FacesTheRay) faces: its N points back along the ray, across the curve, and its
// u runs from 0 to 1 across the width (Embree gives the tangent as Ng and no across parameter).
ObjectHit EvaluateCurve(const CurveSet& curves, unsigned primID, float u, float v,
                        const Imath::V3f& objectP, const Imath::V3f& objectNg,
                        const Imath::V3f& objectDir);
ObjectHit EvaluatePoint(unsigned primID, const Imath::V3f& objectP, const Imath::V3f& objectNg);

// A mesh's variables as plain primitive variables, each rate expressed as the class that
// interpolates the same way (PerFace → uniform, PerVertex → vertex, PerCorner → facevarying).
PrimVarSet MeshPrimVars(const TriangleMesh& mesh);

}  // namespace gonio
