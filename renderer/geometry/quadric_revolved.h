#pragma once
// The machinery shared by every RISpec §5.4 quadric: a profile curve L(v) swept about the z axis
// by θ = u·thetamax, P(u,v) = Rz(θ)·L(v). Each shape supplies its profile, the roots of its
// implicit equation along a ray, and the inverse map from a surface point back to v; this base
// turns those into Intersect (with the θ clipping), Evaluate and Bounds. Internal to
// quadric_*.cpp and quadrics.cpp; the renderer only sees Quadric (shape.h) and quadrics.h.

#include <Imath/ImathVec.h>

#include <vector>

#include "renderer/geometry/quadric_angles.h"
#include "renderer/geometry/quadric_roots.h"
#include "renderer/geometry/shape.h"

namespace gonio::quadric {

using Imath::V2d;
using Imath::V3d;

// The profile at one v, in the θ = 0 frame.
struct ProfilePoint {
    V3d L;     // the point before the sweep
    V3d dLdv;  // its derivative in v
    // A vector along cross(∂P/∂θ, ∂P/∂v) at θ = 0, i.e. along cross((-L.y, L.x, 0), dLdv),
    // with the factor that vanishes on the z axis divided out analytically so that poles and
    // apexes get the limit direction instead of a zero vector. Never NaN; zero only for a
    // degenerate surface.
    V3d normal;
};

// A profile point that can sweep onto a given surface point: its v, and the direction of its own
// xy part (±x for profiles in the xz plane; any positive multiple), from which the sweep angle
// follows.
struct ProfileCandidate {
    double v = 0;
    V2d along{1, 0};
};

// Whether x lies in [0, 1] give or take `slack`; if so, clamps it into [0, 1]. A point rounded
// to float lies slightly off its surface, so that its parameters may fall just outside the
// square: ParametersAt accepts them with a slack (NaN never passes).
inline bool ClampToUnit(double* x, double slack) {
    if (!(*x >= -slack && *x <= 1 + slack)) return false;
    *x = *x < 0 ? 0 : *x > 1 ? 1 : *x;
    return true;
}

// The implicit surface λ·(x² + y²) = α·w² + β·w + γ with w = z − z0: the form shared by the
// sphere, the paraboloid and the swept lines (cylinder, cone, disk, hyperboloid).
struct RevolutionQuadric {
    double lambda = 1, alpha = 0, beta = 0, gamma = 0, z0 = 0;

    // The gradient of λ·(x² + y²) − (α·w² + β·w + γ) at p: a normal of the surface there.
    V3d Gradient(const V3d& p) const {
        const double w = p.z - z0;
        return V3d(2 * lambda * p.x, 2 * lambda * p.y, -(2 * alpha * w + beta));
    }

    // The ray parameters in (lo, hi) where o + t·d meets the surface, ascending. Inline, with
    // SolveQuadratic: it is most of the work of every sphere, cylinder or cone test.
    int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[2]) const {
        // Substitute o + t·d into the implicit equation: c2·t² + c1·t + c0 = 0.
        const double w0 = o.z - z0;
        const double c2 = lambda * (d.x * d.x + d.y * d.y) - alpha * d.z * d.z;
        const double c1 = 2 * lambda * (o.x * d.x + o.y * d.y) - 2 * alpha * w0 * d.z - beta * d.z;
        const double c0 = lambda * (o.x * o.x + o.y * o.y) - (alpha * w0 + beta) * w0 - gamma;
        if (c2 >= 0 &&
            (MovesAwayOutside(c2, c1, c0, lo, 1) || MovesAwayOutside(c2, c1, c0, hi, -1)))
            return 0;
        double all[2];
        const int n = SolveQuadratic(c2, c1, c0, all);
        int kept = 0;
        for (int i = 0; i < n; ++i)
            if (all[i] > lo && all[i] < hi) t[kept++] = all[i];
        return kept;
    }

  private:
    // Whether the convex (c2 ≥ 0) f(t) = c2·t² + c1·t + c0 is positive at t (off the surface,
    // on the outer side of a cylinder or sphere) and not decreasing in the direction `sense`
    // (+1: towards larger t): f then stays positive on that whole side of t, so no root lies
    // there. A photon leaving a cylinder outwards meets this at its own and the neighbouring
    // cylinders, a beam at the cylinders behind its nearest hit so far; it costs a few products
    // instead of a square root and two divisions. Never true for an infinite t (f is then NaN,
    // or f' has the wrong sign).
    static bool MovesAwayOutside(double c2, double c1, double c0, double t, double sense) {
        return (c2 * t + c1) * t + c0 > 0 && sense * (2 * c2 * t + c1) >= 0;
    }
};

class RevolvedQuadric : public Quadric {
  public:
    Box3f Bounds() const final { return bounds_; }
    bool Intersect(const V3f& org, const V3f& dir, float tmin, float tmax,
                   QuadricHit* hit) const final;
    bool IntersectPoint(const V3f& org, const V3f& dir, float tmin, float tmax, float* t,
                        V3f* point) const final;
    const CompleteSphere* AsCompleteSphere() const final {
        return IsCompleteSphere() ? &completeSphere_ : nullptr;
    }
    V2f ParametersAt(const V3f& point) const final;
    V3f NormalAt(const V3f& point) const final;
    SurfaceGeometry Evaluate(float u, float v) const final;
    // Evaluate(ParametersAt(point)) for a point IntersectPoint reported, up to float rounding,
    // without the cosine and sine of θ: for a point on the sweep they are the direction of its
    // xy part from that of the profile point's. Points that needed ParametersAt's slack, and
    // points next to the axis where that direction is lost, go through Evaluate. A shape may
    // take a shorter way for its common case (the whole sphere).
    SurfaceGeometry EvaluateAt(const V3f& point) const override;

  protected:
    explicit RevolvedQuadric(double thetamaxDegrees);

    virtual ProfilePoint Profile(double v) const = 0;
    // The profile point at v whose sweep passes through the surface point p: Profile(v), or
    // the same derived from p by shapes whose profile costs trigonometry.
    virtual ProfilePoint ProfileThrough(const V3d& /*p*/, double v) const { return Profile(v); }
    // Where the ray o + t·d (o already moved near the shape) meets the whole unclipped surface,
    // for t in (lo, hi), ascending; at most 4.
    virtual int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[4]) const = 0;
    // The profile points with v in [0, 1] (give or take `slack`, then clamped: ClampToUnit)
    // whose sweep passes through the surface point p (at most 2: a profile may meet one circle
    // twice).
    virtual int ProfileCandidates(const V3d& p, double slack, ProfileCandidate c[2]) const = 0;
    // The `along` of ProfileCandidates(p, 0, ...): shapes whose v costs trigonometry decide
    // whether it lies in [0, 1] without it.
    virtual int ProfileDirections(const V3d& p, V2d along[2]) const;
    // The gradient of the implicit equation that RayRoots solves, at a point of the surface
    // (zero where it has none, as at a cone's apex).
    virtual V3d ImplicitGradient(const V3d& p) const = 0;

    // Derived constructors end with one of these. The surface lies inside the sweep of the
    // profile points `extremes` (x, y before the sweep), for z in [zlo, zhi].
    void SetExtent(const std::vector<V2d>& extremes, double zlo, double zhi);
    void SetDegenerate();  // a surface of zero area: never hit
    // A ball known to hold the surface, tighter than the box's (SetExtent's default): rays that
    // pass it are rejected with a cross product, before any division.
    void SetBoundingBall(const V3d& centre, double radius);
    // Every point of the implicit surface that RayRoots solves lies on the profile's sweep (a
    // full sphere, a full torus tube): with a full sweep, a root is a hit without computing
    // its (u, v).
    void SetProfileComplete() { everyRootOnShape_ = fullSweep_; }
    // The implicit surface that RayRoots solves is the sphere of this radius about the origin,
    // which is then also the bounding ball: IntersectPoint finds its roots from the ball test's
    // cross product (the robust form of Haines et al., Ray Tracing Gems ch. 7), without
    // calling RayRoots or testing the cylinder about the axis.
    void SetSphericalSurface(double radius);
    // The roots of the spherical surface (SetSphericalSurface) along o + t·d for t in (lo, hi),
    // ascending, o being the ray's point nearest the centre: `missed2` = |w × d|² for any w
    // from the centre to the ray, dd = |d|².
    int SphereRoots(double missed2, double dd, double lo, double hi, double t[2]) const;

    // Whether every root of RayRoots is a hit (SetProfileComplete with a full sweep).
    bool EveryRootOnShape() const { return everyRootOnShape_; }
    // The surface point of `profile` swept by the angle whose cosine and sine are c and s.
    SurfaceGeometry Sweep(const ProfilePoint& profile, double c, double s, float u, float v) const;
    // u for the surface point p swept from a profile point whose xy part points along `along`,
    // if it lies within the sweep (give or take `slack` radians, then moved onto the nearer
    // edge).
    bool ThetaParameter(const V3d& p, const V2d& along, double slack, double* u) const;

    double thetaMax_;  // radians, signed
    bool degenerate_ = false;

  private:
    bool OnShape(const V3d& p) const;
    bool IsCompleteSphere() const { return spherical_ && everyRootOnShape_ && !degenerate_; }
    // The (u, v) of the surface point p (see ParametersAt), in *u, *v; returns the slack that
    // it took (0: p lies on the shape as IntersectPoint decided), or −1 where none did.
    double FindParameters(const V3d& p, double* u, double* v) const;

    bool fullSweep_;
    AngleRange sweep_;  // the directions of the sweep, from the profile's own
    bool everyRootOnShape_ = false;
    bool spherical_ = false;
    double sphereRadius2_ = 0;
    CompleteSphere completeSphere_{};  // the spherical surface and its ball
    V3d center_{0, 0, 0};
    Box3f bounds_;
    V3d ballCentre_{0, 0, 0};
    double ballRadius2_ = 0;
    double rhoMax2_ = 0;  // the largest distance of the surface from the z axis, squared
};

}  // namespace gonio::quadric
