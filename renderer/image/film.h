#pragma once
// The film: every camera sample's raster position and values, kept until the frame is done and
// then resolved into pixels by the pixel filter. Keeping the samples (instead of splatting them
// into pixels as they arrive) makes the result independent of the order in which threads finish,
// and lets samples of neighbouring tiles contribute across tile borders.
//
// Coordinates. Raster space has its origin at the top-left corner of the full frame (Format
// xres yres), x to the right, y down; pixel (px, py) covers [px, px+1) x [py, py+1) and its centre
// is (px + 0.5, py + 0.5). Sample positions are raster positions in that full frame.
//
// Channel layout (a convention shared by the renderer and the image writer): each sample carries
// `channels` floats, in this order: r g b a z, then the AOVs (arbitrary shader outputs) in the
// order the Display requests name them. Colour is premultiplied by alpha, as RenderMan does. z is
// the camera-space depth of the first hit, +infinity where the sample hit nothing.

#include <Imath/ImathBox.h>

#include <vector>

#include "image/pixel_filter.h"

namespace gonio {

enum StandardChannel : int { kChannelR = 0, kChannelG, kChannelB, kChannelA, kChannelZ };
constexpr int kStandardChannelCount = 5;

struct FilmSpec {
    int xres = 640, yres = 480;  // Format
    // The pixel window actually rendered and written, inclusive bounds, in full-frame pixels.
    // See FromCropWindow for the rounding.
    int xmin = 0, xmax = 639, ymin = 0, ymax = 479;
    int xsamples = 2, ysamples = 2;  // PixelSamples
    int channels = kStandardChannelCount;
    // The channel resolved with RenderMan's "min" depth filter (nearest depth among the pixel's
    // own samples) rather than the pixel filter, because averaging depths across an edge invents
    // depths where there is no surface (and +infinity for misses would poison the average).
    // -1 when no channel holds depth.
    int depthChannel = kChannelZ;

    // The window of CropWindow xmin xmax ymin ymax (NDC, 0..1) as RISpec §4.1.1 rounds it:
    //   rxmin = clamp(ceil(xres * xmin), 0, xres - 1)
    //   rxmax = clamp(ceil(xres * xmax - 1), 0, xres - 1)     (and the same for y)
    // so pixel column px belongs to the window when xres*xmin <= px < xres*xmax (its left edge),
    // and two crop windows that share an edge tile the frame without a gap or an overlap. A
    // window that rounds to no pixel (the scene builder should warn about it) keeps one. Sample
    // counts below 1 become 1 (RISpec: "sampling rates less than 1 are clamped to 1").
    // depthChannel is kChannelZ when there are more than 4 channels, else -1.
    static FilmSpec FromCropWindow(int xres, int yres, float cropXmin, float cropXmax,
                                   float cropYmin, float cropYmax, int xsamples, int ysamples,
                                   int channels);

    int WindowWidth() const { return xmax - xmin + 1; }
    int WindowHeight() const { return ymax - ymin + 1; }
    int SamplesPerPixel() const { return xsamples * ysamples; }
};

// A resolved image: the crop window of the frame, row-major from the top, channels interleaved.
struct Image {
    int width = 0, height = 0;
    int channels = 0;
    int xorigin = 0, yorigin = 0;       // position of pixel (0, 0) in the full frame
    int fullWidth = 0, fullHeight = 0;  // the full frame (Format), for the display window
    std::vector<float> pixels;

    float* At(int x, int y) { return &pixels[(size_t(y) * width + x) * channels]; }
    const float* At(int x, int y) const { return &pixels[(size_t(y) * width + x) * channels]; }
};

class Film {
  public:
    // The filter fixes the margin of extra pixels around the window whose samples are needed.
    Film(const FilmSpec& spec, const PixelFilter& filter);

    const FilmSpec& Spec() const { return spec_; }
    const PixelFilter& Filter() const { return filter_; }

    // The pixels whose samples must be rendered, inclusive bounds in full-frame pixels: the
    // window grown by the filter margin on every side. It may reach outside the frame (negative
    // or >= xres): those samples are rendered too, so that pixels at the frame's border are
    // filtered from a full footprint like every other pixel.
    Imath::Box2i PixelRange() const;

    // Stores sample s (0 <= s < SamplesPerPixel()) of pixel (px, py) taken at raster position
    // (x, y), with `Spec().channels` values. Threads may call this concurrently for different
    // (px, py, s). A sample never set is left out of the resolve, and one outside PixelRange()
    // is dropped (no window pixel needs it).
    void SetSample(int px, int py, int s, float x, float y, const float* values);

    // Filters the stored samples into the window's pixels, in parallel. Each pixel sums the
    // samples inside its filter footprint in a fixed order and divides by the sum of weights,
    // so the result is the same whatever the number of threads. Where the weights cancel (a
    // negative lobe), the pixel takes the value of its nearest sample.
    Image Resolve() const;

  private:
    size_t SampleIndex(int px, int py, int s) const;
    void ResolvePixel(int px, int py, std::vector<double>& sum, float* out) const;
    void ResolveDepth(int px, int py, float* out) const;

    FilmSpec spec_;
    PixelFilter filter_;
    int xmargin_, ymargin_;
    int rangeXmin_, rangeYmin_, rangeWidth_, rangeHeight_;
    int stride_;  // floats per sample: x, y, then the channels
    std::vector<float> samples_;
};

}  // namespace gonio
