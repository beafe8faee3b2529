#pragma once
// A whole sphere about the object origin (RISpec §5.4's Sphere with zmin ≤ −r, zmax ≥ r and
// thetamax 360): every root of its equation along a ray is a hit, so its ray test needs no
// clipping. The one ray test of the renderer's commonest shape, inline: RevolvedQuadric's
// IntersectPoint calls it for such a sphere, and the Embree callback (ray_scene_geometry.cpp)
// calls it directly, without the virtual call and the general quadric's tests. A partial
// sphere's roots (RevolvedQuadric::SphereRoots) are the same chord, SphereChordRoots.

#include <Imath/ImathVec.h>

#include <cmath>
#include <limits>

namespace gonio {

// The roots in (lo, hi), ascending, of a ray's line meeting the sphere of squared radius radius2
// about the origin, as parameters from the line's point nearest the centre: missed2 = |w × d|²
// for any w from the centre to the line, dd = |d|². The line passes the centre at √(missed2/dd)
// and crosses the sphere half a chord, √(r² − missed2/dd), to either side of that point.
inline int SphereChordRoots(double radius2, double missed2, double dd, double lo, double hi,
                            double t[2]) {
    const double h2 = radius2 * dd - missed2;
    if (!(h2 >= 0)) return 0;
    // 1/dd runs beside the square root instead of after it.
    const double half = std::sqrt(h2) * (1 / dd);
    int n = 0;
    if (-half > lo && -half < hi) t[n++] = -half;
    if (half > lo && half < hi) t[n++] = half;
    return n;
}

struct CompleteSphere {
    double radius2;      // r²
    double ballRadius2;  // of the padded ball that rejects rays first (never smaller than r²)

    // The nearer root of o + t·d with tmin < t < tmax (object space; d need not be unit
    // length) in *tHit, the point there in *point; false where there is none. Solved from the
    // ray's point nearest the centre with Lagrange's identity, |o × d|² / |d|² being the
    // squared distance of the line from the centre: the robust form of Haines et al., Ray
    // Tracing Gems ch. 7, whose coefficients scale with the sphere, not with the distance of
    // the ray's origin (a ray from 1e3 units away hits a unit sphere as accurately as one from
    // nearby). In double precision; the ray and the results in float.
    bool Intersect(const Imath::V3f& org, const Imath::V3f& dir, float tmin, float tmax,
                   float* tHit, Imath::V3f* point) const {
        const Imath::V3d o(org), d(dir);
        const double dd = d.dot(d);
        // A zero, infinite or NaN direction has no hit; nor has a ray that passes the ball.
        if (!(dd > 0) || !(dd <= std::numeric_limits<double>::max())) return false;
        const double missed2 = o.cross(d).length2();
        if (missed2 > ballRadius2 * dd) return false;
        const double t0 = -o.dot(d) / dd;  // the point nearest the centre
        double roots[2];
        const int n =
            SphereChordRoots(radius2, missed2, dd, double(tmin) - t0, double(tmax) - t0, roots);
        for (int i = 0; i < n; ++i) {
            const double t = t0 + roots[i];
            if (!(t > tmin && t < tmax)) continue;
            *tHit = float(t);
            *point = Imath::V3f((o + t0 * d) + roots[i] * d);
            return true;
        }
        return false;
    }
};

}  // namespace gonio
