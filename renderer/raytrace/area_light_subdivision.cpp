#include "renderer/raytrace/area_light_subdivision.h"

#include <algorithm>
#include <map>
#include <utility>

namespace gonio {
namespace {

constexpr int kLevels = 3;  // a quad becomes 64 quads, 128 triangles

struct PolygonMesh {
    std::vector<V3f> points;
    std::vector<std::vector<uint32_t>> faces;
    std::vector<uint32_t> origin;  // the cage face each face descends from
};

struct Edges {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> index;
    std::vector<std::pair<uint32_t, uint32_t>> ends;
    std::vector<std::vector<uint32_t>> faces;  // one (boundary) or two
};

std::pair<uint32_t, uint32_t> Key(uint32_t a, uint32_t b) {
    return {std::min(a, b), std::max(a, b)};
}

Edges FindEdges(const PolygonMesh& mesh) {
    Edges edges;
    for (uint32_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        for (size_t i = 0; i < face.size(); ++i) {
            const auto key = Key(face[i], face[(i + 1) % face.size()]);
            auto [it, added] = edges.index.emplace(key, uint32_t(edges.ends.size()));
            if (added) edges.ends.push_back(key), edges.faces.emplace_back();
            edges.faces[it->second].push_back(f);
        }
    }
    return edges;
}

// Per vertex: the sums the Catmull-Clark vertex rule and the limit rule need.
struct Ring {
    V3f faceSum{0}, edgeMidSum{0}, neighbourSum{0}, boundarySum{0};
    int faces = 0, edges = 0, boundaryEdges = 0;
};

std::vector<Ring> Rings(const PolygonMesh& mesh, const Edges& edges,
                        const std::vector<V3f>& facePoints) {
    std::vector<Ring> rings(mesh.points.size());
    for (uint32_t f = 0; f < mesh.faces.size(); ++f)
        for (uint32_t v : mesh.faces[f]) rings[v].faceSum += facePoints[f], ++rings[v].faces;
    for (size_t e = 0; e < edges.ends.size(); ++e) {
        const auto [a, b] = edges.ends[e];
        const V3f mid = 0.5f * (mesh.points[a] + mesh.points[b]);
        for (auto [v, other] : {std::pair{a, b}, std::pair{b, a}}) {
            Ring& r = rings[v];
            r.edgeMidSum += mid, r.neighbourSum += mesh.points[other], ++r.edges;
            if (edges.faces[e].size() == 1) r.boundarySum += mesh.points[other], ++r.boundaryEdges;
        }
    }
    return rings;
}

// A boundary vertex follows the B-spline curve of its boundary; one in a single face is a
// corner and stays (Embree's pinned corners).
V3f VertexPoint(const V3f& v, const Ring& r) {
    if (r.boundaryEdges == 2) return r.faces == 1 ? v : (r.boundarySum + 6.f * v) / 8;
    if (r.boundaryEdges > 0 || r.edges < 3) return v;  // non-manifold: left where it is
    const float n = float(r.edges);
    return (r.faceSum / float(r.faces) + 2.f * r.edgeMidSum / n + (n - 3) * v) / n;
}

PolygonMesh Refine(const PolygonMesh& mesh) {
    const Edges edges = FindEdges(mesh);
    std::vector<V3f> facePoints;
    for (const auto& face : mesh.faces) {
        V3f sum(0);
        for (uint32_t v : face) sum += mesh.points[v];
        facePoints.push_back(sum / float(face.size()));
    }
    const std::vector<Ring> rings = Rings(mesh, edges, facePoints);
    PolygonMesh out;
    for (size_t v = 0; v < mesh.points.size(); ++v)
        out.points.push_back(VertexPoint(mesh.points[v], rings[v]));
    const uint32_t edgeBase = uint32_t(out.points.size());
    for (size_t e = 0; e < edges.ends.size(); ++e) {
        const auto [a, b] = edges.ends[e];
        V3f p = mesh.points[a] + mesh.points[b];
        if (edges.faces[e].size() == 2)
            p = (p + facePoints[edges.faces[e][0]] + facePoints[edges.faces[e][1]]) / 4;
        else
            p /= 2;
        out.points.push_back(p);
    }
    for (uint32_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        const uint32_t centre = uint32_t(out.points.size());
        out.points.push_back(facePoints[f]);
        const size_t k = face.size();
        for (size_t i = 0; i < k; ++i) {
            const uint32_t next = edgeBase + edges.index.at(Key(face[i], face[(i + 1) % k]));
            const uint32_t prev = edgeBase + edges.index.at(Key(face[(i + k - 1) % k], face[i]));
            out.faces.push_back({face[i], next, centre, prev});
            out.origin.push_back(mesh.origin[f]);
        }
    }
    return out;
}

// Every vertex of an all-quad mesh moved to the limit surface.
std::vector<V3f> LimitPositions(const PolygonMesh& mesh) {
    const Edges edges = FindEdges(mesh);
    std::vector<V3f> diagonalSum(mesh.points.size(), V3f(0));
    for (const auto& face : mesh.faces)
        for (size_t i = 0; i < 4; ++i) diagonalSum[face[i]] += mesh.points[face[(i + 2) % 4]];
    const std::vector<Ring> rings = Rings(mesh, edges, std::vector<V3f>(mesh.faces.size(), V3f(0)));
    std::vector<V3f> limit(mesh.points.size());
    for (size_t v = 0; v < mesh.points.size(); ++v) {
        const Ring& r = rings[v];
        const V3f& p = mesh.points[v];
        if (r.boundaryEdges == 2)
            limit[v] = r.faces == 1 ? p : (r.boundarySum + 4.f * p) / 6;
        else if (r.boundaryEdges > 0 || r.edges < 3)
            limit[v] = p;
        else {
            const float n = float(r.edges);
            limit[v] = (n * n * p + 4.f * r.neighbourSum + diagonalSum[v]) / (n * (n + 5));
        }
    }
    return limit;
}

// Cage faces that are not rendered: holes, and without "interpolateboundary" every face with a
// vertex on the boundary.
std::vector<bool> DroppedFaces(const SubdivisionCage& cage, const PolygonMesh& mesh) {
    std::vector<bool> dropped(mesh.faces.size(), false);
    for (uint32_t f : cage.holeFaces)
        if (f < dropped.size()) dropped[f] = true;
    if (cage.interpolateBoundary) return dropped;
    const Edges edges = FindEdges(mesh);
    std::vector<bool> onBoundary(mesh.points.size(), false);
    for (size_t e = 0; e < edges.ends.size(); ++e)
        if (edges.faces[e].size() == 1)
            onBoundary[edges.ends[e].first] = onBoundary[edges.ends[e].second] = true;
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        for (uint32_t v : mesh.faces[f])
            if (onBoundary[v]) dropped[f] = true;
    return dropped;
}

}  // namespace

TriangleMesh SubdivisionLimitMesh(const SubdivisionCage& cage) {
    PolygonMesh mesh;
    mesh.points = cage.positions;
    size_t next = 0;
    for (uint32_t count : cage.faceVertexCounts) {
        if (next + count > cage.indices.size()) break;
        mesh.origin.push_back(uint32_t(mesh.faces.size()));
        mesh.faces.emplace_back(cage.indices.begin() + next, cage.indices.begin() + next + count);
        next += count;
    }
    const std::vector<bool> dropped = DroppedFaces(cage, mesh);
    for (int level = 0; level < kLevels; ++level) mesh = Refine(mesh);
    TriangleMesh out;
    out.positions = LimitPositions(mesh);
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        if (dropped[mesh.origin[f]]) continue;
        const auto& q = mesh.faces[f];
        for (uint32_t i : {q[0], q[1], q[2], q[0], q[2], q[3]}) out.indices.push_back(i);
    }
    return out;
}

}  // namespace gonio
