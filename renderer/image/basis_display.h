#pragma once
// Display "x.exr" "openexr" "spectral" "int basis" [k]: the spectral image written as k
// coefficients per pixel in a basis computed from the frame's own resolved pixel spectra
// (spectral/image_basis.h), after rendering, so every bounce that reached the camera is in it.
// The layout (channels basis.NN, the vectors and wavelengths in the header) is
// spectral/image_basis_layout.h's.

#include <string>
#include <vector>

#include "spectral/image_basis_layout.h"

namespace gonio {

struct BasisCodedPixels {
    // Pixel-major: the `preview` channels unchanged, then the k coefficients.
    std::vector<float> values;
    std::vector<std::string> coefficientNames;  // basis.00 … basis.(k−1)
    spectral::HeaderAttributes attributes;      // the basis, for the file's header
};

// `values` holds, per pixel, `preview` channels followed by one sample per wavelength. Throws
// std::invalid_argument when k is not in 1..n.
BasisCodedPixels EncodeInImageBasis(const std::vector<float>& values, int preview,
                                    const std::vector<double>& wavelengths, int k);

}  // namespace gonio
