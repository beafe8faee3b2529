// The torus: the one quartic among the RISpec quadrics.
#include <algorithm>
#include <cmath>

#include "renderer/geometry/quadric_revolved.h"
#include "renderer/geometry/quadric_roots.h"
#include "renderer/geometry/quadrics.h"

namespace gonio {
namespace quadric {
namespace {

// The extremes of cos and sin over the angles [lo, hi].
void CosSinRange(double lo, double hi, V2d* cosRange, V2d* sinRange) {
    if (hi - lo >= 2 * kPi) {
        *cosRange = *sinRange = V2d(-1, 1);
        return;
    }
    const double turns = std::floor(lo / (2 * kPi)) * (2 * kPi);  // keeps the loop below short
    lo -= turns;
    hi -= turns;
    *cosRange = V2d(std::min(std::cos(lo), std::cos(hi)), std::max(std::cos(lo), std::cos(hi)));
    *sinRange = V2d(std::min(std::sin(lo), std::sin(hi)), std::max(std::sin(lo), std::sin(hi)));
    for (double k = std::ceil(lo / (kPi / 2)); k <= std::floor(hi / (kPi / 2)); ++k) {
        switch (((int(k) % 4) + 4) % 4) {
            case 0:
                cosRange->y = 1;
                break;
            case 1:
                sinRange->y = 1;
                break;
            case 2:
                cosRange->x = -1;
                break;
            case 3:
                sinRange->x = -1;
                break;
        }
    }
}

class Torus final : public RevolvedQuadric {
  public:
    Torus(double majorRadius, double minorRadius, double phimin, double phimax, double thetamax)
        : RevolvedQuadric(thetamax),
          major_(majorRadius),
          minor_(minorRadius),
          phiMin_(Radians(phimin)),
          phiMax_(Radians(phimax)),
          fullTube_(std::fabs(phimax - phimin) >= 360) {
        if (minorRadius == 0 || phimin == phimax) SetDegenerate();
        if (fullTube_)
            SetProfileComplete();
        else
            tubeRange_ = AngleRange(phiMin_, phiMax_ - phiMin_);
        V2d cosRange, sinRange;
        CosSinRange(std::min(phiMin_, phiMax_), std::max(phiMin_, phiMax_), &cosRange, &sinRange);
        // For a fixed θ a point's coordinates are linear in the profile's x, so the profile's
        // extreme x values bound the whole sweep.
        const double x0 = major_ + minor_ * cosRange.x, x1 = major_ + minor_ * cosRange.y;
        const double z0 = minor_ * sinRange.x, z1 = minor_ * sinRange.y;
        SetExtent({V2d(x0, 0), V2d(x1, 0)}, std::min(z0, z1), std::max(z0, z1));
        if (major_ == 0)
            SetSphericalSurface(minor_);  // a sphere swept twice
        else
            SetBoundingBall(V3d(0, 0, 0), std::fabs(major_) + std::fabs(minor_));
    }

  protected:
    ProfilePoint Profile(double v) const override {
        const double dphi = phiMax_ - phiMin_;
        const double phi = phiMin_ + v * dphi;
        const double c = std::cos(phi), s = std::sin(phi);
        // cross((-L.y, L.x, 0), dLdv) = (φmax − φmin)·r·(R + r·cos φ)·(cos φ, 0, sin φ).
        const double axisDistance = major_ + minor_ * c;
        double side = axisDistance;
        if (std::fabs(axisDistance) <= 1e-12 * (std::fabs(major_) + std::fabs(minor_))) {
            // On the axis (a spindle torus): the limit from the side of v we come from.
            side = -minor_ * s * dphi * (v < 1 ? 1.0 : -1.0);
        }
        return {V3d(axisDistance, 0, minor_ * s), dphi * minor_ * V3d(-s, 0, c),
                SignOf(dphi * minor_ * side) * V3d(c, 0, s)};
    }

    // Not for major_ = 0, a sphere swept twice (SetSphericalSurface), where the quartic would be
    // a square with only double roots.
    int RayRoots(const V3d& o, const V3d& d, double lo, double hi, double t[4]) const override {
        // Work in distances τ along the unit direction e from the ray's point nearest the
        // torus centre p: the quartic's coefficients are then of the torus's own size.
        const double speed = d.length();
        const V3d e = d / speed;
        const double nearest = -o.dot(e);
        const V3d p = o + nearest * e;
        const double pp = p.dot(p);
        const double bound = std::fabs(major_) + std::fabs(minor_);
        if (pp > bound * bound) return 0;
        const double halfChord = std::sqrt(bound * bound - pp) + 1e-9 * bound;
        const double tauLo = std::max(lo * speed - nearest, -halfChord);
        const double tauHi = std::min(hi * speed - nearest, halfChord);
        if (!(tauLo < tauHi)) return 0;

        // (|P|² + R² − r²)² = 4R²·(x² + y²) with P = p + τ·e.
        const double k = major_ * major_ - minor_ * minor_, fourR2 = 4 * major_ * major_;
        const double ee = e.dot(e), pe = p.dot(e);
        const double exy = e.x * e.x + e.y * e.y, pexy = p.x * e.x + p.y * e.y;
        const double pxy = p.x * p.x + p.y * p.y, g0 = pp + k;
        const double c[5] = {g0 * g0 - fourR2 * pxy, 4 * pe * g0 - 2 * fourR2 * pexy,
                             2 * ee * g0 + 4 * pe * pe - fourR2 * exy, 4 * ee * pe, ee * ee};
        const int n = PolynomialRootsIn(c, 4, tauLo, tauHi, t);
        for (int i = 0; i < n; ++i) t[i] = (t[i] + nearest) / speed;
        return n;
    }

    int ProfileCandidates(const V3d& p, double slack, ProfileCandidate c[2]) const override {
        double offAxis[2];
        const int m = TubeCircles(p, offAxis);
        int n = 0;
        for (int i = 0; i < m; ++i) {
            const double phi = Atan2(p.z / minor_, (offAxis[i] - major_) / minor_);
            if (TubeParameter(phi, slack, &c[n].v)) c[n++].along = Side(offAxis[i]);
        }
        return n;
    }

    int ProfileDirections(const V3d& p, V2d along[2]) const override {
        // φ in the tube's range without φ itself: its direction against the range's ends.
        double offAxis[2];
        const int m = TubeCircles(p, offAxis);
        int n = 0;
        for (int i = 0; i < m; ++i)
            if (tubeRange_.Contains((offAxis[i] - major_) / minor_, p.z / minor_))
                along[n++] = Side(offAxis[i]);
        return n;
    }

    V3d ImplicitGradient(const V3d& p) const override {
        // A sphere swept twice (see RayRoots): the quartic's gradient vanishes on it.
        if (major_ == 0) return p;
        // ∇[(|P|² + R² − r²)² − 4R²·(x² + y²)]
        const double g = 4 * (p.length2() + major_ * major_ - minor_ * minor_);
        const double radial = 8 * major_ * major_;
        return V3d(g * p.x - radial * p.x, g * p.y - radial * p.y, g * p.z);
    }

  private:
    // The signed distances from the axis, in p's half plane, of the centres of the tube circles
    // that p may lie on, nearer first: +R (θ = ψ), or, for a spindle torus, also −R (θ = ψ + π).
    int TubeCircles(const V3d& p, double offAxis[2]) const {
        const double rho = std::sqrt(p.x * p.x + p.y * p.y);
        const double sides[2] = {rho, -rho};
        double miss[2];
        for (int i = 0; i < 2; ++i)
            miss[i] = std::fabs(std::hypot(sides[i] - major_, p.z) - std::fabs(minor_));
        const int first = miss[1] < miss[0] ? 1 : 0;
        const double tolerance = miss[first] + 1e-7 * (std::fabs(major_) + std::fabs(minor_));
        int n = 0;
        for (int i : {first, 1 - first})
            if (!(miss[i] > tolerance)) offAxis[n++] = sides[i];
        return n;
    }

    static V2d Side(double offAxis) { return V2d(offAxis < 0 ? -1 : 1, 0); }

    // v for the tube angle phi (any turn), if phi lies in the swept φ range (give or take
    // `slack` radians, then moved onto the nearer end).
    bool TubeParameter(double phi, double slack, double* v) const {
        const double dphi = phiMax_ - phiMin_;
        double turned = std::fmod(dphi >= 0 ? phi - phiMin_ : phiMin_ - phi, 2 * kPi);
        if (turned < 0) turned += 2 * kPi;
        if (turned >= 2 * kPi - 1e-12) turned = 0;  // on the starting edge
        const double range = std::fabs(dphi);
        if (!fullTube_ && turned > range) {
            const bool nearEnd = turned - range <= 2 * kPi - turned;
            if (std::min(turned - range, 2 * kPi - turned) > slack) return false;
            turned = nearEnd ? range : 0;
        }
        *v = std::min(turned / range, 1.0);
        return true;
    }

    double major_, minor_, phiMin_, phiMax_;
    bool fullTube_;
    AngleRange tubeRange_;  // the directions of (cos φ, sin φ) on the tube
};

}  // namespace
}  // namespace quadric

std::unique_ptr<Quadric> MakeTorus(float majorRadius, float minorRadius, float phimin, float phimax,
                                   float thetamax) {
    const bool finite = std::isfinite(majorRadius) && std::isfinite(minorRadius) &&
                        std::isfinite(phimin) && std::isfinite(phimax) && std::isfinite(thetamax);
    if (!finite) majorRadius = minorRadius = phimin = phimax = thetamax = 0;
    return std::make_unique<quadric::Torus>(majorRadius, minorRadius, phimin, phimax, thetamax);
}

}  // namespace gonio
