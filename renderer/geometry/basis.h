#pragma once
// Cubic basis matrices for Patch, PatchMesh and Curves (RISpec 3.2 §4.2 Basis): a segment with
// geometry G = (G0 G1 G2 G3) is P(t) = [t³ t² t 1] · M · G, and `step` control points separate
// consecutive segments of a mesh or curve.

#include <Imath/ImathMatrix.h>

#include <array>
#include <optional>
#include <string>

namespace gonio {

struct PatchBasis {
    Imath::M44f matrix;  // row-major, x[i][j]: row i multiplies t^(3-i)
    int step = 3;
};

PatchBasis BezierBasis();
PatchBasis BSplineBasis();
PatchBasis CatmullRomBasis();
PatchBasis HermiteBasis();
PatchBasis PowerBasis();

// "bezier", "b-spline", "catmull-rom", "hermite" or "power"; nullopt for any other name.
std::optional<PatchBasis> NamedBasis(const std::string& name);

// The weights of the four geometry values at parameter t: [t³ t² t 1] · M.
std::array<float, 4> BasisWeights(const Imath::M44f& matrix, float t);

// The Bézier control points of the segment that `matrix` makes of the geometry g:
// B = M_bezier⁻¹ · M · g, so that the Bézier curve of B traces the same cubic.
template <class T>
std::array<T, 4> ToBezier(const Imath::M44f& matrix, const std::array<T, 4>& g);

// The matrix M_bezier⁻¹ · M used by ToBezier.
Imath::M44f BezierFromBasis(const Imath::M44f& matrix);

template <class T>
std::array<T, 4> ToBezier(const Imath::M44f& matrix, const std::array<T, 4>& g) {
    const Imath::M44f c = BezierFromBasis(matrix);
    std::array<T, 4> b;
    for (int i = 0; i < 4; ++i)
        b[i] = g[0] * c[i][0] + g[1] * c[i][1] + g[2] * c[i][2] + g[3] * c[i][3];
    return b;
}

}  // namespace gonio
