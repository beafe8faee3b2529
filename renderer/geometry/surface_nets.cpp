#include "renderer/geometry/surface_nets.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace gonio {

namespace {

using Index3 = std::array<int, 3>;

// The sampling grid, stored by blocks: cells of side `cell` from `origin`, n[a] cells (n[a] + 1
// points) along axis a, in blocks of kSurfaceNetsBlock³ points and cells. A block owns the
// points and cells whose indices divided by the block size give its own; only blocks the
// field may cross hold storage, every point of the others reads as outside (−1).
class BlockGrid {
  public:
    static constexpr int B = kSurfaceNetsBlock;

    BlockGrid(const Box3f& box, float cell) : cell_(cell), origin_(box.min - V3f(cell)) {
        for (int a = 0; a < 3; ++a) {
            n_[a] = std::max(1, int(std::ceil((box.max[a] - box.min[a]) / cell))) + 2;
            blocks_[a] = n_[a] / B + 1;  // the last block owns point n[a]
        }
        slot_.assign(size_t(blocks_[0]) * blocks_[1] * blocks_[2], -1);
    }

    const Index3& Cells() const { return n_; }
    const Index3& Blocks() const { return blocks_; }
    float Cell() const { return cell_; }
    V3f Point(const Index3& p) const {
        return origin_ + cell_ * V3f(float(p[0]), float(p[1]), float(p[2]));
    }

    // The box of block b's cells (and its last points), grown by one cell: where its points
    // are sampled and its cells' vertices are placed.
    Box3f BlockBox(const Index3& b) const {
        Index3 lo, hi;
        for (int a = 0; a < 3; ++a) lo[a] = b[a] * B, hi[a] = std::min(lo[a] + B, n_[a]);
        return Box3f(Point(lo) - V3f(cell_), Point(hi) + V3f(cell_));
    }

    void Allocate(const Index3& b) {
        slot_[BlockIndex(b)] = int32_t(values_.size() / (B * B * B));
        values_.resize(values_.size() + B * B * B, -1.f);
        vertices_.resize(vertices_.size() + B * B * B, -1);
    }
    bool Allocated(const Index3& b) const { return slot_[BlockIndex(b)] >= 0; }

    // The value at point p (outside: −1 where no block holds it).
    float Value(const Index3& p) const {
        const long at = Offset(p);
        return at < 0 ? -1.f : values_[at];
    }
    float& ValueOf(const Index3& p) { return values_[Offset(p)]; }
    // The vertex of cell c, or −1.
    int32_t Vertex(const Index3& c) const {
        const long at = Offset(c);
        return at < 0 ? -1 : vertices_[at];
    }
    int32_t& VertexOf(const Index3& c) { return vertices_[Offset(c)]; }

  private:
    size_t BlockIndex(const Index3& b) const {
        return b[0] + size_t(blocks_[0]) * (b[1] + size_t(blocks_[1]) * b[2]);
    }
    long Offset(const Index3& p) const {
        const int32_t slot = slot_[BlockIndex({p[0] / B, p[1] / B, p[2] / B})];
        if (slot < 0) return -1;
        return long(slot) * B * B * B + p[0] % B + B * (p[1] % B + B * (p[2] % B));
    }

    float cell_;
    V3f origin_;
    Index3 n_{}, blocks_{};
    std::vector<int32_t> slot_;
    std::vector<float> values_;
    std::vector<int32_t> vertices_;
};

// Calls f(p) for every index p with lo ≤ p < hi.
template <class F>
void ForEach(const Index3& lo, const Index3& hi, F f) {
    Index3 p;
    for (p[2] = lo[2]; p[2] < hi[2]; ++p[2])
        for (p[1] = lo[1]; p[1] < hi[1]; ++p[1])
            for (p[0] = lo[0]; p[0] < hi[0]; ++p[0]) f(p);
}

// The points (cells when `cells`) block b owns.
void BlockRange(const BlockGrid& g, const Index3& b, bool cells, Index3* lo, Index3* hi) {
    for (int a = 0; a < 3; ++a) {
        (*lo)[a] = b[a] * BlockGrid::B;
        (*hi)[a] = std::min((*lo)[a] + BlockGrid::B, g.Cells()[a] + (cells ? 0 : 1));
    }
}

Index3 Offset(Index3 p, int c) {
    p[0] += c & 1, p[1] += c >> 1 & 1, p[2] += c >> 2;
    return p;
}

// The 12 edges of a cell as pairs of corner numbers (corner c is at offset (c&1, c>>1&1, c>>2)).
constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// The vertex of cell c if the surface crosses it: the mean of its edges' linear crossings, then
// Newton steps x ← x − F·∇F/|∇F|² onto F = 0 while they stay near the cell and bring F closer
// to 0.
void AddCellVertex(const IsoEvaluator& evaluate, BlockGrid* g, const Index3& cell, IsoMesh* mesh) {
    float corner[8];
    V3f at[8];
    int inside = 0;
    for (int c = 0; c < 8; ++c) {
        corner[c] = g->Value(Offset(cell, c));
        at[c] = g->Point(Offset(cell, c));
        inside += corner[c] > 0;
    }
    if (inside == 0 || inside == 8) return;
    V3f x(0);
    int crossings = 0;
    for (const auto& e : kEdges) {
        const float a = corner[e[0]], b = corner[e[1]];
        if ((a > 0) == (b > 0)) continue;
        x += at[e[0]] + (a / (a - b)) * (at[e[1]] - at[e[0]]);
        ++crossings;
    }
    x /= float(crossings);
    const Box3f near(at[0] - V3f(g->Cell()), at[7] + V3f(g->Cell()));
    float value;
    V3f grad, position = x, gradient;
    evaluate(x, &value, &grad);
    gradient = grad;
    float best = std::fabs(value);
    for (int step = 0; step < 8 && best > 0; ++step) {
        const float g2 = grad.length2();
        if (!(g2 > 0)) break;
        x -= (value / g2) * grad;
        if (!near.intersects(x)) break;
        evaluate(x, &value, &grad);
        if (!(std::fabs(value) < best)) break;
        best = std::fabs(value);
        position = x, gradient = grad;
    }
    g->VertexOf(cell) = int32_t(mesh->positions.size());
    mesh->positions.push_back(position);
    mesh->gradients.push_back(gradient);
}

// Two triangles for the quad q0 q1 q2 q3 (counter-clockwise about its normal), split along
// the shorter diagonal.
void AddQuad(const std::array<int32_t, 4>& q, const std::vector<V3f>& positions,
             std::vector<uint32_t>* indices) {
    const uint32_t a = q[0], b = q[1], c = q[2], d = q[3];
    if ((positions[a] - positions[c]).length2() <= (positions[b] - positions[d]).length2())
        indices->insert(indices->end(), {a, b, c, a, c, d});
    else
        indices->insert(indices->end(), {a, b, d, b, c, d});
}

// The quads of the grid edges from point p along each axis a that change sign. Each is shared
// by four cells, offset along the other two axes u, v (with u × v = a): their vertices make one
// quad facing F < 0.
void AddQuads(const BlockGrid& g, const Index3& p, IsoMesh* mesh) {
    const Index3& n = g.Cells();
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        if (p[a] >= n[a] || p[u] < 1 || p[v] < 1 || p[u] >= n[u] || p[v] >= n[v]) continue;
        Index3 next = p;
        ++next[a];
        const bool in0 = g.Value(p) > 0, in1 = g.Value(next) > 0;
        if (in0 == in1) continue;
        auto cellAt = [&](int du, int dv) {
            Index3 c = p;
            c[u] -= du, c[v] -= dv;
            return g.Vertex(c);
        };
        std::array<int32_t, 4> quad{cellAt(1, 1), cellAt(0, 1), cellAt(0, 0), cellAt(1, 0)};
        if (std::min({quad[0], quad[1], quad[2], quad[3]}) < 0) continue;  // cannot happen (step 3)
        if (!in0) std::swap(quad[1], quad[3]);                             // inside lies towards +a
        AddQuad(quad, mesh->positions, &mesh->indices);
    }
}

}  // namespace

IsoMesh PolygonizeSurfaceNets(const IsoField& field, const Box3f& box, float cell) {
    IsoMesh mesh;
    if (box.isEmpty() || !(cell > 0)) return mesh;
    BlockGrid g(box, cell);
    const Index3 zero{0, 0, 0};
    // 1. Sample the points of the blocks the field may cross. A point of a block without
    //    storage reads −1: that block's box (edges included) is outside for certain.
    std::vector<Index3> used;
    ForEach(zero, g.Blocks(), [&](const Index3& b) {
        const IsoEvaluator evaluate = field.near(g.BlockBox(b));
        if (!evaluate) return;
        g.Allocate(b);
        used.push_back(b);
        Index3 lo, hi;
        BlockRange(g, b, false, &lo, &hi);
        V3f unused;
        ForEach(lo, hi, [&](const Index3& p) { evaluate(g.Point(p), &g.ValueOf(p), &unused); });
        mesh.sampledPoints += long(hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    });
    // 2. One vertex per crossed cell. Corners come from the shared values, so a cell has a
    //    vertex exactly when an edge of it changes sign, which step 3 relies on; cells of
    //    blocks without storage are outside at every corner.
    for (const Index3& b : used) {
        const IsoEvaluator evaluate = field.near(g.BlockBox(b));
        Index3 lo, hi;
        BlockRange(g, b, true, &lo, &hi);
        ForEach(lo, hi, [&](const Index3& c) { AddCellVertex(evaluate, &g, c, &mesh); });
    }
    // 3. One quad per crossing edge; edges from points of blocks without storage stay inside
    //    such a block's box and cross nothing.
    for (const Index3& b : used) {
        Index3 lo, hi;
        BlockRange(g, b, false, &lo, &hi);
        ForEach(lo, hi, [&](const Index3& p) { AddQuads(g, p, &mesh); });
    }
    return mesh;
}

}  // namespace gonio
