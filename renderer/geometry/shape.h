#pragma once
// Geometry as the renderer hands it to the ray tracer. Every RIB primitive becomes one of five
// plain descriptions; only embree_scene.cpp turns them into Embree geometry, so nothing here
// knows Embree. All positions are in the primitive's object space.

#include <Imath/ImathBox.h>
#include <Imath/ImathVec.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "renderer/geometry/complete_sphere.h"
#include "renderer/geometry/primvar.h"

namespace gonio {

using Imath::Box3f;
using Imath::V2f;
using Imath::V3f;

// The differential geometry of a surface point. Ng is normalize(cross(dPdu, dPdv)): for every
// RIB primitive this points "outside" as RISpec defines it for a left-handed object space; the
// renderer flips it by Orientation and handedness.
struct SurfaceGeometry {
    V3f P, Ng, dPdu, dPdv;
    float u = 0, v = 0;
};

// How a mesh's pre-evaluated primitive variable maps onto its triangles.
enum class MeshRate {
    Constant,   // one value
    PerFace,    // one value per RIB face or patch, indexed by TriangleMesh::faceOfTriangle
    PerVertex,  // one value per mesh vertex, interpolated barycentrically
    PerCorner,  // three values per triangle (facevarying), interpolated barycentrically
};

struct MeshVar {
    PrimVar var;
    MeshRate rate = MeshRate::Constant;
};

// Polygons, patches, NURBS and other tessellated surfaces: triangles with their primitive
// variables evaluated at the mesh's vertices (or corners). P itself is `positions`, not a MeshVar.
struct TriangleMesh {
    std::vector<V3f> positions;
    std::vector<uint32_t> indices;         // three per triangle
    std::vector<uint32_t> faceOfTriangle;  // the RIB face/patch each triangle came from
    std::vector<V2f> uv;                   // surface (u,v) per vertex; empty: use barycentrics
    std::vector<V3f> normals;              // shading normal per vertex; empty: use Ng
    std::vector<V3f> cornerNormals;        // shading normal per corner (facevarying N); or empty
    std::vector<MeshVar> vars;             // everything but P and N

    size_t TriangleCount() const { return indices.size() / 3; }
};

// A quadric hit in the quadric's own parameters.
struct QuadricHit {
    float t = 0;
    float u = 0, v = 0;
};

// The RISpec §5.4 quadrics, intersected exactly (Embree user geometry).
class Quadric {
  public:
    virtual ~Quadric() = default;
    virtual Box3f Bounds() const = 0;
    // The nearest hit with tmin < t < tmax of the ray org + t·dir (dir need not be unit length).
    virtual bool Intersect(const V3f& org, const V3f& dir, float tmin, float tmax,
                           QuadricHit* hit) const = 0;
    // The same hit without its (u, v): t and the hit point in object space. The ray tracer
    // calls this for every candidate and ParametersAt only for the hit it shades, since (u, v)
    // cost inverse trigonometry that deciding a hit on a full sweep does not need.
    virtual bool IntersectPoint(const V3f& org, const V3f& dir, float tmin, float tmax, float* t,
                                V3f* point) const = 0;
    // A whole sphere's own ray test, which IntersectPoint calls, for the ray tracer's callback
    // to call inline; null for every other quadric.
    virtual const CompleteSphere* AsCompleteSphere() const { return nullptr; }
    // The (u, v) of a point IntersectPoint reported (Intersect's (u, v) up to rounding).
    virtual V2f ParametersAt(const V3f& point) const = 0;
    // A normal at a point IntersectPoint reported, without (u, v): not normalised, facing
    // either side; zero where the surface has none (a cone's apex).
    virtual V3f NormalAt(const V3f& point) const = 0;
    // The direction of EvaluateAt(point).Ng (not normalised, up to rounding) without (u, v) or
    // the tangents, for the quadrics where that is cheaper; zero for the others.
    virtual V3f OrientedNormalAt(const V3f& /*point*/) const { return V3f(0); }
    // The surface point at parameters (u, v) in [0,1]².
    virtual SurfaceGeometry Evaluate(float u, float v) const = 0;
    // Evaluate(ParametersAt(point)) for a point IntersectPoint reported, up to float rounding;
    // a quadric may get there more cheaply from the point itself.
    virtual SurfaceGeometry EvaluateAt(const V3f& point) const {
        const V2f uv = ParametersAt(point);
        return Evaluate(uv.x, uv.y);
    }
};

// A Catmull-Clark control cage, subdivided by Embree.
struct SubdivisionCage {
    std::vector<V3f> positions;
    std::vector<uint32_t> faceVertexCounts;
    std::vector<uint32_t> indices;
    std::vector<uint32_t> creaseEdges;  // pairs of vertex indices
    std::vector<float> creaseWeights;   // one per pair
    std::vector<uint32_t> cornerVertices;
    std::vector<float> cornerWeights;
    std::vector<uint32_t> holeFaces;
    bool interpolateBoundary = false;
    PrimVarSet vars;  // everything but P; vertex/varying per control vertex, facevarying per index
};

// Curves on Embree's curve geometry. Control points are already converted to the basis named
// by `basis`, so that Embree needs no basis matrix of ours.
struct CurveSet {
    enum class Basis { Linear, Bezier, BSpline, CatmullRom };
    Basis basis = Basis::Linear;
    bool ribbon = false;                   // flat, facing the ray (RenderMan's default) or along N
    std::vector<V3f> controlPoints;        // the Embree vertex buffer
    std::vector<float> radii;              // one per control point
    std::vector<V3f> normals;              // one per control point when ribbon is oriented by N
    std::vector<uint32_t> segmentFirst;    // first control point of each segment
    std::vector<uint32_t> curveOfSegment;  // RIB curve of each segment (uniform primvars)
    std::vector<float> segmentV0, segmentV1;  // the curve parameter v at each segment's ends
    PrimVarSet vars;                          // everything but P and width
};

// RenderMan's default curve: a flat ribbon that turns to face each ray. Curves with N are
// oriented by it instead (Embree has no oriented linear curve: those face the ray too).
inline bool FacesTheRay(const CurveSet& curves) {
    return !(curves.ribbon && !curves.normals.empty() && curves.basis != CurveSet::Basis::Linear);
}

// Points as discs facing the ray (RenderMan's default), or spheres.
struct PointSet {
    std::vector<V3f> centers;
    std::vector<float> radii;
    PrimVarSet vars;  // everything but P and width
};

}  // namespace gonio
