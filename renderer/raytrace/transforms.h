#pragma once
// Points, directions and normals through RenderMan's row-vector matrices (p·M), shared by the
// ray tracer and the area-light sampler.

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

namespace gonio {

inline Imath::V3f TransformPoint(const Imath::M44f& m, const Imath::V3f& p) {
    Imath::V3f out;
    m.multVecMatrix(p, out);
    return out;
}

inline Imath::V3f TransformVector(const Imath::M44f& m, const Imath::V3f& v) {
    Imath::V3f out;
    m.multDirMatrix(v, out);
    return out;
}

// Normals transform with the inverse transpose; with row vectors that is n·(M⁻¹)ᵀ, so this
// takes the inverse of the point transform: objectFromSpace carries a normal into space.
inline Imath::V3f TransformNormal(const Imath::M44f& objectFromSpace, const Imath::V3f& n) {
    const Imath::M44f& m = objectFromSpace;  // n·Mᵀ without copying the transpose
    return Imath::V3f(n.x * m[0][0] + n.y * m[0][1] + n.z * m[0][2],
                      n.x * m[1][0] + n.y * m[1][1] + n.z * m[1][2],
                      n.x * m[2][0] + n.y * m[2][1] + n.z * m[2][2]);
}

// Unit length, or `fallback` for a zero vector. One division, not three: every hit normalises
// its normals.
inline Imath::V3f NormalizedOr(const Imath::V3f& v, const Imath::V3f& fallback) {
    const float len = v.length();
    return len > 0 ? v * (1 / len) : fallback;
}

// Unit length, or +z for a zero vector (a degenerate normal).
inline Imath::V3f Normalized(const Imath::V3f& v) { return NormalizedOr(v, Imath::V3f(0, 0, 1)); }

}  // namespace gonio
