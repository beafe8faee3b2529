#include "renderer/shading/neighbour_points.h"

#include <cmath>
#include <limits>

namespace gonio {
namespace {

using Imath::V2f;
using Imath::V3f;

// Where the ray meets the tangent plane of sp; false if it runs along the plane or away.
bool TangentPlaneHit(const SurfacePoint& sp, const V3f& org, const V3f& dir, V3f* q) {
    const float facing = dir.dot(sp.Ng);
    if (std::fabs(facing) < 1e-8f * dir.length()) return false;
    const float t = (sp.P - org).dot(sp.Ng) / facing;
    if (!(t > 0) || !std::isfinite(t)) return false;
    *q = org + t * dir;
    return true;
}

// The hit of one neighbour ray, if it lies on centre's surface near where the tangent plane
// says (a torus behind itself, or another primitive with the same attributes, is rejected).
bool HitOnSurface(const RayScene& scene, const SurfacePoint& centre, const V3f& org, const V3f& dir,
                  float tnear, float time, SurfacePoint* out, V3f* incident) {
    RayHit hit;
    if (!scene.Intersect(org, dir, tnear, std::numeric_limits<float>::infinity(), time, &hit))
        return false;
    scene.Evaluate(org, dir, hit, out);
    if (out->shape != centre.shape || out->attributes != centre.attributes ||
        out->Ng.dot(centre.Ng) <= 0)
        return false;
    V3f q;
    if (TangentPlaneHit(centre, org, dir, &q) && (out->P - q).length() > (q - centre.P).length())
        return false;
    *incident = out->P - org;
    return true;
}

}  // namespace

V2f ParametricStep(const SurfacePoint& sp, const V3f& dP) {
    const float a = sp.dPdu.dot(sp.dPdu), b = sp.dPdu.dot(sp.dPdv), c = sp.dPdv.dot(sp.dPdv);
    const float det = a * c - b * b;
    if (!(det > 1e-12f * a * c) || !std::isfinite(det)) return V2f(0, 0);
    const float ru = sp.dPdu.dot(dP), rv = sp.dPdv.dot(dP);
    return V2f((c * ru - b * rv) / det, (a * rv - b * ru) / det);
}

int FindNeighbourPoint(const RayScene& scene, const SurfacePoint& centre, const V3f& centreOrg,
                       const V3f& centreDir, const V3f& org, const V3f& dir, float tnear,
                       float time, SurfacePoint* out, V3f* incident) {
    if (HitOnSurface(scene, centre, org, dir, tnear, time, out, incident)) return 1;
    // The mirror image of the neighbour ray about the centre ray: a pixel the other way.
    const V3f mirrorOrg = 2.f * centreOrg - org;
    const V3f mirrorDir = 2.f * centreDir.normalized() - dir.normalized();
    if (HitOnSurface(scene, centre, mirrorOrg, mirrorDir, tnear, time, out, incident)) return 2;
    *out = centre;
    V3f q = centre.P;
    if (!TangentPlaneHit(centre, org, dir, &q)) q = centre.P;
    const V2f step = ParametricStep(centre, q - centre.P);
    out->P = q;
    out->u += step.x, out->v += step.y;
    *incident = q - org;
    return 2;
}

}  // namespace gonio
