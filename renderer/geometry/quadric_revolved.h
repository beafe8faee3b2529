#pragma once
// The machinery shared by every RISpec §5.4 quadric: a profile curve L(v) swept about the z axis
// by θ = u·thetamax, P(u,v) = Rz(θ)·L(v). Each shape supplies its profile, the roots of its
// implicit equation along a ray, and the inverse map from a surface point back to v; this base
// turns those into Intersect (with the θ clipping), Evaluate and Bounds. Internal to
// quadric_*.cpp and quadrics.cpp; the renderer only sees Quadric (shape.h) and quadrics.h.

#include <Imath/ImathVec.h>

#include <vector>

#include "geometry/shape.h"

namespace gonio::quadric {

using Imath::V2d;
using Imath::V3d;

constexpr double kPi = 3.14159265358979323846;

inline double Radians(double degrees) { return degrees * (kPi / 180); }
// +1 for zero, so that a degenerate factor never zeroes a normal.
inline double SignOf(double x) { return x < 0 ? -1.0 : 1.0; }

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

// A profile point that can sweep onto a given surface point: its v, and its own polar angle
// atan2(L.y, L.x) (0 or π for profiles in the xz plane), from which the sweep angle follows.
struct ProfileCandidate {
    double v = 0, angle = 0;
};

// The implicit surface λ·(x² + y²) = α·w² + β·w + γ with w = z − z0: the form shared by the
// sphere, the paraboloid and the swept lines (cylinder, cone, disk, hyperboloid).
struct RevolutionQuadric {
    double lambda = 1, alpha = 0, beta = 0, gamma = 0, z0 = 0;

    // The ray parameters in (lo, hi) where o + t·d meets the surface, ascending.
    int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[2]) const;
};

class RevolvedQuadric : public Quadric {
  public:
    Box3f Bounds() const final { return bounds_; }
    bool Intersect(const V3f& org, const V3f& dir, float tmin, float tmax,
                   QuadricHit* hit) const final;
    SurfaceGeometry Evaluate(float u, float v) const final;

  protected:
    explicit RevolvedQuadric(double thetamaxDegrees);

    virtual ProfilePoint Profile(double v) const = 0;
    // Where the ray o + t·d (o already moved near the shape) meets the whole unclipped surface,
    // for t in (lo, hi), ascending; at most 4.
    virtual int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[4]) const = 0;
    // The profile points with v in [0, 1] whose sweep passes through the surface point p (at
    // most 2: a profile may meet one circle twice).
    virtual int ProfileCandidates(const V3d& p, ProfileCandidate c[2]) const = 0;

    // Derived constructors end with one of these. The surface lies inside the sweep of the
    // profile points `extremes` (x, y before the sweep), for z in [zlo, zhi].
    void SetExtent(const std::vector<V2d>& extremes, double zlo, double zhi);
    void SetDegenerate();  // a surface of zero area: never hit

    double thetaMax_;  // radians, signed
    bool degenerate_ = false;

  private:
    bool ThetaParameter(const V3d& p, double profileAngle, double* u) const;

    bool fullSweep_;
    V3d center_{0, 0, 0};
    Box3f bounds_;
};

}  // namespace gonio::quadric
