#include "renderer/scene/solid_closure.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <unordered_map>
#include <variant>

namespace gonio {
namespace {

// Welds vertices that coincide in world space (within a millionth of the surfaces' size) and
// counts how many faces each edge between welded vertices bounds.
class EdgeCounter {
  public:
    explicit EdgeCounter(float cell) : cell_(cell) {}

    // One face: its corners in world space, in order around it.
    void AddFace(const std::vector<V3f>& corners) {
        for (size_t i = 0; i < corners.size(); ++i) {
            const uint32_t a = Weld(corners[i]), b = Weld(corners[(i + 1) % corners.size()]);
            if (a != b) ++edges_[a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a)];
        }
    }
    bool EveryEdgeEven() const {
        for (const auto& [edge, faces] : edges_)
            if (faces % 2 != 0) return false;
        return true;
    }

  private:
    uint32_t Weld(const V3f& p) {
        const auto key = std::make_tuple(std::llround(p.x / cell_), std::llround(p.y / cell_),
                                         std::llround(p.z / cell_));
        return vertices_.emplace(key, uint32_t(vertices_.size())).first->second;
    }

    float cell_;
    std::map<std::tuple<long long, long long, long long>, uint32_t> vertices_;
    std::unordered_map<uint64_t, int> edges_;
};

V3f World(const SceneShape& shape, const V3f& p) {
    return p * shape.worldFromObject;  // Imath's row vectors: world = object · M
}

void AddFaces(const SceneShape& shape, EdgeCounter* counter) {
    std::vector<V3f> corners;
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
        for (size_t i = 0; i + 2 < mesh->indices.size(); i += 3) {
            corners.clear();
            for (int k = 0; k < 3; ++k)
                corners.push_back(World(shape, mesh->positions[mesh->indices[i + k]]));
            counter->AddFace(corners);
        }
        return;
    }
    const auto& cage = std::get<SubdivisionCage>(shape.geometry);
    std::vector<bool> hole(cage.faceVertexCounts.size(), false);
    for (uint32_t face : cage.holeFaces)
        if (face < hole.size()) hole[face] = true;
    size_t first = 0;
    for (size_t face = 0; face < cage.faceVertexCounts.size(); ++face) {
        const uint32_t n = cage.faceVertexCounts[face];
        corners.clear();
        for (uint32_t k = 0; k < n && first + k < cage.indices.size(); ++k)
            corners.push_back(World(shape, cage.positions[cage.indices[first + k]]));
        if (!hole[face]) counter->AddFace(corners);
        first += n;
    }
}

bool IsMesh(const SceneShape& shape) {
    return std::holds_alternative<TriangleMesh>(shape.geometry) ||
           std::holds_alternative<SubdivisionCage>(shape.geometry);
}

}  // namespace

Closure Enclosure(const std::vector<const SceneShape*>& surfaces) {
    bool allMeshes = true;
    for (const SceneShape* shape : surfaces) {
        if (std::holds_alternative<CurveSet>(shape->geometry) ||
            std::holds_alternative<PointSet>(shape->geometry))
            return Closure::Open;
        allMeshes &= IsMesh(*shape);
    }
    if (surfaces.size() == 1) {
        if (const auto* quadric = std::get_if<QuadricShape>(&surfaces.front()->geometry))
            return quadric->closed ? Closure::Closed : Closure::Open;
    }
    if (!allMeshes) return Closure::Unknown;
    Box3f bounds;
    for (const SceneShape* shape : surfaces) {
        const auto* mesh = std::get_if<TriangleMesh>(&shape->geometry);
        for (const V3f& p :
             mesh ? mesh->positions : std::get<SubdivisionCage>(shape->geometry).positions)
            bounds.extendBy(World(*shape, p));
    }
    const float size = bounds.isEmpty() ? 0.f : (bounds.max - bounds.min).length();
    EdgeCounter counter(size > 0 ? 1e-6f * size : 1.f);
    for (const SceneShape* shape : surfaces) AddFaces(*shape, &counter);
    return counter.EveryEdgeEven() ? Closure::Closed : Closure::Open;
}

}  // namespace gonio
