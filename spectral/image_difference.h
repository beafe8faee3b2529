#pragma once
// The colour difference of two renders of one scene, pixel by pixel: CIEDE2000 in CIELAB
// relative to one white. The render tests of the colour representations and the ΔE2000 maps of
// thesis figs. 6.3, 6.5 and 6.6 (`gonio spectral diff`) use it.

#include <vector>

#include "spectral/colorimetry.h"

namespace gonio::spectral {

struct ImageDifference {
    std::vector<double> perPixel;  // ΔE2000 of each pixel
    double mean = 0, p99 = 0, max = 0;
};

// Both images in display RGB (linear sRGB, D65 white), the same size (else SpectralError).
ImageDifference CompareImages(const std::vector<Rgb>& reference, const std::vector<Rgb>& image,
                              const Xyz& white);

// The white of such a comparison: the chromaticity of `light`'s display RGB, at the luminance
// of the reference's brightest pixel (a scene has no perfect white to measure against, and its
// brightest pixel is the nearest thing to one).
Xyz BrightestPixelWhite(const std::vector<Rgb>& reference, const Rgb& light);

// The colour of a ΔE2000 map pixel: black at 0, through red and yellow to white at `full`
// (and above), so that the eye reads the error's size.
Rgb DifferenceColour(double de, double full);

}  // namespace gonio::spectral
