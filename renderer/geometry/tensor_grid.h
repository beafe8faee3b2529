#pragma once
// Tessellation shared by Patch, PatchMesh and NuPatch: a tensor-product surface sampled on a
// grid of (u, v) parameters, with every primitive variable evaluated at the grid's vertices.
//
// Each direction is described by a GridAxis: where the samples lie, which control vertices
// they weigh (vertex class: the surface's own basis), which pair of corner values they blend
// (varying and facevarying: piecewise linear), and which patch or knot span each interval
// belongs to (uniform). The grid is shared between neighbouring patches, so a mesh has no
// cracks; a periodic axis repeats its first sample's evaluation bit for bit at its end.
//
// Triangles are (p00, p10, p11) and (p00, p11, p01) of each grid cell: their normal follows
// dPdu × dPdv. Positions come from homogeneous control points (x·w, y·w, z·w, w), divided after
// interpolation, so "Pw" surfaces are rational; other vertex variables use the same weights
// without w.

#include <vector>

#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

struct GridAxis {
    struct Sample {
        float param = 0;       // the surface parameter here (TriangleMesh::uv)
        int firstControl = 0;  // weights[k] applies to control (firstControl + k) mod count
        std::vector<float> weights;
        int varyingCell = 0;  // blends varying values varyingCell and varyingCell + 1
        float varyingT = 0;   // (mod varyingCount) with weights 1 − t and t
    };
    std::vector<Sample> samples;
    std::vector<int> intervalCell;  // uniform index along the axis of each sample interval
    int controlCount = 0;           // vertex values along the axis
    int varyingCount = 0;           // varying values along the axis
    int cellCount = 0;              // uniform values along the axis
};

// Tessellation density of curved surfaces: grid steps per bicubic patch or per NURBS knot span,
// lowered (to no less than minSteps) when a primitive would exceed vertexBudget grid vertices.
struct TessellationRates {
    int curvedSteps = 16;
    int curvedBilinearSteps = 8;  // bilinear patches that are not flat parallelograms
    int minSteps = 4;
    int vertexBudget = 1 << 18;

    // The steps per cell for a surface of `cells` curved cells that wants `steps` per cell.
    int StepsWithinBudget(int steps, long cells) const;
};

// `homogeneousP` has 4 floats per control vertex, u varying fastest. `rational`: divide by w
// (otherwise w is 1 and left alone). Variables named P, Pw, Pz are skipped; "N" becomes
// TriangleMesh::normals (or cornerNormals when uniform).
TriangleMesh TessellateTensorGrid(const GridAxis& u, const GridAxis& v,
                                  const std::vector<float>& homogeneousP, bool rational,
                                  const PrimVarSet& vars);

}  // namespace gonio
