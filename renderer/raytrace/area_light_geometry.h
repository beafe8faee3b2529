#pragma once
// The world-space surface of one area light: every shape that followed its AreaLightSource in
// the same attribute block (SceneLight::shapes), ready to be sampled uniformly by area. The
// light shader's illuminate runs at such samples (docs/shading-language.md, Area lights); the
// path tracer samples the same surface for next-event estimation.
//
// Shapes, each where its motion block starts (the first transform of a moving shape, the first
// positions of a deforming mesh):
//   * triangle meshes (polygons, patches, NURBS: the triangles that are rendered), exact;
//   * quadrics, on their true surface: (u, v) cells with |∂P/∂u × ∂P/∂v| linear in v across a
//     cell, exact for disks, cones and cylinders under a similarity transform (their area
//     element is linear in v and does not depend on u), within O(Δv²) ≈ 2e-5 of uniform
//     otherwise (spheres, tori, paraboloids, hyperboloids; non-uniform scales);
//   * subdivision surfaces, as their cage refined by Catmull-Clark and moved to the limit
//     surface at the refined vertices (area_light_subdivision.h).
// Curves and points are not light geometry (the scene builder leaves them out with a warning).

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <memory>
#include <vector>

#include "renderer/geometry/shape.h"
#include "renderer/scene/frame.h"

namespace gonio {

// A point on an area light. N is the unit normal of the emitting side: the shape's normal as
// the renderer shades it (Orientation and handedness applied, RISpec §4.2.6).
struct AreaLightSample {
    Imath::V3f P, N;
    // The exact density of this sample per unit of world area: 1/Area() wherever the surface
    // is sampled exactly uniformly (see above), to be used as the Monte Carlo weight.
    float pdfArea;
};

class AreaLightGeometry {
  public:
    static AreaLightGeometry Build(const Frame& frame, const SceneLight& light);
    float Area() const { return area_; }
    bool Empty() const { return !(area_ > 0); }
    // A point distributed uniformly by area over all the light's shapes, from three uniform
    // numbers in [0,1): u0 picks the triangle or quadric cell (in proportion to its area),
    // (u1, u2) the point inside it, so that stratified (u1, u2) stay stratified on each piece.
    AreaLightSample Sample(float u0, float u1, float u2) const;

  private:
    struct Triangle {
        Imath::V3f p0, e1, e2, N;
    };
    // A quadric in its world placement; sign: +1 or −1 on its world-space geometric normal.
    struct PlacedQuadric {
        std::shared_ptr<const Quadric> quadric;
        Imath::M44f worldFromObject, objectFromWorld;
        float sign = 1;
    };
    // A (u, v) rectangle of a quadric; jLow, jHigh: the world area element at its v edges.
    struct QuadricCell {
        uint32_t quadric;
        float u0, du, v0, dv, jLow, jHigh;
    };

    void AddMesh(const TriangleMesh& mesh, const SceneShape& shape);
    void AddQuadric(const QuadricShape& quadric, const SceneShape& shape);
    void AddPieceArea(float area);
    AreaLightSample SampleTriangle(const Triangle& t, float u1, float u2) const;
    AreaLightSample SampleCell(const QuadricCell& cell, float u1, float u2) const;

    std::vector<Triangle> triangles_;
    std::vector<PlacedQuadric> quadrics_;
    std::vector<QuadricCell> cells_;
    // Running area over the pieces: triangles first, then quadric cells.
    std::vector<float> cumulative_;
    float area_ = 0;
};

}  // namespace gonio
