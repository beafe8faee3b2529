#pragma once
// RISpec §5.5 Curves, converted to the control points Embree's curve geometry reads.
//
// Linear curves keep their vertices (a periodic curve repeats its first vertex at its end).
// Cubic curves in any basis (the current vbasis and vstep) become one Bézier segment of four
// control points each: B = M_bezier⁻¹ · M_basis · G (basis.h), which traces the same cubic, so
// Embree needs only its Bézier curves whatever Basis the RIB set.
//
// Widths: "width" (varying: one value per segment end; vertex: evaluated at the segment ends)
// or "constantwidth"; 1 if neither is given. The width varies linearly along each segment
// (RISpec), which the Bézier radii r0 + (r1 − r0)·k/3 reproduce exactly. "N" makes an oriented
// ribbon (CurveSet::ribbon) with its normals converted like the widths (varying) or like the
// points (vertex); without "N" the curves are flat ribbons facing the ray.
//
// CurveSet::vars holds the other variables in a per-segment form: constant (1 value), uniform
// (one per curve, indexed by curveOfSegment), and varying, vertex and facevarying as two values
// per segment, at its start and its end, to be blended linearly by the segment parameter.

#include <string>
#include <vector>

#include "renderer/geometry/basis.h"
#include "renderer/geometry/geometry_result.h"
#include "renderer/geometry/shape.h"

namespace gonio {

// type: "linear" or "cubic"; wrap: "periodic" or "nonperiodic".
GeometryResult<CurveSet> MakeCurves(const std::string& type, const std::vector<int>& nvertices,
                                    const std::string& wrap, const PatchBasis& vbasis,
                                    const PrimVarSet& vars);

}  // namespace gonio
