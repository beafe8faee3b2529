#pragma once
// A reflectance image (thesis §6.2.1): a spectral render under an equal-energy light, so that
// each pixel holds the scene's spectral transfer at the image's wavelengths and any light can be
// applied afterwards. It is read from the spectral OpenEXR that `gonio render` writes
// (Display "x.exr" "openexr" "spectral"): Fichet et al. 2021's channels "S0.<λ>nm" with a comma
// for the decimal point, beside the RGB preview; or, written with "int basis" [k], k coefficients
// per pixel in a basis of the image's own spectra (channels "basis.NN", the basis in the header:
// spectral/image_basis_layout.h).

#include <Eigen/Dense>
#include <stdexcept>
#include <string>
#include <vector>

namespace gonio::viewer {

// An error in what the viewer was given (a file, a request); the text names what was wrong.
class ViewerError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct ReflectanceImage {
    std::string path;
    int width = 0, height = 0;
    // Increasing, as the file's channels give them (the layout sorts channels by name, not by
    // wavelength, so they are reordered here).
    std::vector<double> wavelengths;
    // Pixel-major from the top row: sample k of pixel (x, y) at (y·width + x)·n + k. For an
    // image in a basis, each pixel's basis · coefficients.
    std::vector<float> spectra;
    // An image in a basis: n × k, its vectors at the wavelengths, and each pixel's k coefficients
    // (pixel-major), which relighting uses (k products per pixel, not n). For an image of
    // samples: no columns, no coefficients.
    Eigen::MatrixXd basis;
    std::vector<float> coefficients;
    // The file's R, G, B preview, 3 per pixel in the same order; empty when the file has none.
    std::vector<float> previewRgb;

    int SampleCount() const { return int(wavelengths.size()); }
};

// The wavelength of a channel "S0.552,50nm" (or "S0.552.50nm"), or false for any other name.
bool ParseSpectralChannelName(const std::string& name, double* nm);

// Throws ViewerError naming `path` when the file cannot be read, is not an OpenEXR image, has no
// spectral channels, holds a non-finite sample, or (an image in a basis) has a basis header that
// is missing or malformed.
ReflectanceImage ReadReflectanceImage(const std::string& path);

}  // namespace gonio::viewer
