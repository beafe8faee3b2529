#include "renderer/geometry/quadric_revolved.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/geometry/quadric_roots.h"

namespace gonio::quadric {

namespace {

void Include(Box3f& box, double x, double y, double z) {
    box.extendBy(V3f(float(x), float(y), float(z)));
}

// The xy extent of the arc that the point q sweeps through the angles [0, sweep] (signed):
// its two ends and every axis crossing between them.
void IncludeArc(const V2d& q, double sweep, bool full, double zlo, double zhi, Box3f& box) {
    const double rho = std::hypot(q.x, q.y);
    if (full) {
        Include(box, -rho, -rho, zlo);
        Include(box, rho, rho, zhi);
        return;
    }
    const double start = std::atan2(q.y, q.x);
    const double a = std::min(start, start + sweep), b = std::max(start, start + sweep);
    for (double angle : {a, b}) {
        Include(box, rho * std::cos(angle), rho * std::sin(angle), zlo);
        Include(box, rho * std::cos(angle), rho * std::sin(angle), zhi);
    }
    static const double kAxisX[4] = {1, 0, -1, 0}, kAxisY[4] = {0, 1, 0, -1};
    for (double k = std::ceil(a / (kPi / 2)); k <= std::floor(b / (kPi / 2)); ++k) {
        const int quadrant = ((int(k) % 4) + 4) % 4;
        Include(box, rho * kAxisX[quadrant], rho * kAxisY[quadrant], zlo);
        Include(box, rho * kAxisX[quadrant], rho * kAxisY[quadrant], zhi);
    }
}

}  // namespace

RevolvedQuadric::RevolvedQuadric(double thetamaxDegrees)
    : thetaMax_(Radians(thetamaxDegrees)), fullSweep_(std::fabs(thetamaxDegrees) >= 360) {
    if (thetamaxDegrees == 0) degenerate_ = true;
    if (!fullSweep_) sweep_ = AngleRange(0, thetaMax_);
}

void RevolvedQuadric::SetDegenerate() { degenerate_ = true; }

void RevolvedQuadric::SetExtent(const std::vector<V2d>& extremes, double zlo, double zhi) {
    Box3f box;
    for (const V2d& q : extremes) IncludeArc(q, thetaMax_, fullSweep_, zlo, zhi, box);
    // Pad by a few float ulps of the largest coordinate: Evaluate and Intersect round their
    // double results to float independently of the box.
    const float scale =
        std::max({std::fabs(box.min.x), std::fabs(box.min.y), std::fabs(box.min.z),
                  std::fabs(box.max.x), std::fabs(box.max.y), std::fabs(box.max.z), 1e-30f});
    const V3f pad(scale * 1e-6f);
    bounds_ = Box3f(box.min - pad, box.max + pad);
    center_ = V3d(0.5 * (double(box.min.x) + box.max.x), 0.5 * (double(box.min.y) + box.max.y),
                  0.5 * (double(box.min.z) + box.max.z));
    const V3d halfDiagonal =
        0.5 * V3d(double(bounds_.max.x) - bounds_.min.x, double(bounds_.max.y) - bounds_.min.y,
                  double(bounds_.max.z) - bounds_.min.z);
    ballCentre_ = center_;
    ballRadius2_ = halfDiagonal.length2();
    double rhoMax = 0;
    for (const V2d& q : extremes) rhoMax = std::max(rhoMax, std::hypot(q.x, q.y));
    rhoMax += std::max(rhoMax * 1e-6, double(pad.x));
    rhoMax2_ = rhoMax * rhoMax;
}

void RevolvedQuadric::SetBoundingBall(const V3d& centre, double radius) {
    ballCentre_ = centre;
    // Padded like the box: the test must never reject a hit that rounding put on the edge.
    radius = std::fabs(radius) * (1 + 1e-6);
    ballRadius2_ = radius * radius;
}

void RevolvedQuadric::SetSphericalSurface(double radius) {
    SetBoundingBall(V3d(0, 0, 0), radius);
    spherical_ = true;
    sphereRadius2_ = radius * radius;
    completeSphere_ = {sphereRadius2_, ballRadius2_};
}

int RevolvedQuadric::ProfileDirections(const V3d& p, V2d along[2]) const {
    ProfileCandidate candidates[2];
    const int m = ProfileCandidates(p, 0, candidates);
    for (int j = 0; j < m; ++j) along[j] = candidates[j].along;
    return m;
}

namespace {

// The xy part of p in the frame whose x axis points along `along` (scaled by |along|): its
// angle is the sweep that carries a profile point in that direction onto p.
V2d InProfileFrame(const V3d& p, const V2d& along) {
    // Profiles in the xz plane (the common case) exactly, without products that vanish.
    if (along.y == 0) return V2d(along.x * p.x, along.x * p.y);
    return V2d(along.x * p.x + along.y * p.y, along.x * p.y - along.y * p.x);
}

}  // namespace

bool RevolvedQuadric::ThetaParameter(const V3d& p, const V2d& along, double slack,
                                     double* u) const {
    // How far the sweep has turned to carry the profile point onto p, in the sweep's sense.
    const V2d q = InProfileFrame(p, along);
    double theta = Atan2(SignOf(thetaMax_) * q.y, q.x);
    if (theta < 0) theta += 2 * kPi;
    // A point a rounding error short of a full turn lies on the sweep's starting edge.
    if (theta >= 2 * kPi - 1e-12) theta = 0;
    const double sweep = std::fabs(thetaMax_);
    if (!fullSweep_ && theta > sweep) {
        // Past the end edge, or short of the start edge: onto the nearer, within the slack.
        const bool nearEnd = theta - sweep <= 2 * kPi - theta;
        if (std::min(theta - sweep, 2 * kPi - theta) > slack) return false;
        theta = nearEnd ? sweep : 0;
    }
    *u = std::min(theta / sweep, 1.0);
    return true;
}

bool RevolvedQuadric::OnShape(const V3d& p) const {
    if (everyRootOnShape_) return true;
    V2d along[2];
    const int m = ProfileDirections(p, along);
    for (int j = 0; j < m; ++j) {
        const V2d q = InProfileFrame(p, along[j]);
        if (sweep_.Contains(q.x, q.y)) return true;
    }
    return false;
}

int RevolvedQuadric::SphereRoots(double missed2, double dd, double lo, double hi,
                                 double t[2]) const {
    return SphereChordRoots(sphereRadius2_, missed2, dd, lo, hi, t);
}

bool RevolvedQuadric::IntersectPoint(const V3f& org, const V3f& dir, float tmin, float tmax,
                                     float* tHit, V3f* point) const {
    if (degenerate_) return false;
    if (IsCompleteSphere()) return completeSphere_.Intersect(org, dir, tmin, tmax, tHit, point);
    const V3d d(dir.x, dir.y, dir.z);
    const double dd = d.dot(d);
    if (!(dd > 0) || !std::isfinite(dd)) return false;
    // Solve from the point of the ray nearest the shape's centre: the polynomial coefficients
    // then scale with the shape's size, not with the distance of the ray origin, and do not
    // cancel (a ray from 1e3 units away hits a unit sphere as accurately as one from nearby).
    const V3d o(org.x, org.y, org.z);
    // |w × d|² / |d|² is the squared distance of the ray's line from the ball's centre
    // (Lagrange's identity: no cancellation for rays from far away).
    const V3d w = o - ballCentre_;
    const double missed2 = w.cross(d).length2();
    if (missed2 > ballRadius2_ * dd) return false;
    double roots[4];
    int n;
    double t0;
    V3d origin;
    if (spherical_) {
        t0 = -w.dot(d) / dd;
        origin = o + t0 * d;
        n = SphereRoots(missed2, dd, double(tmin) - t0, double(tmax) - t0, roots);
    } else {
        // Likewise the infinite cylinder ρ ≤ ρmax about the axis of revolution, which holds a
        // long cylinder far more tightly than any ball: seen along z, the line passes the axis
        // at the distance |o.x·d.y − o.y·d.x| / |d.xy|.
        const double across = o.x * d.y - o.y * d.x;
        if (across * across > rhoMax2_ * (d.x * d.x + d.y * d.y)) return false;
        t0 = (center_ - o).dot(d) / dd;
        origin = o + t0 * d;
        n = RayRoots(origin, d, double(tmin) - t0, double(tmax) - t0, roots);
    }
    for (int i = 0; i < n; ++i) {
        const double t = t0 + roots[i];
        if (!(t > tmin && t < tmax)) continue;
        const V3d p = origin + roots[i] * d;
        if (!OnShape(p)) continue;
        *tHit = float(t);
        *point = V3f(p);
        return true;
    }
    return false;
}

double RevolvedQuadric::FindParameters(const V3d& p, double* u, double* v) const {
    // First exactly as IntersectPoint decided, then allowing for the rounding of the point to
    // float, and at last (a point off the surface) the nearest parameters of any candidate.
    for (double slack : {0.0, 1e-4, std::numeric_limits<double>::infinity()}) {
        ProfileCandidate candidates[2];
        const int m = ProfileCandidates(p, slack, candidates);
        for (int j = 0; j < m; ++j) {
            if (ThetaParameter(p, candidates[j].along, slack, u)) {
                *v = candidates[j].v;
                return slack;
            }
        }
    }
    *u = *v = 0;
    return -1;
}

V2f RevolvedQuadric::ParametersAt(const V3f& point) const {
    double u, v;
    FindParameters(V3d(point.x, point.y, point.z), &u, &v);
    return V2f(float(u), float(v));
}

V3f RevolvedQuadric::NormalAt(const V3f& point) const {
    const V3d n = ImplicitGradient(V3d(point.x, point.y, point.z));
    return V3f(float(n.x), float(n.y), float(n.z));
}

bool RevolvedQuadric::Intersect(const V3f& org, const V3f& dir, float tmin, float tmax,
                                QuadricHit* hit) const {
    V3f point;
    if (!IntersectPoint(org, dir, tmin, tmax, &hit->t, &point)) return false;
    const V2f uv = ParametersAt(point);
    hit->u = uv.x;
    hit->v = uv.y;
    return true;
}

SurfaceGeometry RevolvedQuadric::Evaluate(float u, float v) const {
    const double theta = u * thetaMax_;
    return Sweep(Profile(v), std::cos(theta), std::sin(theta), u, v);
}

SurfaceGeometry RevolvedQuadric::EvaluateAt(const V3f& point) const {
    const V3d p(point.x, point.y, point.z);
    double u, v;
    const bool onShape = FindParameters(p, &u, &v) == 0;
    const float fu = float(u), fv = float(v);
    if (!onShape) return Evaluate(fu, fv);  // moved onto an edge: p is not on the sweep
    const ProfilePoint profile = ProfileThrough(p, fv);
    const V3d& L = profile.L;
    // Near the axis the profile point's side (which of L.xy and −L.xy) is at the mercy of the
    // rounding of v, and p's direction is lost in its own rounding.
    const double rhoL2 = L.x * L.x + L.y * L.y, rhoP2 = p.x * p.x + p.y * p.y;
    if (!(rhoL2 > 1e-8 * L.length2()) || !(rhoP2 > 1e-8 * p.length2())) return Evaluate(fu, fv);
    // P = Rz(θ)·L: cos θ and sin θ are the dot and cross products of the unit xy directions.
    const double scale = 1 / std::sqrt(rhoL2 * rhoP2);
    const double c = (L.x * p.x + L.y * p.y) * scale, s = (L.x * p.y - L.y * p.x) * scale;
    return Sweep(profile, c, s, fu, fv);
}

SurfaceGeometry RevolvedQuadric::Sweep(const ProfilePoint& profile, double c, double s, float u,
                                       float v) const {
    auto rotate = [c, s](const V3d& a) { return V3d(c * a.x - s * a.y, s * a.x + c * a.y, a.z); };
    const V3d p = rotate(profile.L);
    const V3d dPdu = thetaMax_ * V3d(-p.y, p.x, 0);
    const V3d dPdv = rotate(profile.dLdv);
    // cross(dPdu, dPdv) = thetamax · Rz(θ)·profile.normal (up to a positive factor).
    V3d n = SignOf(thetaMax_) * rotate(profile.normal);
    const double length = n.length();
    n = length > 0 && std::isfinite(length) ? n / length : V3d(0, 0, 1);

    SurfaceGeometry g;
    g.P = V3f(p);
    g.dPdu = V3f(dPdu);
    g.dPdv = V3f(dPdv);
    g.Ng = V3f(n);
    g.u = u;
    g.v = v;
    return g;
}

}  // namespace gonio::quadric
