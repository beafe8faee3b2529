#pragma once
// An independent answer for CSG along a ray: each primitive's inside as an exact interval of
// the ray parameter (ellipsoids by the quadratic formula, boxes by slabs, in double), combined
// by interval algebra, with each interval end remembering which primitive bounds it. The same
// tree writes itself as RIB, so that the renderer and the oracle see one scene.

#include <Imath/ImathVec.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace gonio::test {

using V3d = Imath::V3d;

// A closed primitive: an axis-aligned ellipsoid (a unit Sphere scaled by `size` about `centre`)
// or an axis-aligned box (PointsPolygons, its half extents `size`).
struct Primitive {
    enum class Kind { Ellipsoid, Box } kind = Kind::Ellipsoid;
    V3d centre{0}, size{1};
};

struct CsgTree {
    std::string operation;  // "primitive" (a leaf), "union", "intersection", "difference"
    Primitive primitive;
    std::vector<CsgTree> children;
};

inline CsgTree Leaf(Primitive::Kind kind, V3d centre, V3d size) {
    return {"primitive", {kind, centre, size}, {}};
}
inline CsgTree Sphere(V3d centre, double radius) {
    return Leaf(Primitive::Kind::Ellipsoid, centre, V3d(radius));
}
inline CsgTree Op(std::string operation, std::vector<CsgTree> children) {
    return {std::move(operation), {}, std::move(children)};
}

// One end of an inside interval: where, and the primitive whose surface it is (its index in
// the tree's leaves, depth first).
struct End {
    double t;
    int leaf;
};
struct Interval {
    End in, out;
};
using Intervals = std::vector<Interval>;

// The leaf's own inside interval along org + t·dir, if the ray meets it.
inline std::optional<Interval> PrimitiveInterval(const Primitive& p, int leaf, const V3d& org,
                                                 const V3d& dir) {
    const V3d o = org - p.centre;
    if (p.kind == Primitive::Kind::Ellipsoid) {
        const V3d os(o.x / p.size.x, o.y / p.size.y, o.z / p.size.z);
        const V3d ds(dir.x / p.size.x, dir.y / p.size.y, dir.z / p.size.z);
        const double a = ds.dot(ds), b = 2 * os.dot(ds), c = os.dot(os) - 1;
        const double disc = b * b - 4 * a * c;
        if (disc <= 0) return std::nullopt;
        const double root = std::sqrt(disc);
        return Interval{{(-b - root) / (2 * a), leaf}, {(-b + root) / (2 * a), leaf}};
    }
    double t0 = -std::numeric_limits<double>::infinity();
    double t1 = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0) {
            if (std::fabs(o[axis]) >= p.size[axis]) return std::nullopt;
            continue;
        }
        double a = (-p.size[axis] - o[axis]) / dir[axis], b = (p.size[axis] - o[axis]) / dir[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    if (t0 >= t1) return std::nullopt;
    return Interval{{t0, leaf}, {t1, leaf}};
}

inline Intervals Unite(const Intervals& a, const Intervals& b) {
    Intervals all = a;
    all.insert(all.end(), b.begin(), b.end());
    std::sort(all.begin(), all.end(),
              [](const Interval& x, const Interval& y) { return x.in.t < y.in.t; });
    Intervals out;
    for (const Interval& i : all) {
        if (!out.empty() && i.in.t <= out.back().out.t) {
            if (i.out.t > out.back().out.t) out.back().out = i.out;
        } else {
            out.push_back(i);
        }
    }
    return out;
}

inline Intervals Intersect(const Intervals& a, const Intervals& b) {
    Intervals out;
    for (const Interval& x : a)
        for (const Interval& y : b) {
            const End in = x.in.t > y.in.t ? x.in : y.in;
            const End out2 = x.out.t < y.out.t ? x.out : y.out;
            if (in.t < out2.t) out.push_back({in, out2});
        }
    std::sort(out.begin(), out.end(),
              [](const Interval& p, const Interval& q) { return p.in.t < q.in.t; });
    return out;
}

// a minus b: what of each interval of a no interval of b covers; b's ends become its ends.
inline Intervals Subtract(const Intervals& a, const Intervals& b) {
    Intervals out;
    for (Interval x : a) {
        std::vector<Interval> pieces{x};
        for (const Interval& y : b) {
            std::vector<Interval> next;
            for (const Interval& p : pieces) {
                if (y.out.t <= p.in.t || y.in.t >= p.out.t) {
                    next.push_back(p);
                    continue;
                }
                if (y.in.t > p.in.t) next.push_back({p.in, y.in});
                if (y.out.t < p.out.t) next.push_back({y.out, p.out});
            }
            pieces = std::move(next);
        }
        out.insert(out.end(), pieces.begin(), pieces.end());
    }
    return out;
}

inline Intervals Evaluate(const CsgTree& tree, const V3d& org, const V3d& dir, int* leaf) {
    if (tree.operation == "primitive") {
        const std::optional<Interval> i = PrimitiveInterval(tree.primitive, (*leaf)++, org, dir);
        return i ? Intervals{*i} : Intervals{};
    }
    Intervals result;
    for (size_t k = 0; k < tree.children.size(); ++k) {
        const Intervals child = Evaluate(tree.children[k], org, dir, leaf);
        if (k == 0)
            result = child;
        else if (tree.operation == "union")
            result = Unite(result, child);
        else if (tree.operation == "intersection")
            result = Intersect(result, child);
        else
            result = Subtract(result, child);
    }
    return result;
}

inline std::vector<Primitive> Leaves(const CsgTree& tree) {
    if (tree.operation == "primitive") return {tree.primitive};
    std::vector<Primitive> out;
    for (const CsgTree& child : tree.children) {
        const std::vector<Primitive> more = Leaves(child);
        out.insert(out.end(), more.begin(), more.end());
    }
    return out;
}

// The first point of the combined solid's surface at t >= tnear: its t, the primitive it lies
// on, and whether the ray enters the solid there.
struct Boundary {
    double t;
    int leaf;
    bool entering;
};

inline std::optional<Boundary> FirstBoundary(const CsgTree& tree, const V3d& org, const V3d& dir,
                                             double tnear) {
    int leaf = 0;
    for (const Interval& i : Evaluate(tree, org, dir, &leaf)) {
        if (i.in.t >= tnear) return Boundary{i.in.t, i.in.leaf, true};
        if (i.out.t >= tnear) return Boundary{i.out.t, i.out.leaf, false};
    }
    return std::nullopt;
}

// How near the line of the ray passes to touching the primitive's surface without crossing it
// (about a length): a ray this close to a tangent, or to a box's edge, may hit or miss in float.
inline double SurfaceMargin(const Primitive& p, const V3d& org, const V3d& dir) {
    const V3d o = org - p.centre;
    if (p.kind == Primitive::Kind::Ellipsoid) {
        const V3d os(o.x / p.size.x, o.y / p.size.y, o.z / p.size.z);
        const V3d ds = V3d(dir.x / p.size.x, dir.y / p.size.y, dir.z / p.size.z).normalized();
        const double distance = (os - os.dot(ds) * ds).length();  // from the centre, scaled
        return std::fabs(distance - 1) * std::min({p.size.x, p.size.y, p.size.z});
    }
    // The slabs' entries and exits: the ray grazes an edge where the last entry and the first
    // exit nearly meet, on either side.
    double t0 = -std::numeric_limits<double>::infinity();
    double t1 = std::numeric_limits<double>::infinity();
    double parallel = std::numeric_limits<double>::infinity();  // along a face's plane
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0) {
            parallel = std::min(parallel, std::fabs(std::fabs(o[axis]) - p.size[axis]));
            continue;
        }
        double a = (-p.size[axis] - o[axis]) / dir[axis], b = (p.size[axis] - o[axis]) / dir[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    return std::min(parallel, std::fabs(t1 - t0) * dir.length());
}

// How near the ray comes to being undecidable in float: the smallest distance between two of
// its crossings of primitive surfaces, the shortest inside interval, or the nearest miss of a
// surface (SurfaceMargin).
inline double NearestCrossingGap(const CsgTree& tree, const V3d& org, const V3d& dir) {
    std::vector<double> ts;
    double gap = std::numeric_limits<double>::infinity();
    int leaf = 0;
    for (const Primitive& p : Leaves(tree)) {
        gap = std::min(gap, SurfaceMargin(p, org, dir));
        const std::optional<Interval> i = PrimitiveInterval(p, leaf++, org, dir);
        if (!i) continue;
        ts.push_back(i->in.t), ts.push_back(i->out.t);
        gap = std::min(gap, i->out.t - i->in.t);
    }
    for (size_t a = 0; a < ts.size(); ++a)
        for (size_t b = a + 1; b < ts.size(); ++b) gap = std::min(gap, std::fabs(ts[a] - ts[b]));
    return gap;
}

// The primitive's outward normal at a point of its surface.
inline V3d OutwardNormal(const Primitive& p, const V3d& point) {
    const V3d o = point - p.centre;
    if (p.kind == Primitive::Kind::Ellipsoid)
        return V3d(o.x / (p.size.x * p.size.x), o.y / (p.size.y * p.size.y),
                   o.z / (p.size.z * p.size.z))
            .normalized();
    int axis = 0;
    double best = -1;
    for (int k = 0; k < 3; ++k) {
        const double closeness = std::fabs(o[k]) / p.size[k];
        if (closeness > best) best = closeness, axis = k;
    }
    V3d n(0);
    n[axis] = o[axis] > 0 ? 1 : -1;
    return n;
}

// The tree as RIB (SolidBegin blocks; boxes as PointsPolygons, each face wound so that its
// geometric normal (p1 − p0) × (p2 − p0) points out of the box).
// `explicitPrimitives` false: a leaf inside an operation is written as its bare geometry, a
// primitive solid of its own.
inline void WriteRib(const CsgTree& tree, std::ostringstream& rib, bool explicitPrimitives) {
    const bool block = tree.operation != "primitive" || explicitPrimitives;
    if (block) rib << "SolidBegin \"" << tree.operation << "\"\n";
    if (tree.operation == "primitive") {
        const Primitive& p = tree.primitive;
        rib << "TransformBegin\nTranslate " << p.centre.x << ' ' << p.centre.y << ' ' << p.centre.z
            << "\n";
        if (p.kind == Primitive::Kind::Ellipsoid) {
            rib << "Scale " << p.size.x << ' ' << p.size.y << ' ' << p.size.z
                << "\nSphere 1 -1 1 360\n";
        } else {
            rib << "Scale " << p.size.x << ' ' << p.size.y << ' ' << p.size.z
                << "\nPointsPolygons [4 4 4 4 4 4] [0 2 3 1  4 5 7 6  0 1 5 4  2 6 7 3  0 4 6 2"
                   "  1 3 7 5] \"P\" [-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1"
                   "  1 1 1]\n";
        }
        rib << "TransformEnd\n";
    }
    for (const CsgTree& child : tree.children) WriteRib(child, rib, explicitPrimitives);
    if (block) rib << "SolidEnd\n";
}

inline std::string Rib(const CsgTree& tree, bool explicitPrimitives = true) {
    std::ostringstream rib;
    WriteRib(tree, rib, explicitPrimitives);
    return rib.str();
}

}  // namespace gonio::test
