#include "spectral/colorimetry.h"

#include <cmath>

#include "base/math.h"

namespace gonio::spectral {

namespace {

Eigen::Matrix3d SrgbFromXyz() {
    // IEC 61966-2-1:1999 §5.2, as printed.
    Eigen::Matrix3d m;
    m << 3.2406, -1.5372, -0.4986, -0.9689, 1.8758, 0.0415, 0.0557, -0.2040, 1.0570;
    return m;
}

Eigen::Matrix3d Bradford() {
    Eigen::Matrix3d m;
    m << 0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296;
    return m;
}

double Degrees(double radians) { return radians / kDegree; }
double Radians(double degrees) { return degrees * kDegree; }

}  // namespace

SampledObserver SampleObserver(const Observer& observer, const WavelengthGrid& grid) {
    SampledObserver sampled{grid, Eigen::Matrix<double, 3, Eigen::Dynamic>(3, grid.Count())};
    const Spectrum* functions[3] = {&observer.x, &observer.y, &observer.z};
    for (int row = 0; row < 3; ++row) {
        const std::vector<double> values = functions[row]->Sample(grid, Resampling::Linear);
        for (int i = 0; i < grid.Count(); ++i) sampled.cmf(row, i) = values[i] * grid.step;
    }
    return sampled;
}

Eigen::VectorXd SampleSpectrum(const Spectrum& spectrum, const WavelengthGrid& grid) {
    const std::vector<double> values = spectrum.Sample(grid);
    return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
}

Xyz Tristimulus(const Eigen::VectorXd& spd, const SampledObserver& observer) {
    return observer.cmf * spd;
}

Xyz EmissiveXyz(const Spectrum& light, const SampledObserver& observer) {
    const Xyz xyz = Tristimulus(SampleSpectrum(light, observer.grid), observer);
    return xyz * (100 / xyz.y());
}

Xyz ReflectanceXyz(const Spectrum& reflectance, const Spectrum& illuminant,
                   const SampledObserver& observer) {
    const Eigen::VectorXd s = SampleSpectrum(illuminant, observer.grid);
    const Eigen::VectorXd r = SampleSpectrum(reflectance, observer.grid);
    const double k = 100 / Tristimulus(s, observer).y();  // CIE 15:2004 eq. 7.3
    return k * Tristimulus(s.cwiseProduct(r), observer);  // eq. 7.1-7.2
}

Eigen::Vector2d Chromaticity(const Xyz& xyz) {
    const double sum = xyz.sum();
    return Eigen::Vector2d(xyz.x() / sum, xyz.y() / sum);
}

Xyz SrgbWhite() {
    // IEC 61966-2-1: D65 at x = 0.3127, y = 0.3290, Y = 1.
    const double x = 0.3127, y = 0.3290;
    return Xyz(x / y, 1, (1 - x - y) / y);
}

Rgb XyzToLinearSrgb(const Xyz& xyz) { return SrgbFromXyz() * xyz; }

Xyz LinearSrgbToXyz(const Rgb& rgb) { return SrgbFromXyz().inverse() * rgb; }

Xyz BradfordAdapt(const Xyz& xyz, const Xyz& sourceWhite, const Xyz& destinationWhite) {
    const Eigen::Matrix3d m = Bradford();
    const Eigen::Vector3d source = m * sourceWhite, destination = m * destinationWhite;
    return m.inverse() * (destination.cwiseQuotient(source).asDiagonal() * (m * xyz));
}

Rgb XyzToDisplaySrgb(const Xyz& xyz, const Xyz& sceneWhite) {
    // Adapt a white of the scene's Y to D65 of the same Y, so only the chromaticity changes.
    return XyzToLinearSrgb(BradfordAdapt(xyz, sceneWhite, SrgbWhite() * sceneWhite.y()) /
                           sceneWhite.y());
}

Lab XyzToLab(const Xyz& xyz, const Xyz& white) {
    // CIE 15:2004 eq. 8.1-8.3 with the linear segment below (6/29)³ (eq. 8.4's f).
    auto f = [](double t) {
        constexpr double delta = 6.0 / 29.0;
        return t > delta * delta * delta ? std::cbrt(t) : t / (3 * delta * delta) + 4.0 / 29.0;
    };
    const double fx = f(xyz.x() / white.x()), fy = f(xyz.y() / white.y()),
                 fz = f(xyz.z() / white.z());
    return Lab(116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz));
}

double Ciede2000(const Lab& lab1, const Lab& lab2, double kL, double kC, double kH) {
    // Sharma, Wu, Dalal 2005, "The CIEDE2000 color-difference formula: implementation notes",
    // eq. 1-22; hue angles in degrees as the paper writes them.
    const double pow25to7 = 6103515625.0;  // 25⁷
    const double L1 = lab1[0], a1 = lab1[1], b1 = lab1[2];
    const double L2 = lab2[0], a2 = lab2[1], b2 = lab2[2];
    const double C1 = std::hypot(a1, b1), C2 = std::hypot(a2, b2);  // eq. 2
    const double Cbar = (C1 + C2) / 2;                              // eq. 3
    const double Cbar7 = std::pow(Cbar, 7);
    const double G = 0.5 * (1 - std::sqrt(Cbar7 / (Cbar7 + pow25to7)));  // eq. 4
    const double a1p = (1 + G) * a1, a2p = (1 + G) * a2;                 // eq. 5
    const double C1p = std::hypot(a1p, b1), C2p = std::hypot(a2p, b2);   // eq. 6
    auto hue = [](double b, double ap) {                                 // eq. 7
        if (b == 0 && ap == 0) return 0.0;
        double h = Degrees(std::atan2(b, ap));
        return h < 0 ? h + 360 : h;
    };
    const double h1p = hue(b1, a1p), h2p = hue(b2, a2p);
    const double dLp = L2 - L1;    // eq. 8
    const double dCp = C2p - C1p;  // eq. 9
    double dhp = 0;                // eq. 10
    if (C1p * C2p != 0) {
        dhp = h2p - h1p;
        if (dhp > 180) dhp -= 360;
        if (dhp < -180) dhp += 360;
    }
    const double dHp = 2 * std::sqrt(C1p * C2p) * std::sin(Radians(dhp / 2));  // eq. 11
    const double Lbarp = (L1 + L2) / 2;                                        // eq. 12
    const double Cbarp = (C1p + C2p) / 2;                                      // eq. 13
    double hbarp = h1p + h2p;                                                  // eq. 14
    if (C1p * C2p != 0) {
        if (std::abs(h1p - h2p) <= 180)
            hbarp = (h1p + h2p) / 2;
        else if (h1p + h2p < 360)
            hbarp = (h1p + h2p + 360) / 2;
        else
            hbarp = (h1p + h2p - 360) / 2;
    }
    const double T = 1 - 0.17 * std::cos(Radians(hbarp - 30)) +
                     0.24 * std::cos(Radians(2 * hbarp)) + 0.32 * std::cos(Radians(3 * hbarp + 6)) -
                     0.20 * std::cos(Radians(4 * hbarp - 63));              // eq. 15
    const double dTheta = 30 * std::exp(-std::pow((hbarp - 275) / 25, 2));  // eq. 16
    const double Cbarp7 = std::pow(Cbarp, 7);
    const double RC = 2 * std::sqrt(Cbarp7 / (Cbarp7 + pow25to7));  // eq. 17
    const double Lm50 = (Lbarp - 50) * (Lbarp - 50);
    const double SL = 1 + 0.015 * Lm50 / std::sqrt(20 + Lm50);  // eq. 18
    const double SC = 1 + 0.045 * Cbarp;                        // eq. 19
    const double SH = 1 + 0.015 * Cbarp * T;                    // eq. 20
    const double RT = -std::sin(Radians(2 * dTheta)) * RC;      // eq. 21
    const double l = dLp / (kL * SL), c = dCp / (kC * SC), h = dHp / (kH * SH);
    return std::sqrt(l * l + c * c + h * h + RT * c * h);  // eq. 22
}

}  // namespace gonio::spectral
