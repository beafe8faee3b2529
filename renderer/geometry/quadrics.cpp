// Sphere, the swept lines (cylinder, cone, disk, hyperboloid) and the paraboloid: the quadrics
// whose implicit equation is quadratic. The torus is in quadric_torus.cpp.
#include "renderer/geometry/quadrics.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "renderer/geometry/quadric_revolved.h"
#include "renderer/geometry/quadric_roots.h"

namespace gonio {
namespace quadric {
namespace {

bool AllFinite(std::initializer_list<float> values) {
    return std::all_of(values.begin(), values.end(), [](float x) { return std::isfinite(x); });
}

class Sphere final : public RevolvedQuadric {
  public:
    Sphere(double radius, double zmin, double zmax, double thetamax)
        : RevolvedQuadric(thetamax), radius_(radius) {
        // RISpec: φmin = asin(zmin/r), or −90° where zmin ≤ −r (likewise φmax); clamping the
        // argument is the same thing for r > 0 and keeps [zmin, zmax] for r < 0.
        if (radius != 0) {
            phiMin_ = std::asin(std::clamp(zmin / radius, -1.0, 1.0));
            phiMax_ = std::asin(std::clamp(zmax / radius, -1.0, 1.0));
        }
        if (radius == 0 || phiMin_ == phiMax_) SetDegenerate();
        // atan2 below never leaves [−90°, 90°]: a full φ range takes every point of the sphere.
        if (std::fabs(phiMax_ - phiMin_) == kPi)
            SetProfileComplete();
        else
            phiRange_ = AngleRange(phiMin_, phiMax_ - phiMin_);

        const double lo = std::min(phiMin_, phiMax_), hi = std::max(phiMin_, phiMax_);
        const double cosMin = std::min(std::cos(lo), std::cos(hi));
        const double cosMax = lo <= 0 && hi >= 0 ? 1.0 : std::max(std::cos(lo), std::cos(hi));
        const double z0 = radius * std::sin(lo), z1 = radius * std::sin(hi);
        SetExtent({V2d(radius * cosMin, 0), V2d(radius * cosMax, 0)}, std::min(z0, z1),
                  std::max(z0, z1));
        SetSphericalSurface(radius);
        orientation_ = float(SignOf(thetaMax_) * SignOf(phiMax_ - phiMin_) * SignOf(radius));
    }

    // A whole sphere's hits, the renderer's common case, straight from the point: its one
    // profile candidate always holds (u, v), and the profile and sweep directions are those of
    // the point; exactly the (u, v) of ParametersAt, the rest as RevolvedQuadric::EvaluateAt
    // up to rounding, with fewer square roots and no search.
    SurfaceGeometry EvaluateAt(const V3f& point) const override {
        const V3d p(point.x, point.y, point.z);
        const double rho = std::sqrt(p.x * p.x + p.y * p.y), z = p.z * SignOf(radius_);
        const double distance = std::sqrt(rho * rho + z * z);
        // Partial spheres, and points near the poles (see ProfileThrough), the general way.
        if (!EveryRootOnShape() || !(rho > 0.05 * distance))
            return RevolvedQuadric::EvaluateAt(point);
        double u;
        ThetaParameter(p, ProfileSide(), 0, &u);  // always on a full sweep
        const double v = ParameterV(p, rho);      // in [0, 1] for a full φ range
        // P = Rz(θ)·L: the sweep's cos θ and sin θ are the direction of p's xy part from the
        // profile point's (ProfileSide).
        const double side = SignOf(radius_) / rho;
        return Sweep(ProfileAtAngle(rho / distance, z / distance), side * p.x, side * p.y, float(u),
                     float(v));
    }

    // Sweep's normal, sign(θmax)·Rz(θ)·profile.normal, is sign(θmax)·sign(φmax − φmin)·p/r
    // (ProfileAtAngle): the one thing camera hits that are not shaded need, without atan2.
    V3f OrientedNormalAt(const V3f& point) const override { return orientation_ * point; }

  protected:
    ProfilePoint Profile(double v) const override {
        const double phi = phiMin_ + v * (phiMax_ - phiMin_);
        return ProfileAtAngle(std::cos(phi), std::sin(phi));
    }

    ProfilePoint ProfileThrough(const V3d& p, double v) const override {
        // cos φ = ρ/|r| and sin φ = z/r, as in ProfileCandidates; divided by the point's own
        // distance from the centre, so that a point rounded off the sphere gives a unit pair.
        const double rho = std::sqrt(p.x * p.x + p.y * p.y), z = p.z * SignOf(radius_);
        const double distance = std::sqrt(rho * rho + z * z);
        // Near the poles v, rounded to float, no longer pins cos φ down to 1e-5: there the
        // point's profile would be more accurate than Evaluate's, but it must be the same.
        if (!(rho > 0.05 * distance)) return Profile(v);
        return ProfileAtAngle(rho / distance, z / distance);
    }

    // IntersectPoint solves the sphere itself (SetSphericalSurface); this is the same.
    int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[4]) const override {
        return SphereRoots(o.cross(d).length2(), d.dot(d), lo, hi, t);
    }

    int ProfileCandidates(const V3d& p, double slack, ProfileCandidate c[2]) const override {
        c[0] = {ParameterV(p, std::sqrt(p.x * p.x + p.y * p.y)), ProfileSide()};
        return ClampToUnit(&c[0].v, slack) ? 1 : 0;
    }

    int ProfileDirections(const V3d& p, V2d along[2]) const override {
        // φ in [φmin, φmax] without φ itself: (cos φ, sin φ) = (ρ/|r|, z/r) points along
        // (ρ, z·sign r).
        if (!phiRange_.Contains(std::sqrt(p.x * p.x + p.y * p.y), p.z * SignOf(radius_))) return 0;
        along[0] = ProfileSide();
        return 1;
    }

    V3d ImplicitGradient(const V3d& p) const override { return 2.0 * p; }

  private:
    // L.x = r·cos φ has the sign of r.
    V2d ProfileSide() const { return V2d(radius_ < 0 ? -1 : 1, 0); }

    // v of the surface point p at the distance rho from the axis (before ClampToUnit): sin φ =
    // z/r and cos φ = ρ/|r| ≥ 0; atan2 stays accurate near the poles.
    double ParameterV(const V3d& p, double rho) const {
        const double phi = Atan2(p.z * SignOf(radius_), rho);
        return (phi - phiMin_) / (phiMax_ - phiMin_);
    }

    ProfilePoint ProfileAtAngle(double c, double s) const {
        // cross((-L.y, L.x, 0), dLdv) = r²·(φmax − φmin)·cos φ·(cos φ, 0, sin φ), cos φ ≥ 0.
        return {radius_ * V3d(c, 0, s), radius_ * (phiMax_ - phiMin_) * V3d(-s, 0, c),
                SignOf(phiMax_ - phiMin_) * V3d(c, 0, s)};
    }

    double radius_, phiMin_ = 0, phiMax_ = 0;
    float orientation_ = 1;  // ±1: see OrientedNormalAt
    AngleRange phiRange_;    // (cos φ, sin φ) of the profile's points
};

// The surface swept by the segment point1 → point2: RISpec's hyperboloid, of which the
// cylinder, the cone and the disk are special cases with exactly the same (u, v).
class SweptLine final : public RevolvedQuadric {
  public:
    SweptLine(const V3d& point1, const V3d& point2, double thetamax)
        : RevolvedQuadric(thetamax),
          start_(point1),
          direction_(point2 - point1),
          inXZPlane_(point1.y == 0 && point2.y == 0) {
        const bool onAxis = point1.x == 0 && point1.y == 0 && point2.x == 0 && point2.y == 0;
        if (point1 == point2 || onAxis) SetDegenerate();
        // At height z the sweep is the circle of radius |a + b·w/dz| (a, b: the xy parts of
        // point1 and of the direction; w = z − z1). Times dz² so a nearly flat line stays
        // well scaled: dz²·(x² + y²) = |b|²·w² + 2·(a·b)·dz·w + |a|²·dz².
        const double dz = direction_.z;
        const double aa = start_.x * start_.x + start_.y * start_.y;
        const double ab = start_.x * direction_.x + start_.y * direction_.y;
        const double bb = direction_.x * direction_.x + direction_.y * direction_.y;
        implicit_ = {dz * dz, bb, 2 * ab * dz, aa * dz * dz, start_.z};
        SetExtent({V2d(point1.x, point1.y), V2d(point2.x, point2.y)}, std::min(point1.z, point2.z),
                  std::max(point1.z, point2.z));
    }

  protected:
    ProfilePoint Profile(double v) const override {
        const V3d L = start_ + v * direction_;
        const V3d& d = direction_;
        const double dxy = std::hypot(d.x, d.y);
        V3d normal(L.x * d.z, L.y * d.z, -(L.x * d.x + L.y * d.y));
        if (std::hypot(L.x, L.y) <= 1e-9 * dxy) {
            // On the axis (cone apex, disk centre): near it L.xy ≈ (v − v0)·d.xy, so the
            // normal tends to ±(d.x·dz, d.y·dz, −|d.xy|²), the sign that of v − v0 on the
            // side of the surface we come from.
            const double along = L.x * d.x + L.y * d.y;
            const double side = along != 0 ? SignOf(along) : (v < 1 ? 1.0 : -1.0);
            normal = side * V3d(d.x * d.z, d.y * d.z, -dxy * dxy);
        }
        return {L, d, normal};
    }

    int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[4]) const override {
        if (direction_.z != 0) return implicit_.RayRoots(o, d, lo, hi, t);
        // A horizontal line sweeps a planar annulus (the disk).
        if (d.z == 0) return 0;
        t[0] = (start_.z - o.z) / d.z;
        return t[0] > lo && t[0] < hi ? 1 : 0;
    }

    int ProfileCandidates(const V3d& p, double slack, ProfileCandidate c[2]) const override {
        if (direction_.z != 0) {
            double v = (p.z - start_.z) / direction_.z;
            if (!ClampToUnit(&v, slack)) return 0;
            c[0] = {v, AlongAt(v)};
            return 1;
        }
        // In the plane: the v where |a + v·b| equals the point's distance from the axis.
        const double aa = start_.x * start_.x + start_.y * start_.y;
        const double ab = start_.x * direction_.x + start_.y * direction_.y;
        const double bb = direction_.x * direction_.x + direction_.y * direction_.y;
        double roots[2];
        const int n = SolveQuadratic(bb, 2 * ab, aa - (p.x * p.x + p.y * p.y), roots);
        int kept = 0;
        for (int i = 0; i < n; ++i)
            if (ClampToUnit(&roots[i], slack)) c[kept++] = {roots[i], AlongAt(roots[i])};
        return kept;
    }

    V3d ImplicitGradient(const V3d& p) const override {
        // A horizontal line sweeps a planar annulus: RayRoots uses no implicit equation there.
        return direction_.z != 0 ? implicit_.Gradient(p) : V3d(0, 0, 1);
    }

  private:
    // The direction of the profile point's xy part, scaled by its larger coordinate so that the
    // products of InProfileFrame neither overflow nor underflow; +x on the axis.
    V2d AlongAt(double v) const {
        const V3d L = start_ + v * direction_;
        if (inXZPlane_) return V2d(L.x < 0 ? -1 : 1, 0);
        const double scale = std::max(std::fabs(L.x), std::fabs(L.y));
        return scale > 0 ? V2d(L.x / scale, L.y / scale) : V2d(1, 0);
    }

    V3d start_, direction_;
    bool inXZPlane_;  // the cylinder, cone and disk: every profile angle is 0 or π
    RevolutionQuadric implicit_;
};

class Paraboloid final : public RevolvedQuadric {
  public:
    Paraboloid(double rmax, double zmin, double zmax, double thetamax)
        : RevolvedQuadric(thetamax), rmax_(rmax), zmin_(zmin), zmax_(zmax) {
        if (rmax == 0 || zmax == 0 || zmin == zmax) SetDegenerate();
        implicit_ = {zmax, 0, rmax * rmax, 0, 0};  // zmax·(x² + y²) = rmax²·z
        std::vector<V2d> extremes = {V2d(Profile(0).L.x, 0), V2d(Profile(1).L.x, 0)};
        if (zmin * zmax < 0) extremes.push_back(V2d(0, 0));
        SetExtent(extremes, std::min(zmin, zmax), std::max(zmin, zmax));
    }

  protected:
    ProfilePoint Profile(double v) const override {
        const double z = zmin_ + v * (zmax_ - zmin_);
        // z/zmax < 0 lies off the surface; the formula collapses it onto the axis.
        const double q = zmax_ != 0 ? std::max(z / zmax_, 0.0) : 0.0;
        const double rho = rmax_ * std::sqrt(q);
        const double drhodz = zmax_ != 0 ? rmax_ / (2 * zmax_ * std::sqrt(std::max(q, 1e-12))) : 0;
        // cross((-L.y, L.x, 0), dLdv) = (zmax − zmin)·(ρ, 0, −ρ·dρ/dz) and ρ·dρ/dz =
        // rmax²/(2·zmax) everywhere, the apex included.
        const double halfSlope = zmax_ != 0 ? rmax_ * rmax_ / (2 * zmax_) : 0;
        return {V3d(rho, 0, z), (zmax_ - zmin_) * V3d(drhodz, 0, 1),
                SignOf(zmax_ - zmin_) * V3d(rho, 0, -halfSlope)};
    }

    int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[4]) const override {
        return implicit_.RayRoots(o, d, lo, hi, t);
    }

    int ProfileCandidates(const V3d& p, double slack, ProfileCandidate c[2]) const override {
        c[0] = {(p.z - zmin_) / (zmax_ - zmin_), V2d(rmax_ < 0 ? -1 : 1, 0)};
        return ClampToUnit(&c[0].v, slack) ? 1 : 0;
    }

    V3d ImplicitGradient(const V3d& p) const override { return implicit_.Gradient(p); }

  private:
    double rmax_, zmin_, zmax_;
    RevolutionQuadric implicit_;
};

}  // namespace
}  // namespace quadric

std::unique_ptr<Quadric> MakeSphere(float radius, float zmin, float zmax, float thetamax) {
    if (!quadric::AllFinite({radius, zmin, zmax, thetamax})) radius = thetamax = 0;
    return std::make_unique<quadric::Sphere>(radius, zmin, zmax, thetamax);
}

std::unique_ptr<Quadric> MakeCone(float height, float radius, float thetamax) {
    return MakeHyperboloid(V3f(radius, 0, 0), V3f(0, 0, height), thetamax);
}

std::unique_ptr<Quadric> MakeCylinder(float radius, float zmin, float zmax, float thetamax) {
    return MakeHyperboloid(V3f(radius, 0, zmin), V3f(radius, 0, zmax), thetamax);
}

std::unique_ptr<Quadric> MakeDisk(float height, float radius, float thetamax) {
    return MakeHyperboloid(V3f(radius, 0, height), V3f(0, 0, height), thetamax);
}

std::unique_ptr<Quadric> MakeHyperboloid(const V3f& point1, const V3f& point2, float thetamax) {
    if (!quadric::AllFinite({point1.x, point1.y, point1.z, point2.x, point2.y, point2.z, thetamax}))
        return std::make_unique<quadric::SweptLine>(quadric::V3d(0), quadric::V3d(0), 0);
    return std::make_unique<quadric::SweptLine>(quadric::V3d(point1), quadric::V3d(point2),
                                                thetamax);
}

std::unique_ptr<Quadric> MakeParaboloid(float rmax, float zmin, float zmax, float thetamax) {
    if (!quadric::AllFinite({rmax, zmin, zmax, thetamax})) rmax = zmin = zmax = thetamax = 0;
    return std::make_unique<quadric::Paraboloid>(rmax, zmin, zmax, thetamax);
}

}  // namespace gonio
