#pragma once
// The quadrics under test: each with its implicit equation and its "outside" direction, so that
// every test runs over every shape and several partial sweeps.

#include <Imath/ImathVec.h>

#include <cmath>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "renderer/geometry/quadrics.h"

namespace gonio::test {

using Imath::V3d;

struct QuadricCase {
    std::string name;
    std::function<std::unique_ptr<Quadric>()> make;
    std::function<double(const V3d&)> implicit;  // zero on the surface
    std::function<V3d(const V3d&)> outside;      // RISpec's "outward" at a surface point
    // +1: Ng points outside; −1: the parameters turn it inside out; 0: no outside to speak of
    double orientation = 1;
    double scale = 1;                     // the shape's size
    bool uniqueUV = true;                 // each surface point has one (u, v)
    bool clipU = false;                   // thetamax < 360: u outside [0, 1] lies off the surface
    bool clipV0 = false, clipV1 = false;  // likewise for v < 0 and v > 1
};

inline std::ostream& operator<<(std::ostream& os, const QuadricCase& c) { return os << c.name; }

inline double Rho2(const V3d& p) { return p.x * p.x + p.y * p.y; }
inline V3d Radial(const V3d& p) { return V3d(p.x, p.y, 0); }

inline QuadricCase SphereCase(std::string name, double r, double zmin, double zmax, double thetamax,
                              double orientation) {
    QuadricCase c;
    c.name = name;
    c.make = [=] { return MakeSphere(r, zmin, zmax, thetamax); };
    c.implicit = [=](const V3d& p) { return p.length2() - r * r; };
    c.outside = [](const V3d& p) { return p; };
    c.orientation = orientation;
    c.scale = std::fabs(r);
    c.clipU = std::fabs(thetamax) < 360;
    c.clipV0 = std::min(zmin, zmax) > -std::fabs(r);
    c.clipV1 = std::max(zmin, zmax) < std::fabs(r);
    if (zmin > zmax) std::swap(c.clipV0, c.clipV1);
    return c;
}

// Cylinder, cone, disk and hyperboloid: the sweep of the segment p1 → p2.
inline QuadricCase LineCase(std::string name, std::function<std::unique_ptr<Quadric>()> make,
                            V3d p1, V3d p2, double thetamax, double orientation) {
    QuadricCase c;
    c.name = name;
    c.make = make;
    const V3d d = p2 - p1;
    c.implicit = [=](const V3d& p) {
        if (d.z == 0) return p.z - p1.z;
        const double w = (p.z - p1.z) / d.z;
        const double x = p1.x + w * d.x, y = p1.y + w * d.y;
        return Rho2(p) - (x * x + y * y);
    };
    if (d.z == 0)
        c.outside = [](const V3d&) { return V3d(0, 0, 1); };
    else
        c.outside = Radial;
    c.orientation = orientation;
    c.scale = std::max(p1.length(), p2.length());
    c.clipU = std::fabs(thetamax) < 360;
    c.clipV0 = c.clipV1 = true;
    return c;
}

inline QuadricCase ParaboloidCase(std::string name, double rmax, double zmin, double zmax,
                                  double thetamax) {
    QuadricCase c;
    c.name = name;
    c.make = [=] { return MakeParaboloid(rmax, zmin, zmax, thetamax); };
    c.implicit = [=](const V3d& p) { return zmax * Rho2(p) - rmax * rmax * p.z; };
    c.outside = Radial;
    c.scale = std::max(std::fabs(rmax), std::fabs(zmax));
    c.clipU = std::fabs(thetamax) < 360;
    c.clipV0 = zmin != 0;
    c.clipV1 = true;
    return c;
}

inline QuadricCase TorusCase(std::string name, double R, double r, double phimin, double phimax,
                             double thetamax) {
    QuadricCase c;
    c.name = name;
    c.make = [=] { return MakeTorus(R, r, phimin, phimax, thetamax); };
    c.implicit = [=](const V3d& p) {
        const double g = p.length2() + R * R - r * r;
        return g * g - 4 * R * R * Rho2(p);
    };
    // Out of the tube: away from the centre circle of radius R in the point's half plane.
    c.outside = [=](const V3d& p) {
        const double rho = std::sqrt(Rho2(p));
        return rho > 0 ? p - V3d(p.x, p.y, 0) * (R / rho) : V3d(0);
    };
    c.scale = R + r;
    c.clipU = std::fabs(thetamax) < 360;
    c.clipV0 = c.clipV1 = std::fabs(phimax - phimin) < 330;
    return c;
}

inline std::vector<QuadricCase> AllQuadricCases() {
    auto hyperboloid = [](std::string name, V3d p1, V3d p2, double thetamax, double sign) {
        return LineCase(
            name, [=] { return MakeHyperboloid(Imath::V3f(p1), Imath::V3f(p2), thetamax); }, p1, p2,
            thetamax, sign);
    };
    auto cylinder = [](std::string name, double r, double zmin, double zmax, double thetamax,
                       double sign) {
        return LineCase(
            name, [=] { return MakeCylinder(r, zmin, zmax, thetamax); }, V3d(r, 0, zmin),
            V3d(r, 0, zmax), thetamax, sign);
    };
    auto cone = [](std::string name, double height, double r, double thetamax) {
        QuadricCase c = LineCase(
            name, [=] { return MakeCone(height, r, thetamax); }, V3d(r, 0, 0), V3d(0, 0, height),
            thetamax, 1);
        return c;
    };
    auto disk = [](std::string name, double height, double r, double thetamax) {
        QuadricCase c = LineCase(
            name, [=] { return MakeDisk(height, r, thetamax); }, V3d(r, 0, height),
            V3d(0, 0, height), thetamax, thetamax < 0 ? -1 : 1);
        c.clipV1 = false;  // v > 1 continues through the centre onto the disk itself
        return c;
    };

    std::vector<QuadricCase> cases = {
        SphereCase("SphereFull", 1, -1, 1, 360, 1),
        SphereCase("SpherePartial", 1, -0.5, 0.8, 270, 1),
        SphereCase("SphereLarge", 100, -100, 100, 360, 1),
        SphereCase("SphereNegativeTheta", 1.5, -0.3, 1.5, -200, -1),
        SphereCase("SphereReversedZ", 2, 1, -1.5, 300, -1),
        SphereCase("SphereNegativeRadius", -1, -0.6, 0.7, 160, 1),
        cylinder("CylinderFull", 1, -1, 2, 360, 1),
        cylinder("CylinderQuarter", 0.5, 0, 1, 90, 1),
        cylinder("CylinderReversedZ", 0.5, 1, -1, 200, -1),
        cone("ConeFull", 2, 1, 360),
        cone("ConePartial", 1, 0.5, 120),
        disk("DiskFull", 0.5, 1, 360),
        disk("DiskPartial", 0, 2, 45),
        disk("DiskNegativeTheta", -1, 1, -100),
        hyperboloid("HyperboloidFull", V3d(1, -0.5, -1), V3d(0.5, 1, 1), 360, 1),
        hyperboloid("HyperboloidPartial", V3d(1, 0, 0), V3d(1, 1, 1), 250, 1),
        hyperboloid("HyperboloidDown", V3d(0.3, 0.4, 1), V3d(1, 0, -0.5), 300, -1),
        ParaboloidCase("ParaboloidFull", 1, 0, 1, 360),
        ParaboloidCase("ParaboloidPartial", 0.5, 0.2, 0.7, 270),
        ParaboloidCase("ParaboloidDownward", 1, -2, -0.5, 300),
        TorusCase("TorusFull", 1, 0.3, 0, 360, 360),
        TorusCase("TorusPartial", 2, 0.5, -90, 180, 270),
        TorusCase("TorusSlice", 1, 0.25, 45, 300, 90),
    };
    QuadricCase annulus =
        hyperboloid("HyperboloidFlat", V3d(0.5, 0.2, 0), V3d(0.3, -0.4, 0), 180, 1);
    annulus.uniqueUV = false;  // the segment passes some distances from the axis twice
    annulus.orientation = 0;   // ... towards the axis (Ng = +z) and then away from it (−z)
    annulus.clipU = annulus.clipV0 = annulus.clipV1 = false;
    cases.push_back(annulus);
    return cases;
}

}  // namespace gonio::test
