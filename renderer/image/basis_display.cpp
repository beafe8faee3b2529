#include "renderer/image/basis_display.h"

#include <algorithm>
#include <stdexcept>

#include "spectral/image_basis.h"

namespace gonio {

namespace {

// The samples of every pixel, without its preview channels: the n × P matrix R of
// spectral/image_basis.h, pixel-major.
std::vector<float> SpectralSamples(const std::vector<float>& values, size_t pixels, int preview,
                                   int n) {
    std::vector<float> samples(pixels * size_t(n));
    for (size_t p = 0; p < pixels; ++p)
        std::copy_n(&values[p * size_t(preview + n) + size_t(preview)], n, &samples[p * size_t(n)]);
    return samples;
}

}  // namespace

BasisCodedPixels EncodeInImageBasis(const std::vector<float>& values, int preview,
                                    const std::vector<double>& wavelengths, int k) {
    const int n = int(wavelengths.size());
    if (k < 1 || k > n)
        throw std::invalid_argument("\"basis\" " + std::to_string(k) +
                                    ": a basis has 1 to as many vectors as wavelengths (" +
                                    std::to_string(n) + ")");
    const size_t pixels = values.size() / size_t(preview + n);
    const std::vector<float> samples = SpectralSamples(values, pixels, preview, n);
    const spectral::ImageSpectraBasis principal =
        spectral::PrincipalSpectra(samples.data(), pixels, n);
    const Eigen::MatrixXd basis = principal.Basis(k);
    const std::vector<float> coefficients = spectral::ProjectSpectra(samples.data(), pixels, basis);

    BasisCodedPixels coded;
    coded.values.resize(pixels * size_t(preview + k));
    for (size_t p = 0; p < pixels; ++p) {
        float* out = &coded.values[p * size_t(preview + k)];
        std::copy_n(&values[p * size_t(preview + n)], preview, out);
        std::copy_n(&coefficients[p * size_t(k)], k, out + preview);
    }
    for (int i = 0; i < k; ++i) coded.coefficientNames.push_back(spectral::BasisChannelName(i));
    coded.attributes =
        spectral::BasisHeaderAttributes(wavelengths, basis, principal.LostEnergyFraction(k));
    return coded;
}

}  // namespace gonio
