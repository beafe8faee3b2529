#include "spectral/image_difference.h"

#include <algorithm>

#include "spectral/spectral_error.h"

namespace gonio::spectral {

ImageDifference CompareImages(const std::vector<Rgb>& reference, const std::vector<Rgb>& image,
                              const Xyz& white) {
    if (reference.size() != image.size() || reference.empty())
        throw SpectralError("the images to compare must have the same, non-zero size");
    ImageDifference difference;
    for (size_t p = 0; p < reference.size(); ++p) {
        const double de = Ciede2000(XyzToLab(LinearSrgbToXyz(reference[p]), white),
                                    XyzToLab(LinearSrgbToXyz(image[p]), white));
        difference.perPixel.push_back(de);
        difference.mean += de / double(reference.size());
    }
    std::vector<double> sorted = difference.perPixel;
    std::sort(sorted.begin(), sorted.end());
    difference.p99 = sorted[size_t(0.99 * double(sorted.size() - 1))];
    difference.max = sorted.back();
    return difference;
}

Xyz BrightestPixelWhite(const std::vector<Rgb>& reference, const Rgb& light) {
    double brightest = 0;
    for (const Rgb& p : reference) brightest = std::max(brightest, LinearSrgbToXyz(p).y());
    const Xyz lightXyz = LinearSrgbToXyz(light);
    if (!(lightXyz.y() > 0)) throw SpectralError("the light of the comparison is black");
    return lightXyz * (brightest / lightXyz.y());
}

Rgb DifferenceColour(double de, double full) {
    const double t = 3 * std::clamp(de / full, 0.0, 1.0);
    return Rgb(std::min(t, 1.0), std::clamp(t - 1, 0.0, 1.0), std::clamp(t - 2, 0.0, 1.0));
}

}  // namespace gonio::spectral
