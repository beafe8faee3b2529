#include "renderer/geometry/polygons.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "renderer/geometry/primvar_eval.h"

namespace gonio {
namespace {

// Twice the signed area of triangle abc: positive when a, b, c turn counter-clockwise.
float Cross(const V2f& a, const V2f& b, const V2f& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

float SignedArea(const std::vector<V2f>& pts, const std::vector<int>& loop) {
    float area = 0;
    for (size_t i = 0; i < loop.size(); ++i) {
        const V2f& a = pts[loop[i]];
        const V2f& b = pts[loop[(i + 1) % loop.size()]];
        area += a.x * b.y - a.y * b.x;
    }
    return 0.5f * area;
}

// True when the open segments ab and cd cross at a single interior point.
bool SegmentsCross(const V2f& a, const V2f& b, const V2f& c, const V2f& d) {
    const float d1 = Cross(a, b, c), d2 = Cross(a, b, d);
    const float d3 = Cross(c, d, a), d4 = Cross(c, d, b);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Whether the direction from v towards x starts inside the polygon's interior angle at v, for a
// counter-clockwise ring with neighbours prev and next.
bool LocallyInside(const V2f& prev, const V2f& v, const V2f& next, const V2f& x) {
    const bool leftOfOut = Cross(v, next, x) >= 0;
    const bool leftOfIn = Cross(prev, v, x) >= 0;
    return Cross(prev, v, next) >= 0 ? (leftOfOut && leftOfIn) : (leftOfOut || leftOfIn);
}

bool InTriangle(const V2f& a, const V2f& b, const V2f& c, const V2f& p) {
    return Cross(a, b, p) >= 0 && Cross(b, c, p) >= 0 && Cross(c, a, p) >= 0;
}

// Ear clipping with holes, after Eberly, "Triangulation by Ear Clipping" (2002): each hole is
// joined to the outline by a bridge edge that crosses no other edge, turning the polygon with
// holes into one weakly simple ring that ear clipping handles.
class EarClipper {
  public:
    explicit EarClipper(std::vector<V2f> pts) : pts_(std::move(pts)) {}

    std::vector<std::array<uint32_t, 3>> Run(std::vector<int> outline,
                                             std::vector<std::vector<int>> holes) {
        const float outlineArea = SignedArea(pts_, outline);
        if (!(outlineArea > 0)) return {};
        // Turns smaller than this are rounding noise of (nearly) collinear vertices: such a
        // vertex is dropped without a triangle rather than clipped as a sliver whose winding
        // rounding may have flipped.
        const float tinyArea = outlineArea * 1e-7f;
        flatTurn_ = 2 * tinyArea;
        std::vector<std::vector<int>> kept;
        for (auto& hole : holes) {
            if (hole.size() < 3) continue;
            const float area = SignedArea(pts_, hole);
            if (std::abs(area) <= tinyArea) continue;
            // Bridging needs holes clockwise, opposite to the outline.
            if (area > 0) std::reverse(hole.begin(), hole.end());
            kept.push_back(std::move(hole));
        }
        ring_ = std::move(outline);
        holes_ = std::move(kept);
        // Rightmost holes first, so that bridges of later holes can reach past them.
        std::sort(holes_.begin(), holes_.end(),
                  [&](const auto& a, const auto& b) { return MaxX(a) > MaxX(b); });
        for (size_t h = 0; h < holes_.size(); ++h) BridgeHole(h);
        return ClipEars();
    }

  private:
    float MaxX(const std::vector<int>& loop) const {
        float m = -INFINITY;
        for (int i : loop) m = std::max(m, pts_[i].x);
        return m;
    }

    bool Same(int a, int b) const { return pts_[a] == pts_[b]; }

    // Whether segment m–v crosses an edge of the ring or of a hole not yet bridged.
    bool BridgeBlocked(int m, int v, size_t firstOpenHole) const {
        auto crossesLoop = [&](const std::vector<int>& loop) {
            for (size_t i = 0; i < loop.size(); ++i) {
                const int a = loop[i], b = loop[(i + 1) % loop.size()];
                if (Same(a, m) || Same(b, m) || Same(a, v) || Same(b, v)) continue;
                if (SegmentsCross(pts_[m], pts_[v], pts_[a], pts_[b])) return true;
            }
            return false;
        };
        if (crossesLoop(ring_)) return true;
        for (size_t h = firstOpenHole; h < holes_.size(); ++h)
            if (crossesLoop(holes_[h])) return true;
        return false;
    }

    void BridgeHole(size_t h) {
        const std::vector<int>& hole = holes_[h];
        size_t mPos = 0;
        for (size_t i = 1; i < hole.size(); ++i)
            if (pts_[hole[i]].x > pts_[hole[mPos]].x) mPos = i;
        const int m = hole[mPos];
        const V2f& holePrev = pts_[hole[(mPos + hole.size() - 1) % hole.size()]];
        const V2f& holeNext = pts_[hole[(mPos + 1) % hole.size()]];

        std::vector<size_t> order(ring_.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            return (pts_[ring_[a]] - pts_[m]).length2() < (pts_[ring_[b]] - pts_[m]).length2();
        });
        // The nearest visible ring vertex; the nearest of all if the input is too tangled to
        // have one (the result then overlaps itself but still covers the polygon).
        size_t bridge = order.front();
        const size_t n = ring_.size();
        for (size_t r : order) {
            const int v = ring_[r];
            const V2f& prev = pts_[ring_[(r + n - 1) % n]];
            const V2f& next = pts_[ring_[(r + 1) % n]];
            if (!LocallyInside(prev, pts_[v], next, pts_[m])) continue;
            if (!LocallyInside(holePrev, pts_[m], holeNext, pts_[v])) continue;
            if (BridgeBlocked(m, v, h)) continue;
            bridge = r;
            break;
        }
        std::vector<int> merged(ring_.begin(), ring_.begin() + bridge + 1);
        for (size_t i = 0; i <= hole.size(); ++i) merged.push_back(hole[(mPos + i) % hole.size()]);
        merged.insert(merged.end(), ring_.begin() + bridge, ring_.end());
        ring_ = std::move(merged);
    }

    bool IsEar(int prev, int v, int next, const std::vector<int>& prevOf,
               const std::vector<int>& nextOf) const {
        const V2f &a = pts_[ring_[prev]], &b = pts_[ring_[v]], &c = pts_[ring_[next]];
        if (Cross(a, b, c) <= flatTurn_) return false;
        for (int i = nextOf[next]; i != prev; i = nextOf[i]) {
            const int p = ring_[i];
            // Bridge duplicates of the ear's own corners may touch it without blocking it.
            if (Same(p, ring_[prev]) || Same(p, ring_[v]) || Same(p, ring_[next])) continue;
            // Only reflex vertices can lie inside an ear of a simple polygon.
            if (Cross(pts_[ring_[prevOf[i]]], pts_[p], pts_[ring_[nextOf[i]]]) > 0) continue;
            if (InTriangle(a, b, c, pts_[p])) return false;
        }
        return true;
    }

    std::vector<std::array<uint32_t, 3>> ClipEars() {
        const int n = static_cast<int>(ring_.size());
        std::vector<std::array<uint32_t, 3>> tris;
        if (n < 3) return tris;
        std::vector<int> prevOf(n), nextOf(n);
        for (int i = 0; i < n; ++i) {
            prevOf[i] = (i + n - 1) % n;
            nextOf[i] = (i + 1) % n;
        }
        auto remove = [&](int v) {
            nextOf[prevOf[v]] = nextOf[v];
            prevOf[nextOf[v]] = prevOf[v];
        };
        auto emit = [&](int a, int b, int c) {
            tris.push_back({static_cast<uint32_t>(ring_[a]), static_cast<uint32_t>(ring_[b]),
                            static_cast<uint32_t>(ring_[c])});
        };
        int remaining = n, v = 0, sinceLastClip = 0;
        while (remaining > 3) {
            const int prev = prevOf[v], next = nextOf[v];
            const float turn = Cross(pts_[ring_[prev]], pts_[ring_[v]], pts_[ring_[next]]);
            // Collinear, or a zero-width spike: nothing to emit.
            const bool flat = std::abs(turn) <= flatTurn_;
            if (flat || IsEar(prev, v, next, prevOf, nextOf)) {
                if (!flat) emit(prev, v, next);
                remove(v);
                --remaining;
                v = next;
                sinceLastClip = 0;
                continue;
            }
            v = next;
            if (++sinceLastClip > remaining) {
                // No ear: the ring intersects itself. Clip a convex corner anyway so that the
                // loop ends; stop if none is left (the rest has no positive area).
                int convex = -1;
                for (int i = nextOf[v], k = 0; k < remaining; i = nextOf[i], ++k)
                    if (Cross(pts_[ring_[prevOf[i]]], pts_[ring_[i]], pts_[ring_[nextOf[i]]]) > 0) {
                        convex = i;
                        break;
                    }
                if (convex < 0) return tris;
                emit(prevOf[convex], convex, nextOf[convex]);
                remove(convex);
                --remaining;
                v = nextOf[convex];
                sinceLastClip = 0;
            }
        }
        if (Cross(pts_[ring_[prevOf[v]]], pts_[ring_[v]], pts_[ring_[nextOf[v]]]) > flatTurn_)
            emit(prevOf[v], v, nextOf[v]);
        return tris;
    }

    std::vector<V2f> pts_;
    std::vector<int> ring_;
    std::vector<std::vector<int>> holes_;
    float flatTurn_ = 0;
};

// The faces of a PointsGeneralPolygons, checked: nloops per face, nverts per loop, and corner
// indices into P.
struct FaceLayout {
    const std::vector<int>& nloops;
    const std::vector<int>& nverts;
    const std::vector<int>& vertices;
};

std::optional<std::string> CheckLayout(const FaceLayout& f, size_t pointCount) {
    size_t loops = 0, corners = 0;
    for (int n : f.nloops) {
        if (n < 1)
            return std::string("every face needs at least one loop, got ") + std::to_string(n);
        loops += n;
    }
    if (loops != f.nverts.size())
        return "the faces have " + std::to_string(loops) + " loops in all but nverts has " +
               std::to_string(f.nverts.size()) + " entries";
    for (int n : f.nverts) {
        if (n < 0) return "a loop has a negative vertex count (" + std::to_string(n) + ")";
        corners += n;
    }
    if (corners != f.vertices.size())
        return "the loops have " + std::to_string(corners) + " vertices in all but " +
               std::to_string(f.vertices.size()) + " vertex indices were given";
    for (int v : f.vertices)
        if (v < 0 || static_cast<size_t>(v) >= pointCount)
            return "vertex index " + std::to_string(v) + " is out of range (P has " +
                   std::to_string(pointCount) + " values)";
    return std::nullopt;
}

V3f AnyPerpendicular(const V3f& n) {
    const V3f axis = std::abs(n.x) < 0.6f ? V3f(1, 0, 0) : V3f(0, 1, 0);
    return (axis - n * axis.dot(n)).normalize();
}

// Appends `var` at the corners listed in `corners` (three per triangle).
std::vector<float> GatherCorners(const PrimVar& var, const std::vector<uint32_t>& corners,
                                 bool perFace, const std::vector<uint32_t>& faceOfTriangle) {
    std::vector<float> out;
    out.reserve(corners.size() * var.components);
    for (size_t i = 0; i < corners.size(); ++i) {
        const int src = perFace ? static_cast<int>(faceOfTriangle[i / 3]) : corners[i];
        const float* v = var.Value(src);
        out.insert(out.end(), v, v + var.components);
    }
    return out;
}

void AttachNormals(const PrimVar& n, const std::vector<uint32_t>& corners, TriangleMesh* mesh) {
    auto toV3 = [](const float* v) { return V3f(v[0], v[1], v[2]); };
    switch (n.decl.cls) {
        case ParamClass::Constant:
            mesh->normals.assign(mesh->positions.size(), toV3(n.Value(0)));
            break;
        case ParamClass::Varying:
        case ParamClass::Vertex:
            for (int i = 0; i < n.ValueCount(); ++i) mesh->normals.push_back(toV3(n.Value(i)));
            break;
        case ParamClass::Uniform:
        case ParamClass::FaceVarying:
        case ParamClass::FaceVertex: {
            const bool perFace = n.decl.cls == ParamClass::Uniform;
            const std::vector<float> v = GatherCorners(n, corners, perFace, mesh->faceOfTriangle);
            for (size_t i = 0; i + 2 < v.size(); i += 3)
                mesh->cornerNormals.push_back(V3f(v[i], v[i + 1], v[i + 2]));
            break;
        }
    }
}

void AttachVars(const PrimVarSet& vars, const std::vector<uint32_t>& corners, TriangleMesh* mesh) {
    for (const PrimVar& var : vars.vars) {
        if (IsPositionVar(var.decl.name)) continue;
        if (var.decl.name == "N" && var.components == 3) {
            AttachNormals(var, corners, mesh);
            continue;
        }
        switch (var.decl.cls) {
            case ParamClass::Constant:
            case ParamClass::Uniform:
                mesh->vars.push_back(UnchangedMeshVar(var));
                break;
            case ParamClass::Varying:
            case ParamClass::Vertex:
                mesh->vars.push_back({var, MeshRate::PerVertex});
                break;
            case ParamClass::FaceVarying:
            case ParamClass::FaceVertex:
                mesh->vars.push_back(
                    {WithValues(var, GatherCorners(var, corners, false, mesh->faceOfTriangle)),
                     MeshRate::PerCorner});
                break;
        }
    }
}

}  // namespace

V3f NewellNormal(const std::vector<V3f>& loop) {
    if (loop.empty()) return V3f(0);
    // About the centroid, so that far-from-origin polygons keep their precision.
    V3f c(0);
    for (const V3f& p : loop) c += p;
    c /= static_cast<float>(loop.size());
    V3f n(0);
    for (size_t i = 0; i < loop.size(); ++i)
        n += (loop[i] - c).cross(loop[(i + 1) % loop.size()] - c);
    return n;
}

std::vector<std::array<uint32_t, 3>> TriangulateLoops(const std::vector<V3f>& points,
                                                      const std::vector<int>& loopSizes) {
    if (loopSizes.empty() || loopSizes[0] < 3) return {};
    const std::vector<V3f> outline(points.begin(), points.begin() + loopSizes[0]);
    if (loopSizes.size() == 1 && loopSizes[0] == 3) {
        if (NewellNormal(outline).length2() == 0) return {};
        return {{0, 1, 2}};
    }
    V3f n = NewellNormal(outline);
    if (!(n.length2() > 0)) return {};
    n.normalize();
    // In the frame (t, b) with t × b = n the outline runs counter-clockwise.
    const V3f t = AnyPerpendicular(n), b = n.cross(t);
    // Relative to the first vertex, so that polygons far from the origin keep their precision.
    std::vector<V2f> flat(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const V3f p = points[i] - points[0];
        flat[i] = V2f(p.dot(t), p.dot(b));
    }

    std::vector<int> ring(loopSizes[0]);
    std::iota(ring.begin(), ring.end(), 0);
    std::vector<std::vector<int>> holes;
    int start = loopSizes[0];
    for (size_t l = 1; l < loopSizes.size(); ++l) {
        std::vector<int> hole(loopSizes[l]);
        std::iota(hole.begin(), hole.end(), start);
        start += loopSizes[l];
        holes.push_back(std::move(hole));
    }
    return EarClipper(std::move(flat)).Run(std::move(ring), std::move(holes));
}

GeometryResult<TriangleMesh> MakePointsGeneralPolygons(const std::vector<int>& nloops,
                                                       const std::vector<int>& nverts,
                                                       const std::vector<int>& vertices,
                                                       const PrimVarSet& vars) {
    using Result = GeometryResult<TriangleMesh>;
    std::string error;
    std::optional<std::vector<V3f>> positions = ReadPositions(vars, &error);
    if (!positions) return Result::Error(error);
    if (auto bad = CheckLayout({nloops, nverts, vertices}, positions->size()))
        return Result::Error(*bad);
    const int pointCount = static_cast<int>(positions->size());
    const ClassCounts counts{static_cast<int>(nloops.size()), pointCount, pointCount,
                             static_cast<int>(vertices.size())};
    if (auto bad = CheckCounts(vars, counts)) return Result::Error(*bad);

    TriangleMesh mesh;
    mesh.positions = std::move(*positions);
    std::vector<uint32_t> corners;  // the facevarying index of each triangle corner
    size_t loop = 0, corner = 0;
    std::vector<V3f> facePoints;
    std::vector<int> loopSizes;
    for (size_t face = 0; face < nloops.size(); ++face) {
        facePoints.clear();
        loopSizes.clear();
        const size_t firstCorner = corner;
        for (int l = 0; l < nloops[face]; ++l, ++loop) {
            loopSizes.push_back(nverts[loop]);
            for (int k = 0; k < nverts[loop]; ++k, ++corner)
                facePoints.push_back(mesh.positions[vertices[corner]]);
        }
        for (const auto& tri : TriangulateLoops(facePoints, loopSizes)) {
            for (uint32_t local : tri) {
                corners.push_back(static_cast<uint32_t>(firstCorner + local));
                mesh.indices.push_back(static_cast<uint32_t>(vertices[firstCorner + local]));
            }
            mesh.faceOfTriangle.push_back(static_cast<uint32_t>(face));
        }
    }
    AttachVars(vars, corners, &mesh);
    return mesh;
}

GeometryResult<TriangleMesh> MakePointsPolygons(const std::vector<int>& nverts,
                                                const std::vector<int>& vertices,
                                                const PrimVarSet& vars) {
    return MakePointsGeneralPolygons(std::vector<int>(nverts.size(), 1), nverts, vertices, vars);
}

GeometryResult<TriangleMesh> MakeGeneralPolygon(const std::vector<int>& nverts,
                                                const PrimVarSet& vars) {
    const int total = std::accumulate(nverts.begin(), nverts.end(), 0);
    std::vector<int> vertices(std::max(total, 0));
    std::iota(vertices.begin(), vertices.end(), 0);
    return MakePointsGeneralPolygons({static_cast<int>(nverts.size())}, nverts, vertices, vars);
}

GeometryResult<TriangleMesh> MakePolygon(const PrimVarSet& vars) {
    std::string error;
    const std::optional<std::vector<V3f>> positions = ReadPositions(vars, &error);
    if (!positions) return GeometryResult<TriangleMesh>::Error(error);
    return MakeGeneralPolygon({static_cast<int>(positions->size())}, vars);
}

}  // namespace gonio
