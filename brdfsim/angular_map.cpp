#include "brdfsim/angular_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "base/math.h"
#include "imageio/image_formats.h"

namespace gonio {

namespace {

using Rgb = std::array<float, 3>;

Rgb Lerp(const std::vector<Rgb>& anchors, float t) {
    t = std::clamp(t, 0.0f, 1.0f) * (anchors.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(t), anchors.size() - 2);
    const float u = t - i;
    Rgb c;
    for (int k = 0; k < 3; ++k) c[k] = (1 - u) * anchors[i][k] + u * anchors[i + 1][k];
    return c;
}

Rgb Colour(ColourMap map, float t) {
    static const std::vector<Rgb> viridis = {
        {0.267f, 0.005f, 0.329f}, {0.283f, 0.141f, 0.458f}, {0.254f, 0.265f, 0.530f},
        {0.207f, 0.372f, 0.553f}, {0.164f, 0.471f, 0.558f}, {0.128f, 0.567f, 0.551f},
        {0.135f, 0.659f, 0.518f}, {0.267f, 0.749f, 0.441f}, {0.478f, 0.821f, 0.318f},
        {0.741f, 0.873f, 0.150f}, {0.993f, 0.906f, 0.144f}};
    static const std::vector<Rgb> heat = {{0, 0, 0},    {0.5f, 0, 0}, {1, 0.2f, 0},
                                          {1, 0.7f, 0}, {1, 1, 0.4f}, {1, 1, 1}};
    switch (map) {
        case ColourMap::kViridis:
            return Lerp(viridis, t);
        case ColourMap::kHeat:
            return Lerp(heat, t);
        default: {
            const float g = std::clamp(t, 0.0f, 1.0f);
            return {g, g, g};
        }
    }
}

}  // namespace

ColourMap ParseColourMap(const std::string& text) {
    if (text == "none") return ColourMap::kNone;
    if (text == "grey" || text == "gray") return ColourMap::kGrey;
    if (text == "viridis") return ColourMap::kViridis;
    if (text == "heat") return ColourMap::kHeat;
    throw std::invalid_argument("--colormap expects none, grey, viridis or heat, got '" + text +
                                "'");
}

AngularMapResult WriteAngularMap(const Brdf& brdf, const AngularMapOptions& options,
                                 const std::string& path) {
    if (options.size < 8 || options.size > 8192) {
        throw std::invalid_argument("map size must be in 8..8192 pixels");
    }
    const int size = options.size;
    const int bar = options.scaleBar ? std::max(8, size / 16) : 0;
    const int gap = options.scaleBar ? std::max(4, size / 32) : 0;
    const int width = size + gap + bar;
    std::vector<float> pixels(static_cast<std::size_t>(width) * size * 3, 0.0f);
    std::vector<float> rowMax(size, 0.0f);
    const Imath::V3f wIn =
        DirectionFromAngles(options.thetaLight * kDegree, options.phiLight * kDegree);
    const int n = brdf.NumComponents();
    tbb::parallel_for(0, size, [&](int y) {
        std::vector<float> f(n);
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size * 2 - 1, v = 1 - (y + 0.5) / size * 2;
            const double r = std::sqrt(u * u + v * v);
            if (r >= 1) continue;
            brdf.Eval(wIn, DirectionFromAngles(r * 0.5 * kPi, std::atan2(v, u)), f.data());
            rowMax[y] = std::max(rowMax[y], f[0]);
            float* p = &pixels[(static_cast<std::size_t>(y) * width + x) * 3];
            if (options.colourMap == ColourMap::kNone) {
                for (int c = 0; c < 3; ++c) {
                    p[c] = static_cast<float>(f[n == 3 ? c : 0] * options.energyScale);
                }
            } else {
                const Rgb c =
                    Colour(options.colourMap, static_cast<float>(f[0] * options.energyScale));
                std::copy(c.begin(), c.end(), p);
            }
        }
    });
    for (int y = 0; y < size && bar; ++y) {  // 0 at the bottom, 1/energyScale at the top
        const float t = 1.0f - (y + 0.5f) / size;
        const Rgb c = Colour(options.colourMap, t);
        for (int x = size + gap; x < width; ++x) {
            std::copy(c.begin(), c.end(), &pixels[(static_cast<std::size_t>(y) * width + x) * 3]);
        }
    }
    const std::string format = FormatForFileName(path);
    if (format.empty()) throw std::runtime_error(path + ": no image writer for this file type");
    ImageFileSpec spec;
    spec.width = width, spec.height = size;
    spec.channelNames = {"R", "G", "B"};
    spec.fileType = format == "openexr" || format == "hdr" ? PixelType::Float : PixelType::UInt8;
    spec.attributes = {{"ImageDescription", "gonio brdf map: theta_light " +
                                                std::to_string(options.thetaLight) + " phi_light " +
                                                std::to_string(options.phiLight)}};
    const std::string error =
        WriteImageFile(format, path, spec, PixelBuffer{PixelType::Float, pixels.data()});
    if (!error.empty()) throw std::runtime_error(path + ": cannot write the map: " + error);
    AngularMapResult result;
    result.maxValue = *std::max_element(rowMax.begin(), rowMax.end());
    return result;
}

}  // namespace gonio
