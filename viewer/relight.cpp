#include "viewer/relight.h"

#include <algorithm>
#include <cmath>

#include "spectral/light_match.h"
#include "spectral/spectral_error.h"

namespace gonio::viewer {

namespace {

Eigen::Matrix3Xd BoxMatrix(int n) {
    Eigen::Matrix3Xd m = Eigen::Matrix3Xd::Zero(3, n);
    for (int i = 0; i < n; ++i) {
        const int third = std::min(2, 3 * i / n);  // 0: shortest wavelengths, blue
        m(2 - third, i) = 1;
    }
    for (int c = 0; c < 3; ++c) m.row(c) /= m.row(c).sum();
    return m;
}

Eigen::Matrix3Xd CieMatrix(const std::vector<double>& wavelengths) {
    const int n = int(wavelengths.size());
    const double step = n > 1 ? (wavelengths.back() - wavelengths.front()) / (n - 1) : 1;
    for (int i = 1; i < n; ++i)
        if (std::abs(wavelengths[i] - wavelengths[i - 1] - step) > 1e-6 * step)
            throw ViewerError("the CIE conversion needs evenly spaced wavelengths");
    try {
        return spectral::RenderRgbMatrix(
            spectral::WavelengthGrid::Make(wavelengths.front(), wavelengths.back(), step));
    } catch (const spectral::SpectralError& e) {
        throw ViewerError(std::string("the CIE conversion: ") + e.what());
    }
}

}  // namespace

RgbConversion ParseRgbConversion(const std::string& name) {
    if (name == "box") return RgbConversion::Box;
    if (name == "cie") return RgbConversion::Cie;
    throw ViewerError("unknown RGB conversion \"" + name + "\": expected \"box\" or \"cie\"");
}

Eigen::Matrix3Xd ConversionMatrix(RgbConversion conversion,
                                  const std::vector<double>& wavelengths) {
    if (conversion == RgbConversion::Box) return BoxMatrix(int(wavelengths.size()));
    return CieMatrix(wavelengths);
}

std::vector<float> Relight(const ReflectanceImage& image, const Eigen::VectorXd& light,
                           const Eigen::Matrix3Xd& toRgb) {
    const int n = image.SampleCount();
    if (light.size() != n || toRgb.cols() != n)
        throw ViewerError("the light has " + std::to_string(light.size()) +
                          " values; the image has " + std::to_string(n) + " wavelengths");
    // Thesis §6.2.4: C = M X diag(l) Bᵀ, once per light: 3 × n for samples (B the identity),
    // 3 × k in a basis (the file's B is n × k), so each pixel costs one 3 × k product.
    const bool inBasis = image.basis.cols() > 0;
    const Eigen::Matrix3Xd c = inBasis ? Eigen::Matrix3Xd(toRgb * light.asDiagonal() * image.basis)
                                       : Eigen::Matrix3Xd(toRgb * light.asDiagonal());
    const std::vector<float>& components = inBasis ? image.coefficients : image.spectra;
    const int k = int(c.cols());
    const size_t pixels = size_t(image.width) * image.height;
    std::vector<float> rgb(3 * pixels);
    for (size_t p = 0; p < pixels; ++p) {
        const Eigen::Map<const Eigen::VectorXf> r(&components[p * k], k);
        const Eigen::Vector3d out = c * r.cast<double>();
        for (int j = 0; j < 3; ++j) rgb[3 * p + j] = float(out[j]);
    }
    return rgb;
}

}  // namespace gonio::viewer
