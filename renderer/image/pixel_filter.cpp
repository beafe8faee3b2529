#include "renderer/image/pixel_filter.h"

#include <cmath>

#include "base/math.h"

namespace gonio {

namespace {

// Catmull-Rom cubic (Keys' cubic convolution with a = -1/2; Mitchell & Netravali 1988 with
// B = 0, C = 1/2), support |x| < 2 pixels, 1 at the centre, 0 at every other integer.
float CatmullRom1D(float x) {
    x = std::fabs(x);
    float x2 = x * x;
    if (x < 1.0f) return 1.5f * x * x2 - 2.5f * x2 + 1.0f;
    if (x < 2.0f) return -0.5f * x * x2 + 2.5f * x2 - 4.0f * x + 2.0f;
    return 0.0f;
}

// Mitchell & Netravali 1988 with B = C = 1/3, its support |x| < 2 stretched over the footprint as
// pbrt does (x = 2 * offset / radius), so the negative lobes fall inside the filter width.
float Mitchell1D(float x) {
    constexpr float B = 1.0f / 3.0f, C = 1.0f / 3.0f;
    x = std::fabs(x);
    float x2 = x * x, x3 = x2 * x;
    if (x < 1.0f)
        return ((12 - 9 * B - 6 * C) * x3 + (-18 + 12 * B + 6 * C) * x2 + (6 - 2 * B)) / 6.0f;
    if (x < 2.0f)
        return ((-B - 6 * C) * x3 + (6 * B + 30 * C) * x2 + (-12 * B - 48 * C) * x +
                (8 * B + 24 * C)) /
               6.0f;
    return 0.0f;
}

// RiSincFilter of the RenderMan C binding (as Pixie ships it): sin(pi x)/(pi x), windowed by
// cos(pi x / (2 width)), which falls to cos(pi/4) at the footprint's edge.
float WindowedSinc1D(float x, float width) {
    if (x == 0.0f) return 1.0f;
    float px = kPiF * x;
    return std::cos(0.5f * px / width) * std::sin(px) / px;
}

}  // namespace

std::optional<PixelFilter> PixelFilter::FromRib(const std::string& name, float xwidth, float ywidth,
                                                std::string& error) {
    static const struct {
        const char* name;
        Kind kind;
    } kNames[] = {{"box", Kind::Box},           {"triangle", Kind::Triangle},
                  {"gaussian", Kind::Gaussian}, {"catmull-rom", Kind::CatmullRom},
                  {"sinc", Kind::Sinc},         {"disk", Kind::Disk},
                  {"mitchell", Kind::Mitchell}};
    if (!(xwidth > 0.0f) || !(ywidth > 0.0f) || !std::isfinite(xwidth) || !std::isfinite(ywidth)) {
        error = "PixelFilter widths must be positive, got " + std::to_string(xwidth) + " " +
                std::to_string(ywidth);
        return std::nullopt;
    }
    for (const auto& entry : kNames)
        if (name == entry.name) return PixelFilter(entry.kind, xwidth, ywidth);
    error = "unknown PixelFilter \"" + name +
            "\" (expected box, triangle, gaussian, catmull-rom, sinc, disk or mitchell)";
    return std::nullopt;
}

const std::string& PixelFilter::Name() const {
    static const std::string kNames[] = {"box",  "triangle", "gaussian", "catmull-rom",
                                         "sinc", "disk",     "mitchell"};
    return kNames[static_cast<int>(kind_)];
}

float PixelFilter::Weight1D(float d, float width) const {
    const float radius = 0.5f * width;
    if (std::fabs(d) > radius) return 0.0f;
    switch (kind_) {
        case Kind::Box:
        case Kind::Disk:
            return 1.0f;
        case Kind::Triangle:
            // The RISpec's sample code divides (1 - |x|) by the half width, which is not a
            // triangle of the given width; this is the tent the text describes.
            return 1.0f - std::fabs(d) / radius;
        case Kind::Gaussian: {
            // RiGaussianFilter (RISpec App. E): exp(-2 ((2x/xw)^2 + (2y/yw)^2)), a product of
            // exp(-2 (2x/xw)^2) and the same in y.
            const float x = d / radius;
            return std::exp(-2.0f * x * x);
        }
        case Kind::CatmullRom:
            // In pixels, not scaled to the width: "catmull-rom 4 4" covers the whole cubic and
            // a narrower width truncates it, as in the RenderMan binding.
            return CatmullRom1D(d);
        case Kind::Sinc:
            return WindowedSinc1D(d, width);
        case Kind::Mitchell:
            return Mitchell1D(2.0f * d / radius);
    }
    return 0.0f;
}

float PixelFilter::Evaluate(float dx, float dy) const {
    if (Separable()) return XWeight(dx) * YWeight(dy);
    // The disk.
    const float x = dx / XRadius(), y = dy / YRadius();
    return x * x + y * y <= 1.0f ? 1.0f : 0.0f;
}

}  // namespace gonio
