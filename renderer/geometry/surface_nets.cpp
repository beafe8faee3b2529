#include "renderer/geometry/surface_nets.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace gonio {

namespace {

constexpr int kBlock = 8;  // cells per block side: the unit of skipping

// The sampling grid: cells of side `cell` from `origin`, n[a] cells along axis a.
struct Grid {
    V3f origin;
    float cell = 1;
    std::array<int, 3> n{};

    long PointIndex(int i, int j, int k) const {
        return i + long(n[0] + 1) * (j + long(n[1] + 1) * k);
    }
    long CellIndex(int i, int j, int k) const { return i + long(n[0]) * (j + long(n[1]) * k); }
    V3f Point(int i, int j, int k) const {
        return origin + cell * V3f(float(i), float(j), float(k));
    }
    long PointCount() const { return long(n[0] + 1) * (n[1] + 1) * (n[2] + 1); }
    long CellCount() const { return long(n[0]) * n[1] * n[2]; }
};

// The 12 edges of a cell as pairs of corner numbers (corner c is at offset (c&1, c>>1&1, c>>2)).
constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// The cell's vertex: the mean of its edges' linear crossings, then Newton steps
// x ← x − F·∇F/|∇F|² onto F = 0 while they stay near the cell and bring F closer to 0.
void CellVertex(const IsoEvaluator& evaluate, const Grid& g, const std::vector<float>& values,
                int i, int j, int k, V3f* position, V3f* gradient) {
    float corner[8];
    V3f at[8];
    for (int c = 0; c < 8; ++c) {
        const int ci = i + (c & 1), cj = j + (c >> 1 & 1), ck = k + (c >> 2);
        corner[c] = values[g.PointIndex(ci, cj, ck)];
        at[c] = g.Point(ci, cj, ck);
    }
    V3f sum(0);
    int crossings = 0;
    for (const auto& e : kEdges) {
        const float a = corner[e[0]], b = corner[e[1]];
        if ((a > 0) == (b > 0)) continue;
        const float t = a / (a - b);
        sum += at[e[0]] + t * (at[e[1]] - at[e[0]]);
        ++crossings;
    }
    V3f x = sum / float(crossings);
    const Box3f near(at[0] - V3f(g.cell), at[7] + V3f(g.cell));
    float value;
    V3f grad;
    evaluate(x, &value, &grad);
    *position = x, *gradient = grad;
    float best = std::fabs(value);
    for (int step = 0; step < 8 && best > 0; ++step) {
        const float g2 = grad.length2();
        if (!(g2 > 0)) break;
        x -= (value / g2) * grad;
        if (!near.intersects(x)) break;
        evaluate(x, &value, &grad);
        if (!(std::fabs(value) < best)) break;
        best = std::fabs(value);
        *position = x, *gradient = grad;
    }
}

// The vertex of cell (i, j, k) if the surface crosses it.
void AddCellVertex(const IsoEvaluator& evaluate, const Grid& g, const std::vector<float>& values,
                   int i, int j, int k, std::vector<int32_t>* vertexOfCell, IsoMesh* mesh) {
    int inside = 0;
    for (int c = 0; c < 8; ++c)
        inside += values[g.PointIndex(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2))] > 0;
    if (inside == 0 || inside == 8) return;
    V3f p, grad;
    CellVertex(evaluate, g, values, i, j, k, &p, &grad);
    (*vertexOfCell)[g.CellIndex(i, j, k)] = int32_t(mesh->positions.size());
    mesh->positions.push_back(p);
    mesh->gradients.push_back(grad);
}

// Two triangles for the quad q0 q1 q2 q3 (counter-clockwise about its normal), split along
// the shorter diagonal.
void AddQuad(const std::array<uint32_t, 4>& q, const std::vector<V3f>& positions,
             std::vector<uint32_t>* indices) {
    const float d02 = (positions[q[0]] - positions[q[2]]).length2();
    const float d13 = (positions[q[1]] - positions[q[3]]).length2();
    if (d02 <= d13)
        indices->insert(indices->end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    else
        indices->insert(indices->end(), {q[0], q[1], q[3], q[1], q[2], q[3]});
}

}  // namespace

IsoMesh PolygonizeSurfaceNets(const IsoField& field, const Box3f& box, float cell) {
    IsoMesh mesh;
    if (box.isEmpty() || !(cell > 0)) return mesh;
    Grid g;
    g.cell = cell;
    g.origin = box.min - V3f(cell);
    for (int a = 0; a < 3; ++a)
        g.n[a] = std::max(1, int(std::ceil((box.max[a] - box.min[a]) / cell))) + 2;
    // Block by block: sample the points not sampled yet, then place the vertices of the
    // block's cells (whose corners all lie in the block). Vertices stay within a cell of their
    // own cell, so the block's evaluator serves a box one cell larger.
    std::vector<float> values(g.PointCount(), -1.f);
    std::vector<uint8_t> sampled(values.size(), 0);
    std::vector<int32_t> vertexOfCell(g.CellCount(), -1);
    for (int bz = 0; bz < g.n[2]; bz += kBlock)
        for (int by = 0; by < g.n[1]; by += kBlock)
            for (int bx = 0; bx < g.n[0]; bx += kBlock) {
                const int ex = std::min(bx + kBlock, g.n[0]), ey = std::min(by + kBlock, g.n[1]),
                          ez = std::min(bz + kBlock, g.n[2]);
                const IsoEvaluator evaluate = field.near(
                    Box3f(g.Point(bx, by, bz) - V3f(cell), g.Point(ex, ey, ez) + V3f(cell)));
                if (!evaluate) continue;
                V3f unused;
                for (int k = bz; k <= ez; ++k)
                    for (int j = by; j <= ey; ++j)
                        for (int i = bx; i <= ex; ++i) {
                            const long index = g.PointIndex(i, j, k);
                            if (sampled[index]) continue;
                            evaluate(g.Point(i, j, k), &values[index], &unused);
                            sampled[index] = 1;
                            ++mesh.sampledPoints;
                        }
                for (int k = bz; k < ez; ++k)
                    for (int j = by; j < ey; ++j)
                        for (int i = bx; i < ex; ++i)
                            AddCellVertex(evaluate, g, values, i, j, k, &vertexOfCell, &mesh);
            }

    // Each grid edge along axis a that changes sign is shared by four cells, offset along the
    // other two axes u, v (with u × v = a): their vertices make one quad facing F < 0.
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        std::array<int, 3> p{};
        for (p[2] = 0; p[2] <= g.n[2]; ++p[2])
            for (p[1] = 0; p[1] <= g.n[1]; ++p[1])
                for (p[0] = 0; p[0] <= g.n[0]; ++p[0]) {
                    if (p[a] >= g.n[a] || p[u] < 1 || p[v] < 1 || p[u] >= g.n[u] || p[v] >= g.n[v])
                        continue;
                    std::array<int, 3> next = p;
                    ++next[a];
                    const bool in0 = values[g.PointIndex(p[0], p[1], p[2])] > 0;
                    const bool in1 = values[g.PointIndex(next[0], next[1], next[2])] > 0;
                    if (in0 == in1) continue;
                    auto cellAt = [&](int du, int dv) {
                        std::array<int, 3> c = p;
                        c[u] -= du, c[v] -= dv;
                        return uint32_t(vertexOfCell[g.CellIndex(c[0], c[1], c[2])]);
                    };
                    std::array<uint32_t, 4> quad{cellAt(1, 1), cellAt(0, 1), cellAt(0, 0),
                                                 cellAt(1, 0)};
                    if (!in0) std::swap(quad[1], quad[3]);  // inside lies towards +a
                    AddQuad(quad, mesh.positions, &mesh.indices);
                }
    }
    return mesh;
}

}  // namespace gonio
