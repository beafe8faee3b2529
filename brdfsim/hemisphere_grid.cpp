#include "hemisphere_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gonio {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
}  // namespace

HemisphereGrid::HemisphereGrid(int bands, int maxRects)
    : bands_(bands), maxRects_(maxRects), bandWidth_(0.5 * kPi / bands) {
    if (bands < 1 || maxRects < 1 || bands > 1000 || maxRects > 4000) {
        throw std::invalid_argument("rings must be in 1..1000 and rects in 1..4000");
    }
    firstCell_.push_back(0);
    for (int b = 1; b <= bands; ++b) {
        // thesis eq. 4.14
        const int rects = std::max(
            static_cast<int>(std::lround(std::sin(0.5 * kPi * b / bands) * maxRects)), 1);
        firstCell_.push_back(firstCell_.back() + rects);
        bandOfCell_.insert(bandOfCell_.end(), rects, b - 1);
    }
}

int HemisphereGrid::CellOf(const Imath::V3f& w) const {
    const double theta = std::acos(std::clamp(static_cast<double>(w.z), -1.0, 1.0));
    const int band = std::min(static_cast<int>(theta / bandWidth_), bands_ - 1);
    double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
    if (phi < 0) phi += kTwoPi;
    const int rects = RectsInBand(band);
    const int rect = std::min(static_cast<int>(phi / kTwoPi * rects), rects - 1);
    return firstCell_[band] + rect;
}

double HemisphereGrid::DistanceToCell(int cell, double thetaC, double phiC) const {
    const int band = bandOfCell_[cell];
    const int rects = RectsInBand(band);
    const double theta0 = band * bandWidth_, theta1 = theta0 + bandWidth_;
    const double width = kTwoPi / rects;
    const double phi0 = (cell - firstCell_[band]) * width;
    const double sinC = std::sin(thetaC), cosC = std::cos(thetaC);
    double offset = std::fmod(phiC - phi0, kTwoPi);
    if (offset < 0) offset += kTwoPi;
    if (rects == 1 || offset <= width || sinC < 1e-12) {
        // The nearest point lies on the centre's own meridian.
        return std::max({0.0, theta0 - thetaC, thetaC - theta1});
    }
    // Otherwise on the nearer bounding meridian: the circle of radius d around the centre meets
    // that meridian where a cos θ + b sin θ = cos d (thesis eq. 4.17). The left side peaks at
    // θ* = atan2(b, a), so the closest point of the band's stretch is θ* clamped to the band.
    const double cosDphi = std::max(std::cos(offset), std::cos(offset - width));
    const double a = cosC, b = sinC * cosDphi;
    const double thetaStar = std::atan2(b, a);
    const double best = thetaStar >= theta0 && thetaStar <= theta1
                            ? std::sqrt(a * a + b * b)
                            : std::max(a * std::cos(theta0) + b * std::sin(theta0),
                                       a * std::cos(theta1) + b * std::sin(theta1));
    return std::acos(std::clamp(best, -1.0, 1.0));
}

void HemisphereGrid::CellsNear(const Imath::V3d& centre, double radius,
                               std::vector<std::pair<int, double>>& cells) const {
    const double thetaC = std::acos(std::clamp(centre.z, -1.0, 1.0));
    const double phiC = std::atan2(centre.y, centre.x);
    for (int band = 0; band < bands_; ++band) {
        // thesis eq. 4.16: only bands within the radius in θ
        const double theta0 = band * bandWidth_;
        if (thetaC < theta0 - radius || thetaC > theta0 + bandWidth_ + radius) continue;
        for (int cell = firstCell_[band]; cell < firstCell_[band + 1]; ++cell) {
            const double d = DistanceToCell(cell, thetaC, phiC);
            if (d < radius) cells.emplace_back(cell, d);
        }
    }
}

}  // namespace gonio
