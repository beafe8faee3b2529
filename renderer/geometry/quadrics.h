#pragma once
// The RISpec 3.2 §5.4 quadrics as exact analytic shapes, each a Quadric (shape.h) in its own
// object space. Parameters come in RIB order, angles in degrees; (u, v) span [0, 1]² and
// θ = u·thetamax is the sweep about z. Profiles (before the sweep, at θ = 0):
//
//   Sphere       φ = φmin + v·(φmax − φmin), φmin = asin(zmin/r) (−90° if zmin ≤ −r),
//                φmax = asin(zmax/r) (90° if zmax ≥ r); L = r·(cos φ, 0, sin φ)
//   Cone         L = (radius·(1 − v), 0, v·height)
//   Cylinder     L = (radius, 0, zmin + v·(zmax − zmin))
//   Disk         L = (radius·(1 − v), 0, height)
//   Hyperboloid  L = (1 − v)·point1 + v·point2 (the line is swept, so it may leave the xz plane)
//   Paraboloid   z = zmin + v·(zmax − zmin), L = (rmax·√(z/zmax), 0, z)
//   Torus        φ = phimin + v·(phimax − phimin), L = (R + r·cos φ, 0, r·sin φ)
//
// Orientation: Ng = normalize(cross(dPdu, dPdv)) exactly as RISpec defines the geometric
// normal. With the parameters in their usual sense (thetamax > 0, zmin < zmax, phimin < phimax,
// radii > 0, a hyperboloid's point1 below point2) it points away from the z axis (out of the
// torus tube, down and out of an upward paraboloid, +z for the disk), as RISpec requires. As
// RISpec also says, reversing a parameter turns the quadric inside out: negative thetamax,
// zmin > zmax, phimin > phimax (and point1 above point2) flip Ng; the ranges are never swapped,
// so (u, v) always follow the formulas above literally. A flat hyperboloid (point1.z = point2.z)
// faces +z where its line runs towards the axis (as Disk does) and −z where it runs away. A
// negative sphere radius keeps the z range [zmin, zmax] (φ = asin(z/r) with the argument clamped to
// [−1, 1]).
//
// Degenerate parameters (a zero radius or height where it collapses the surface, thetamax = 0,
// an empty z or φ range, point1 = point2, a paraboloid with zmax = 0, non-finite numbers) give a
// shape that is never hit; Evaluate still returns finite values. Where a surface meets the z axis
// (sphere poles, cone apex, disk centre, paraboloid apex) Ng is the limit of the normals around
// it. At the paraboloid apex, where ∂P/∂v is infinite, dPdv is evaluated at z = 1e-12·zmax.
// |thetamax| > 360 sweeps the surface more than once; Intersect reports the smallest u.
// Evaluate extrapolates the formulas for (u, v) outside [0, 1].

#include <memory>

#include "renderer/geometry/shape.h"

namespace gonio {

std::unique_ptr<Quadric> MakeSphere(float radius, float zmin, float zmax, float thetamax);
std::unique_ptr<Quadric> MakeCone(float height, float radius, float thetamax);
std::unique_ptr<Quadric> MakeCylinder(float radius, float zmin, float zmax, float thetamax);
std::unique_ptr<Quadric> MakeHyperboloid(const V3f& point1, const V3f& point2, float thetamax);
std::unique_ptr<Quadric> MakeParaboloid(float rmax, float zmin, float zmax, float thetamax);
std::unique_ptr<Quadric> MakeDisk(float height, float radius, float thetamax);
std::unique_ptr<Quadric> MakeTorus(float majorRadius, float minorRadius, float phimin, float phimax,
                                   float thetamax);

}  // namespace gonio
