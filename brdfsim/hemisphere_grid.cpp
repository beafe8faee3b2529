#include "brdfsim/hemisphere_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/math.h"

namespace gonio {

namespace {

// The cells in band b (1-based) of `bands`: thesis eq. 4.14.
int RectsOfBand(int b, int bands, int maxRects) {
    return std::max(static_cast<int>(std::lround(std::sin(0.5 * kPi * b / bands) * maxRects)), 1);
}

}  // namespace

std::uint64_t HemisphereGrid::CellCount(int bands, int maxRects) {
    std::uint64_t cells = 0;
    for (int b = 1; b <= bands; ++b) cells += std::uint64_t(RectsOfBand(b, bands, maxRects));
    return cells;
}

HemisphereGrid::HemisphereGrid(int bands, int maxRects)
    : bands_(bands), maxRects_(maxRects), bandWidth_(0.5 * kPi / bands) {
    if (bands < 1 || maxRects < 1 || bands > 1000 || maxRects > 4000) {
        throw std::invalid_argument("rings must be in 1..1000 and rects in 1..4000");
    }
    firstCell_.push_back(0);
    for (int b = 1; b <= bands; ++b) {
        const int rects = RectsOfBand(b, bands, maxRects);
        firstCell_.push_back(firstCell_.back() + rects);
        bandOfCell_.insert(bandOfCell_.end(), rects, b - 1);
    }
    for (int b = 0; b <= bands; ++b) {
        bandCos_.push_back(std::cos(b * bandWidth_));
        bandSin_.push_back(std::sin(b * bandWidth_));
    }
    for (int cell = 0; cell < NumCells(); ++cell) ComputeBoundingCap(cell);
}

void HemisphereGrid::ComputeBoundingCap(int cell) {
    const int band = bandOfCell_[cell];
    const int rects = RectsInBand(band);
    const double theta0 = band * bandWidth_, theta1 = theta0 + bandWidth_;
    const double width = kTwoPi / rects;
    const double phi0 = (cell - firstCell_[band]) * width;
    auto point = [](double theta, double phi) {
        return Imath::V3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                          std::cos(theta));
    };
    // Centre: the normalised mean of points spread over the cell; radius: the farthest
    // boundary point, sampled finely, with a margin for the sampling.
    const int n = 32;
    Imath::V3d sum(0.0);
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            sum += point(theta0 + (theta1 - theta0) * i / n, phi0 + width * j / n);
        }
    }
    const Imath::V3d centre = rects == 1 ? Imath::V3d(0, 0, 1) : sum.normalized();
    double radius = 0.0;
    for (int i = 0; i <= 4 * n; ++i) {
        const double t = static_cast<double>(i) / (4 * n);
        for (const Imath::V3d& p :
             {point(theta0, phi0 + width * t), point(theta1, phi0 + width * t),
              point(theta0 + (theta1 - theta0) * t, phi0),
              point(theta0 + (theta1 - theta0) * t, phi0 + width)}) {
            radius = std::max(radius, std::acos(std::clamp(centre.dot(p), -1.0, 1.0)));
        }
    }
    cellCentre_.push_back(centre);
    cellRadius_.push_back(radius + 0.01);
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
    return DistanceToCell(cell, thetaC, phiC, std::sin(thetaC), std::cos(thetaC));
}

double HemisphereGrid::DistanceToCell(int cell, double thetaC, double phiC, double sinC,
                                      double cosC) const {
    const int band = bandOfCell_[cell];
    const int rects = RectsInBand(band);
    const double theta0 = band * bandWidth_, theta1 = theta0 + bandWidth_;
    const double width = kTwoPi / rects;
    const double phi0 = (cell - firstCell_[band]) * width;
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
                            : std::max(a * bandCos_[band] + b * bandSin_[band],
                                       a * bandCos_[band + 1] + b * bandSin_[band + 1]);
    return std::acos(std::clamp(best, -1.0, 1.0));
}

CellFinder::CellFinder(const HemisphereGrid& grid, double radius) : grid_(grid), radius_(radius) {
    for (int cell = 0; cell < grid.NumCells(); ++cell) {
        const double reach = radius + grid.cellRadius_[cell];
        cosReach_.push_back(reach < kPi ? std::cos(reach) : -2.0);
    }
}

void CellFinder::Near(const Imath::V3d& centre, std::vector<std::pair<int, double>>& cells) const {
    const double thetaC = std::acos(std::clamp(centre.z, -1.0, 1.0));
    const double phiC = std::atan2(centre.y, centre.x);
    const double sinC = std::sin(thetaC), cosC = std::cos(thetaC);
    for (int band = 0; band < grid_.bands_; ++band) {
        // thesis eq. 4.16: only bands within the radius in θ
        const double theta0 = band * grid_.bandWidth_;
        if (thetaC < theta0 - radius_ || thetaC > theta0 + grid_.bandWidth_ + radius_) continue;
        for (int cell = grid_.firstCell_[band]; cell < grid_.firstCell_[band + 1]; ++cell) {
            if (centre.dot(grid_.cellCentre_[cell]) < cosReach_[cell]) continue;
            const double d = grid_.DistanceToCell(cell, thetaC, phiC, sinC, cosC);
            if (d < radius_) cells.emplace_back(cell, d);
        }
    }
}

}  // namespace gonio
