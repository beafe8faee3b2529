#include "renderer/geometry/basis.h"

namespace gonio {

// The matrices RISpec 3.2 §4.2 gives as RiBezierBasis, RiBSplineBasis, RiCatmullRomBasis,
// RiHermiteBasis and RiPowerBasis. Hermite geometry is (point0, vector0, point1, vector1).

PatchBasis BezierBasis() {
    return {Imath::M44f(-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0), 3};
}

PatchBasis BSplineBasis() {
    Imath::M44f m(-1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0);
    return {m * (1.0f / 6.0f), 1};
}

PatchBasis CatmullRomBasis() {
    Imath::M44f m(-1, 3, -3, 1, 2, -5, 4, -1, -1, 0, 1, 0, 0, 2, 0, 0);
    return {m * 0.5f, 1};
}

PatchBasis HermiteBasis() {
    return {Imath::M44f(2, 1, -2, 1, -3, -2, 3, -1, 0, 1, 0, 0, 1, 0, 0, 0), 2};
}

PatchBasis PowerBasis() { return {Imath::M44f(), 4}; }

std::optional<PatchBasis> NamedBasis(const std::string& name) {
    if (name == "bezier") return BezierBasis();
    if (name == "b-spline") return BSplineBasis();
    if (name == "catmull-rom") return CatmullRomBasis();
    if (name == "hermite") return HermiteBasis();
    if (name == "power") return PowerBasis();
    return std::nullopt;
}

std::array<float, 4> BasisWeights(const Imath::M44f& m, float t) {
    const float powers[4] = {t * t * t, t * t, t, 1.0f};
    std::array<float, 4> w{};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) w[j] += powers[i] * m[i][j];
    return w;
}

Imath::M44f BezierFromBasis(const Imath::M44f& matrix) {
    // T·M·G = T·Mb·(Mb⁻¹·M·G), so the Bézier geometry is Mb⁻¹·M·G. Mb⁻¹ written out exactly
    // rather than inverted in floating point.
    const float third = 1.0f / 3.0f;
    const Imath::M44f bezierInverse(0, 0, 0, 1, 0, 0, third, 1, 0, third, 2 * third, 1, 1, 1, 1, 1);
    return bezierInverse * matrix;
}

}  // namespace gonio
