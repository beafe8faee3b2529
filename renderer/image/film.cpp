#include "image/film.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gonio {

namespace {

int ClampInt(int value, int low, int high) { return std::max(low, std::min(value, high)); }

// Pixels beyond the window whose samples can reach a window pixel: a sample of pixel q lies in
// [q, q+1) and counts for pixel p when -radius <= x - (p + 0.5) < radius.
int FilterMargin(float radius) { return std::max(0, int(std::ceil(0.5f + radius)) - 1); }

// Below this fraction of the summed absolute weights, the weights of a pixel are taken to have
// cancelled (negative lobes), and dividing by their sum would only amplify noise.
constexpr float kCancelledWeightFraction = 1e-3f;

}  // namespace

FilmSpec FilmSpec::FromCropWindow(int xres, int yres, float cropXmin, float cropXmax,
                                  float cropYmin, float cropYmax, int xsamples, int ysamples,
                                  int channels) {
    FilmSpec spec;
    spec.xres = xres = std::max(1, xres);
    spec.yres = yres = std::max(1, yres);
    // RISpec §4.1.1 (RiCropWindow).
    spec.xmin = ClampInt(int(std::ceil(xres * cropXmin)), 0, xres - 1);
    spec.xmax = ClampInt(int(std::ceil(xres * cropXmax - 1.0f)), 0, xres - 1);
    spec.ymin = ClampInt(int(std::ceil(yres * cropYmin)), 0, yres - 1);
    spec.ymax = ClampInt(int(std::ceil(yres * cropYmax - 1.0f)), 0, yres - 1);
    // A window that rounds to nothing (or is given backwards) keeps one pixel.
    spec.xmax = std::max(spec.xmax, spec.xmin);
    spec.ymax = std::max(spec.ymax, spec.ymin);
    spec.xsamples = std::max(1, xsamples);
    spec.ysamples = std::max(1, ysamples);
    spec.channels = std::max(1, channels);
    spec.depthChannel = channels > kChannelZ ? int(kChannelZ) : -1;
    return spec;
}

Film::Film(const FilmSpec& spec, const PixelFilter& filter)
    : spec_(spec),
      filter_(filter),
      xmargin_(FilterMargin(filter.XRadius())),
      ymargin_(FilterMargin(filter.YRadius())),
      rangeXmin_(spec.xmin - xmargin_),
      rangeYmin_(spec.ymin - ymargin_),
      rangeWidth_(spec.WindowWidth() + 2 * xmargin_),
      rangeHeight_(spec.WindowHeight() + 2 * ymargin_),
      stride_(2 + spec.channels) {
    // A NaN position marks a sample never set.
    samples_.assign(size_t(rangeWidth_) * rangeHeight_ * spec.SamplesPerPixel() * stride_,
                    std::numeric_limits<float>::quiet_NaN());
}

Imath::Box2i Film::PixelRange() const {
    return Imath::Box2i(Imath::V2i(rangeXmin_, rangeYmin_),
                        Imath::V2i(rangeXmin_ + rangeWidth_ - 1, rangeYmin_ + rangeHeight_ - 1));
}

size_t Film::SampleIndex(int px, int py, int s) const {
    size_t pixel = size_t(py - rangeYmin_) * rangeWidth_ + size_t(px - rangeXmin_);
    return (pixel * spec_.SamplesPerPixel() + s) * stride_;
}

void Film::SetSample(int px, int py, int s, float x, float y, const float* values) {
    if (px < rangeXmin_ || px >= rangeXmin_ + rangeWidth_ || py < rangeYmin_ ||
        py >= rangeYmin_ + rangeHeight_ || s < 0 || s >= spec_.SamplesPerPixel())
        return;  // no window pixel needs it
    float* sample = &samples_[SampleIndex(px, py, s)];
    sample[0] = x;
    sample[1] = y;
    std::copy(values, values + spec_.channels, sample + 2);
}

void Film::ResolvePixel(int px, int py, std::vector<double>& sum, float* out) const {
    const int channels = spec_.channels, spp = spec_.SamplesPerPixel();
    const float cx = px + 0.5f, cy = py + 0.5f;
    const float xr = filter_.XRadius(), yr = filter_.YRadius();
    std::fill(sum.begin(), sum.end(), 0.0);
    double weightSum = 0.0, absWeightSum = 0.0;
    const float* nearest = nullptr;
    float nearestDistance = std::numeric_limits<float>::infinity();
    // Fixed order (rows, columns, samples) so the floating-point sums never depend on threads.
    for (int qy = py - ymargin_; qy <= py + ymargin_; ++qy) {
        for (int qx = px - xmargin_; qx <= px + xmargin_; ++qx) {
            const float* sample = &samples_[SampleIndex(qx, qy, 0)];
            for (int s = 0; s < spp; ++s, sample += stride_) {
                if (std::isnan(sample[0])) continue;
                float dx = sample[0] - cx, dy = sample[1] - cy;
                if (dx < -xr || dx >= xr || dy < -yr || dy >= yr) continue;
                float distance = dx * dx + dy * dy;
                if (distance < nearestDistance) {
                    nearestDistance = distance;
                    nearest = sample;
                }
                float w = filter_.Evaluate(dx, dy);
                if (w == 0.0f) continue;
                weightSum += w;
                absWeightSum += std::fabs(w);
                for (int c = 0; c < channels; ++c) sum[c] += double(w) * sample[2 + c];
            }
        }
    }
    bool cancelled =
        absWeightSum == 0.0 || std::fabs(weightSum) < kCancelledWeightFraction * absWeightSum;
    for (int c = 0; c < channels; ++c) {
        if (!cancelled)
            out[c] = float(sum[c] / weightSum);
        else
            out[c] = nearest ? nearest[2 + c] : 0.0f;
    }
}

void Film::ResolveDepth(int px, int py, float* out) const {
    // RenderMan's "min" depth filter over the pixel's own samples.
    float depth = std::numeric_limits<float>::infinity();
    const float* sample = &samples_[SampleIndex(px, py, 0)];
    for (int s = 0; s < spec_.SamplesPerPixel(); ++s, sample += stride_)
        if (!std::isnan(sample[0])) depth = std::min(depth, sample[2 + spec_.depthChannel]);
    out[spec_.depthChannel] = depth;
}

Image Film::Resolve() const {
    Image image;
    image.width = spec_.WindowWidth();
    image.height = spec_.WindowHeight();
    image.channels = spec_.channels;
    image.xorigin = spec_.xmin;
    image.yorigin = spec_.ymin;
    image.fullWidth = spec_.xres;
    image.fullHeight = spec_.yres;
    image.pixels.resize(size_t(image.width) * image.height * image.channels);
    const bool hasDepth = spec_.depthChannel >= 0 && spec_.depthChannel < spec_.channels;
    tbb::parallel_for(tbb::blocked_range<int>(0, image.height), [&](const auto& rows) {
        std::vector<double> sums(spec_.channels);
        for (int y = rows.begin(); y != rows.end(); ++y) {
            for (int x = 0; x < image.width; ++x) {
                float* out = image.At(x, y);
                ResolvePixel(spec_.xmin + x, spec_.ymin + y, sums, out);
                if (hasDepth) ResolveDepth(spec_.xmin + x, spec_.ymin + y, out);
            }
        }
    });
    return image;
}

}  // namespace gonio
