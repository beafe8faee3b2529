#pragma once
// The scalar field of a Blobby (RISpec 3.2 §5.6, PRMan Application Note #31) with its analytic
// gradient, and the weights that blend the leaves' primitive variables at a point.
//
// Each ellipsoid leaf is the field of the unit sphere carried into object space by its matrix:
// with r² = |P·M⁻¹|², the distance from the centre in blob space,
//
//     f(r²) = 1 − 3r² + 3r⁴ − r⁶ = (1 − r²)³   for r² < 1,   0 beyond      (Application Note #31)
//
// which is 1 at the centre and falls to 0 on the unit sphere, where its first and second
// derivatives in r² vanish too, so that blended fields stay smooth. A segment blob uses the same f
// of its blob-space distance to the segment divided by its radius. The surface is the level set f =
// 0.5 (kThreshold): a lone ellipsoid with the identity matrix is the sphere of radius √(1 − 0.5^⅓)
// ≈ 0.4542. (Aqsis draws the level 27/64 instead, radius 0.5; gonio keeps RISpec's 0.5.)
//
// The repelling plane (1003) is Application Note #31's repulsion of the height z above the
// plane, (D·bump(z/C) − B/z)·(1 − ease(z/A)), with z clamped to ≥ 10⁻⁶: z is the height above
// the surface of the plane's depth map along the map's view (blobby_depth_map.h), or above z = 0
// of object space when the plane has no map.

#include <vector>

#include "renderer/geometry/blobby_program.h"

namespace gonio {

// A field value and its gradient with respect to the object-space point.
struct FieldSample {
    float value = 0;
    V3f gradient{0, 0, 0};
};

class BlobbyField {
  public:
    static constexpr float kThreshold = 0.5f;

    explicit BlobbyField(BlobbyProgram program);

    const BlobbyProgram& Program() const { return program_; }

    // The field at p. `scratch` holds one sample per instruction (resized here), so that one
    // field can be evaluated from several threads, each with its own scratch.
    FieldSample Evaluate(const V3f& p, std::vector<FieldSample>* scratch) const;

    // How much each leaf's vertex value counts at p (they sum to 1). The code's operations
    // pass the weight down the way they combine fields: add and multiply share it in
    // proportion to their (positive) operands, maximum and minimum give it all to the
    // operand they chose, subtract and divide to their first operand, negate and identity to
    // theirs. So a colour stays with the blobs that make the surface where it is seen.
    void LeafWeights(const V3f& p, std::vector<FieldSample>* scratch,
                     std::vector<float>* weights) const;

    // The union of the leaves' supports: outside it every ellipsoid and segment field is 0.
    // Empty when the program has none (only constants, planes and plugins).
    Box3f Bounds() const { return bounds_; }

    // The field where no ellipsoid or segment reaches (constants, planes at their cut-off).
    float FarValue() const { return farValue_; }

    // The radius of the smallest leaf's surface alone (its threshold sphere's smallest semi-
    // axis): the tessellation's feature size. 0 when there is no ellipsoid or segment.
    float SmallestFeature() const { return smallestFeature_; }

    // The field restricted to a box: only the leaves whose supports meet it (and the planes)
    // are evaluated there, and only the operations that depend on them; an add, multiply,
    // maximum or minimum folds its other operands into one constant. Tessellating a blobby of
    // many small leaves then costs what each block's few leaves cost, not all of them.
    struct LocalOperation {
        int instruction = 0;
        std::vector<int> operands;  // the operands that vary in the box
        FieldSample folded;         // the others combined (add, multiply, maximum, minimum)
        bool hasFolded = false;
    };
    struct Local {
        std::vector<int> leaves;                 // instructions of the leaves evaluated
        std::vector<LocalOperation> operations;  // the operations evaluated, in order
        std::vector<FieldSample> at;             // one sample per instruction
    };
    // Prepares `local` for points in `box`; false when no ellipsoid or segment reaches it (the
    // field there is FarValue(), planes aside).
    bool Localize(const Box3f& box, Local* local) const;
    // The field at p, for p in the box `local` was prepared for: Evaluate(p, scratch) up to
    // the order of floating-point additions.
    FieldSample Evaluate(const V3f& p, Local* local) const;

  private:
    FieldSample LeafField(const BlobbyLeaf& leaf, const V3f& p) const;

    BlobbyProgram program_;
    std::vector<int> operations_;   // the instructions that are not leaves, in order
    std::vector<FieldSample> far_;  // every instruction's sample where no support reaches
    Box3f bounds_;
    float farValue_ = 0;
    float smallestFeature_ = 0;
};

}  // namespace gonio
