#include "renderer/raytrace/area_light_geometry.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "renderer/raytrace/area_light_subdivision.h"
#include "renderer/raytrace/transforms.h"

namespace gonio {
namespace {

using Imath::M44f;
using Imath::V3f;

// Quadric cells: 256 bands in v keep the linear area element within (π/256)²/8 ≈ 2e-5 of a
// sphere's cos φ; a non-similarity transform makes the element depend on u, so u gets 64
// columns.
constexpr int kBandsV = 256;
constexpr int kColumnsU = 64;

// A similarity (rotation, reflection, uniform scale) keeps a quadric's area element
// independent of u, since the quadric is symmetric about its z axis.
bool IsSimilarity(const M44f& m) {
    const V3f a(m[0][0], m[0][1], m[0][2]), b(m[1][0], m[1][1], m[1][2]),
        c(m[2][0], m[2][1], m[2][2]);
    const float s = a.length2(), tolerance = 1e-5f * s;
    return std::abs(b.length2() - s) <= tolerance && std::abs(c.length2() - s) <= tolerance &&
           std::abs(a.dot(b)) <= tolerance && std::abs(a.dot(c)) <= tolerance &&
           std::abs(b.dot(c)) <= tolerance;
}

// The world area element |∂P/∂u × ∂P/∂v| of a quadric at (u, v).
float AreaElement(const Quadric& q, const M44f& worldFromObject, float u, float v) {
    const SurfaceGeometry g = q.Evaluate(u, v);
    return TransformVector(worldFromObject, g.dPdu)
        .cross(TransformVector(worldFromObject, g.dPdv))
        .length();
}

// A sample of the density on [0, 1] that runs linearly from a to b (a, b ≥ 0, not both 0),
// by inverting its CDF in the form that stays accurate when a ≈ b.
float SampleLinear(float xi, float a, float b) {
    const float denominator = a + std::sqrt(std::max(0.f, (1 - xi) * a * a + xi * b * b));
    if (!(denominator > 0)) return xi;
    return std::min(xi * (a + b) / denominator, std::nextafter(1.f, 0.f));
}

// Orientation "inside" and its handedness reverse the normal (SceneShape::flipNormals).
float FlipSign(const SceneShape& shape) { return shape.flipNormals ? -1.f : 1.f; }

}  // namespace

AreaLightGeometry AreaLightGeometry::Build(const Frame& frame, const SceneLight& light) {
    AreaLightGeometry geometry;
    for (size_t index : light.shapes) {
        if (index >= frame.shapes.size()) continue;
        const SceneShape& shape = frame.shapes[index];
        std::visit(
            [&](const auto& g) {
                using T = std::decay_t<decltype(g)>;
                if constexpr (std::is_same_v<T, TriangleMesh>) {
                    geometry.AddMesh(g, shape);
                } else if constexpr (std::is_same_v<T, QuadricShape>) {
                    geometry.AddQuadric(g, shape);
                } else if constexpr (std::is_same_v<T, SubdivisionCage>) {
                    geometry.AddMesh(SubdivisionLimitMesh(g), shape);
                }
                // CurveSet, PointSet: never recorded as light geometry (see the header).
            },
            shape.geometry);
    }
    return geometry;
}

void AreaLightGeometry::AddPieceArea(float area) {
    area_ += area;
    cumulative_.push_back(area_);
}

void AreaLightGeometry::AddMesh(const TriangleMesh& mesh, const SceneShape& shape) {
    const M44f& m = shape.worldFromObject;  // a moving shape's first placement
    // (Ma × Mb) = det(M)·M⁻ᵀ(a × b): the world cross product is the transformed object normal
    // up to det(M)'s sign.
    const float sign = FlipSign(shape) * (m.determinant() < 0 ? -1.f : 1.f);
    for (size_t t = 0; t < mesh.TriangleCount(); ++t) {
        const V3f p0 = TransformPoint(m, mesh.positions[mesh.indices[3 * t]]);
        const V3f e1 = TransformPoint(m, mesh.positions[mesh.indices[3 * t + 1]]) - p0;
        const V3f e2 = TransformPoint(m, mesh.positions[mesh.indices[3 * t + 2]]) - p0;
        const V3f cross = e1.cross(e2);
        const float area = 0.5f * cross.length();
        if (!(area > 0) || !std::isfinite(area)) continue;
        triangles_.push_back({p0, e1, e2, sign * Normalized(cross)});
        AddPieceArea(area);
    }
}

void AreaLightGeometry::AddQuadric(const QuadricShape& shape, const SceneShape& scene) {
    const M44f& m = scene.worldFromObject;
    const uint32_t index = uint32_t(quadrics_.size());
    quadrics_.push_back({shape.quadric, m, m.inverse(), FlipSign(scene)});
    // Triangles come first in cumulative_ (Sample relies on it): quadric cells follow them.
    const int columns = IsSimilarity(m) ? 1 : kColumnsU;
    const float du = 1.f / columns, dv = 1.f / kBandsV;
    for (int i = 0; i < columns; ++i) {
        const float uc = (i + 0.5f) * du;
        float jLow = AreaElement(*shape.quadric, m, uc, 0);
        for (int k = 0; k < kBandsV; ++k) {
            const float jHigh = AreaElement(*shape.quadric, m, uc, (k + 1) * dv);
            // The cell's area under the element linear in v (trapezoid rule).
            const float area = 0.5f * (jLow + jHigh) * du * dv;
            if (area > 0 && std::isfinite(area)) {
                cells_.push_back({index, i * du, du, k * dv, dv, jLow, jHigh});
                AddPieceArea(area);
            }
            jLow = jHigh;
        }
    }
}

AreaLightSample AreaLightGeometry::Sample(float u0, float u1, float u2) const {
    if (Empty()) return {V3f(0), V3f(0, 0, 1), 0};
    const float target = u0 * area_;
    size_t piece = size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) -
                          cumulative_.begin());
    piece = std::min(piece, cumulative_.size() - 1);
    if (piece < triangles_.size()) return SampleTriangle(triangles_[piece], u1, u2);
    return SampleCell(cells_[piece - triangles_.size()], u1, u2);
}

// Uniform on the triangle by folding the unit square onto it (pbrt-v4 §6.5.4's simpler
// cousin): the reflected half keeps the density uniform.
AreaLightSample AreaLightGeometry::SampleTriangle(const Triangle& t, float u1, float u2) const {
    float b1 = u1, b2 = u2;
    if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
    return {t.p0 + b1 * t.e1 + b2 * t.e2, t.N, 1 / area_};
}

// u uniform across the cell, v with density linear between the area elements at the cell's
// edges; the density per unit area is then ℓ(v) / (Area · J(u, v)), J the true element.
AreaLightSample AreaLightGeometry::SampleCell(const QuadricCell& cell, float u1, float u2) const {
    const PlacedQuadric& q = quadrics_[cell.quadric];
    const float t = SampleLinear(u2, cell.jLow, cell.jHigh);
    const float u = cell.u0 + u1 * cell.du, v = cell.v0 + t * cell.dv;
    const SurfaceGeometry g = q.quadric->Evaluate(u, v);
    const V3f dPdu = TransformVector(q.worldFromObject, g.dPdu),
              dPdv = TransformVector(q.worldFromObject, g.dPdv);
    const float linear = (1 - t) * cell.jLow + t * cell.jHigh;
    const float element = dPdu.cross(dPdv).length();
    const float pdf = element > 0 ? linear / (area_ * element) : 1 / area_;
    return {TransformPoint(q.worldFromObject, g.P),
            q.sign * Normalized(TransformNormal(q.objectFromWorld, g.Ng)), pdf};
}

}  // namespace gonio
