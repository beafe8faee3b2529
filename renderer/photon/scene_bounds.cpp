#include "renderer/photon/scene_bounds.h"

#include "base/overloaded.h"

namespace gonio {
namespace {

using Imath::Box3f;
using Imath::V3f;

void ExtendByPoints(const std::vector<V3f>& points, float pad, const M44f& m, Box3f* box) {
    for (const V3f& p : points) {
        V3f world;
        m.multVecMatrix(p, world);
        box->extendBy(world - V3f(pad));
        box->extendBy(world + V3f(pad));
    }
}

float MaxOf(const std::vector<float>& values) {
    float m = 0;
    for (float v : values) m = std::max(m, v);
    return m;
}

// Radii are in object space; a uniform pad of the largest radius scaled by the largest
// row norm of the transform is conservative for any affine map.
float ScaledPad(float radius, const M44f& m) {
    float scale = 0;
    for (int i = 0; i < 3; ++i) scale = std::max(scale, V3f(m[i][0], m[i][1], m[i][2]).length());
    return radius * scale;
}

void ExtendByShape(const SceneShape& shape, const M44f& worldFromObject, Box3f* box) {
    std::visit(
        Overloaded{
            [&](const TriangleMesh& mesh) {
                ExtendByPoints(mesh.positions, 0, worldFromObject, box);
            },
            [&](const QuadricShape& quadric) {
                const Box3f b = quadric.quadric->Bounds();
                std::vector<V3f> corners;
                for (int i = 0; i < 8; ++i)
                    corners.emplace_back((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                         (i & 4) ? b.max.z : b.min.z);
                ExtendByPoints(corners, 0, worldFromObject, box);
            },
            [&](const SubdivisionCage& cage) {
                ExtendByPoints(cage.positions, 0, worldFromObject, box);
            },
            [&](const CurveSet& curves) {
                ExtendByPoints(curves.controlPoints,
                               ScaledPad(MaxOf(curves.radii), worldFromObject), worldFromObject,
                               box);
            },
            [&](const PointSet& points) {
                ExtendByPoints(points.centers, ScaledPad(MaxOf(points.radii), worldFromObject),
                               worldFromObject, box);
            },
        },
        shape.geometry);
}

}  // namespace

Box3f WorldBounds(const Frame& frame) {
    Box3f box;
    for (const SceneShape& shape : frame.shapes) ExtendByShape(shape, shape.worldFromObject, &box);
    for (const ObjectInstanceUse& use : frame.instances) {
        for (const SceneShape& shape : use.definition->shapes)
            ExtendByShape(shape, shape.worldFromObject * use.worldFromDefinition, &box);
    }
    return box;
}

}  // namespace gonio
