#pragma once
// Applying a light to a reflectance image (thesis §6.2.3-6.2.4): pixel_rgb = M diag(l) r, where
// r is the pixel's spectral transfer, l the light at the image's wavelengths and M the 3×n matrix
// of the "RGB conversion" (Appendix D.1.1). The matrix C = M diag(l) is formed once per light and
// each pixel costs one 3×n product (§6.2.4); for an image in a basis B (n × k) the matrix is
// C = M diag(l) B and each pixel's k coefficients cost one 3×k product.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "viewer/reflectance_image.h"

namespace gonio::viewer {

// Appendix D.1.1's "RGB Conversion" menu.
enum class RgbConversion {
    // Three non-overlapping box functions of the same width (the thesis's default): B, G and R
    // are the means of the first, second and last third of the samples, so a constant spectrum c
    // is RGB (c, c, c).
    Box,
    // The CIE observer to linear sRGB, as `gonio render` makes its preview
    // (spectral::SampledColorSpace).
    Cie,
};

// "box" or "cie" (case-sensitive, as the API spells them); throws ViewerError otherwise.
RgbConversion ParseRgbConversion(const std::string& name);

// The 3×n matrix M for samples at `wavelengths` (increasing, evenly spaced for Cie). Throws
// ViewerError when the CIE tables do not cover them.
Eigen::Matrix3Xd ConversionMatrix(RgbConversion conversion, const std::vector<double>& wavelengths);

// Linear RGB, 3 floats per pixel in the image's order. `light` has one value per wavelength
// (throws ViewerError otherwise).
std::vector<float> Relight(const ReflectanceImage& image, const Eigen::VectorXd& light,
                           const Eigen::Matrix3Xd& toRgb);

}  // namespace gonio::viewer
