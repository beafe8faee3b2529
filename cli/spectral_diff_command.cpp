// gonio spectral diff REFERENCE.exr IMAGE.exr [--light NAME|FILE] [-o MAP.png] [--full DE]: the
// CIEDE2000 colour difference of two renders of one scene, pixel by pixel (the ΔE2000 maps of
// thesis figs. 6.3, 6.5 and 6.6), in CIELAB relative to the light's white at the reference's
// brightest pixel. Prints the mean, the 99th percentile and the maximum; writes the map.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "renderer/image/rgb_image_file.h"
#include "spectral/image_difference.h"
#include "spectral/named_spectra.h"
#include "spectral/render_color_space.h"
#include "spectral/spectral_error.h"
#include "spectral_cli.h"

namespace gonio {
namespace {

struct DiffOptions {
    std::string reference, image, light = "D65", map;
    double full = 5;
};

// A linear render's pixels (8-bit files hold display-encoded values, which CIELAB cannot use).
std::vector<spectral::Rgb> LinearPixels(const RgbImage& image, const std::string& path) {
    if (!image.floatingPoint)
        throw spectral::SpectralError(
            path + ": expected a linear, floating-point image (OpenEXR, as gonio renders it)");
    std::vector<spectral::Rgb> pixels;
    for (size_t p = 0; p + 2 < image.rgb.size(); p += 3)
        pixels.emplace_back(image.rgb[p], image.rgb[p + 1], image.rgb[p + 2]);
    return pixels;
}

void WriteMap(const std::string& path, const RgbImage& like, const std::vector<double>& de,
              double full) {
    RgbImage map{like.width, like.height, {}, false};
    for (double d : de) {
        const spectral::Rgb colour = spectral::DifferenceColour(d, full);
        for (int c = 0; c < 3; ++c) map.rgb.push_back(float(colour[c]));
    }
    WriteRgbImage(path, map);
}

void RunDiff(const DiffOptions& options) {
    const RgbImage reference = ReadRgbImage(options.reference);
    const RgbImage image = ReadRgbImage(options.image);
    if (reference.width != image.width || reference.height != image.height)
        throw spectral::SpectralError(options.image + ": " + std::to_string(image.width) + "x" +
                                      std::to_string(image.height) + ", the reference is " +
                                      std::to_string(reference.width) + "x" +
                                      std::to_string(reference.height));
    const std::vector<spectral::Rgb> ref = LinearPixels(reference, options.reference);
    const spectral::Xyz white = spectral::BrightestPixelWhite(
        ref, spectral::DisplayRgb(spectral::LookupSpectrum(options.light)));
    const spectral::ImageDifference difference =
        spectral::CompareImages(ref, LinearPixels(image, options.image), white);
    std::printf(
        "%s against %s: ΔE2000 mean %.3f, 99th percentile %.3f, max %.3f (CIELAB "
        "relative to %s's white at the reference's brightest pixel)\n",
        options.image.c_str(), options.reference.c_str(), difference.mean, difference.p99,
        difference.max, options.light.c_str());
    if (!options.map.empty()) WriteMap(options.map, reference, difference.perPixel, options.full);
}

}  // namespace

void AddSpectralDiffCommand(CLI::App& spectral, int* exitCode) {
    auto options = std::make_shared<DiffOptions>();
    CLI::App* diff =
        spectral.add_subcommand("diff", "ΔE2000 of a render against a reference, and its map");
    diff->add_option("reference", options->reference, "the reference render (OpenEXR)")->required();
    diff->add_option("image", options->image, "the render to compare (OpenEXR)")->required();
    diff->add_option("--light", options->light, "the light whose white CIELAB is relative to")
        ->capture_default_str();
    diff->add_option("-o,--map", options->map, "write the ΔE2000 map (black 0, white --full)");
    diff->add_option("--full", options->full, "the ΔE2000 the map shows as white")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    diff->callback(
        [options, exitCode] { RunSpectralGuarded(exitCode, [&] { RunDiff(*options); }); });
}

}  // namespace gonio
