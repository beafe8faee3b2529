#pragma once
// The film: camera samples filtered into pixels. The frame is cut into square tiles; the
// renderer splats each tile's samples into a FilmTile (filter-weighted sums for every pixel the
// samples reach, including pixels of neighbouring tiles), and each pixel adds the sums of the
// tiles that reach it in tile order, as soon as they are all stored (StoreTile) or at the end
// (Resolve). The result is therefore the same whatever order threads finish their tiles in;
// only a few floats per pixel are kept instead of every sample, and the filter sums only for a
// band of unfinished tiles.
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

#include <cstdint>
#include <mutex>
#include <vector>

#include "renderer/image/filter_reach_table.h"
#include "renderer/image/filter_table.h"
#include "renderer/image/pixel_filter.h"

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

    bool HasDepth() const { return depthChannel >= 0 && depthChannel < channels; }
    int DepthChannelOrNone() const { return HasDepth() ? depthChannel : -1; }
    // The channels the pixel filter sums: all but depth.
    int FilteredChannels() const { return channels - (HasDepth() ? 1 : 0); }
    int WindowWidth() const { return xmax - xmin + 1; }
    int WindowHeight() const { return ymax - ymin + 1; }
    int SamplesPerPixel() const { return xsamples * ysamples; }
};

// The window `part` (xmin xmax ymin ymax, as fractions of `window`) of the crop window `window`
// (NDC), in NDC: a tile of a scene that has a CropWindow of its own. Two parts that share an
// edge value share the composed edge value too (the same arithmetic on the same numbers), so
// tiles cover the window without a gap or an overlap (see FromCropWindow).
void ComposeCropWindow(const float window[4], const float part[4], float out[4]);

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

class FilmTile;

class Film {
  public:
    // The filter fixes the margin of extra pixels around the window whose samples are needed.
    Film(const FilmSpec& spec, const PixelFilter& filter, int tileSize = 16);

    // At most what such a film holds (every tile stored, and the resolved image; StoreTile lets
    // finished tiles go, so a render holds far less), so a render can refuse one that cannot
    // fit before allocating it.
    static double BytesNeeded(const FilmSpec& spec, const PixelFilter& filter);

    const FilmSpec& Spec() const { return spec_; }
    const PixelFilter& Filter() const { return filter_; }

    // The pixels whose samples must be rendered, inclusive bounds in full-frame pixels: the
    // window grown by the filter margin on every side. It may reach outside the frame (negative
    // or >= xres): those samples are rendered too, so that pixels at the frame's border are
    // filtered from a full footprint like every other pixel.
    Imath::Box2i PixelRange() const;

    // PixelRange() cut into tiles of tileSize x tileSize pixels (smaller at the right and bottom
    // edges), numbered row by row.
    int TileCount() const { return tilesX_ * tilesY_; }
    Imath::Box2i TilePixels(int tile) const;

    // An empty tile to splat the samples of TilePixels(tile) into.
    FilmTile StartTile(int tile) const;
    // Takes a finished tile (each tile once; threads may store different tiles concurrently).
    // As soon as every tile whose samples reach a tile's pixels is stored, those pixels are
    // resolved, and a stored tile is let go once every pixel it reaches is resolved: a frame
    // holds its resolved image and a band of tiles, not the filter sums of every pixel.
    void StoreTile(FilmTile&& tile);

    // The window's pixels, filtered: those StoreTile has not resolved yet are resolved now from
    // the tiles stored. Each pixel adds the sums of the tiles that reach it in tile order and
    // divides by the sum of weights, so the result is the same whatever the number of threads
    // and whatever order the tiles came in. Where the weights cancel (a negative lobe), the
    // pixel takes the value of its nearest sample; a pixel no sample reaches is 0. Call once.
    Image Resolve();

    // Whether some pixel's weights can sum to (nearly) 0, so that the film must keep each
    // pixel's nearest sample as Resolve's fallback: filters with negative lobes, and footprints
    // too small to hold all of a pixel's own samples.
    static bool WeightsCanCancel(const PixelFilter& filter);

  private:
    friend class FilmTile;
    // The window pixels that samples of `pixels` can reach.
    Imath::Box2i Footprint(const Imath::Box2i& pixels) const;
    void ResolvePixel(int px, int py, std::vector<double>& sum, float* out) const;
    // The tiles within reach of `tile` (whose samples can reach its pixels, and whose pixels its
    // samples can reach), itself included, as a tile-index box.
    Imath::Box2i TilesInReach(int tile) const;
    bool AllInReach(int tile, const std::vector<uint8_t>& flags) const;
    // Resolves the window pixels of `tile` into image_ (StoreTile and Resolve, under mutex_).
    void ResolveTile(int tile);
    void ResolveReadyTiles(int stored);

    FilmSpec spec_;
    PixelFilter filter_;
    FilterTable xWeight_, yWeight_;  // a separable filter's axes, for the per-sample path
    bool narrow_;                    // separable, and FilterReachTable covers both radii
    int tileSize_;
    int xmargin_, ymargin_;
    FilterReachTable xReach_, yReach_;  // where narrow_
    bool keepNearest_;
    Imath::Box2i range_;
    int tilesX_, tilesY_;
    int reachX_, reachY_;  // tiles each way within reach of a tile
    std::vector<FilmTile> tiles_;
    std::mutex mutex_;  // guards what follows and the stores into tiles_
    std::vector<uint8_t> stored_, resolved_;
    Image image_;
};

// The samples of one tile, splatted: for each window pixel they reach, the filter-weighted sums
// of their channels, the sums of weights, the nearest sample (the fallback where weights cancel)
// and the smallest depth among the pixel's own samples (RenderMan's "min" depth filter).
class FilmTile {
  public:
    FilmTile() = default;

    // Adds a sample of pixel (px, py) taken at raster position (x, y), with Spec().channels
    // values. A sample of a pixel outside the tile is dropped.
    void AddSample(int px, int py, float x, float y, const float* values);
    // Adds `count` samples of pixel (px, py) at once, the same as adding them in turn (up to
    // rounding: the usual filters sum the batch in float first): `positions` holds their
    // (x, y), `values` their Spec().channels values each.
    void AddPixelSamples(int px, int py, int count, const float* positions, const float* values);

  private:
    friend class Film;
    FilmTile(const Film& film, int index);
    size_t PixelIndex(int px, int py) const {
        return size_t(py - footprint_.min.y) * size_t(footprint_.max.x - footprint_.min.x + 1) +
               size_t(px - footprint_.min.x);
    }
    // Fills columns_ with the columns of `reach` that a sample at x falls within the filter's
    // radius of (those of weight 0 only with kKeepZeroWeights); returns how many.
    template <bool kKeepZeroWeights>
    int FindColumns(const Imath::Box2i& reach, float x);
    // AddPixelSamples' two ways to splat into the footprint pixels `reach`: the usual case
    // (separableColourAndAlpha_, and LookUpReachWeights takes the batch), a pixel's samples at
    // once, and every other, a sample at (x, y) at a time.
    bool LookUpReachWeights(int px, int py, int count, const float* positions, const float* values);
    template <int kColumns>
    void AddReachRows(int px, int py, const Imath::Box2i& reach, int count, const float* values);
    void AddAnyChannels(const Imath::Box2i& reach, float x, float y, const float* values);
    // Makes a sample at squared distance `distance` from the pixel's centre its nearest one, if
    // it is nearer than the one kept.
    void KeepNearest(size_t pixel, float distance, const float* values);

    const Film* film_ = nullptr;
    int index_ = -1;
    Imath::Box2i pixels_;     // whose samples it takes
    Imath::Box2i footprint_;  // the window pixels they can reach
    int channels_ = 0;
    // Per footprint pixel, side by side (one cache line for the standard channels): the sum of
    // weights, the sum of |weights|, then the weighted sums of the filtered channels: all but
    // the depth channel (resolved by min, from depth_), in channel order.
    std::vector<double> sums_;
    // Distance², then the channels: 1 + channels_ per pixel; empty unless the film keeps them.
    std::vector<float> nearest_;
    std::vector<float> depth_;  // per footprint pixel
    int filtered_ = 0;          // channels summed in sums_
    int depthChannel_ = -1;     // Spec().DepthChannelOrNone()
    // A narrow separable filter (Film::narrow_), no nearest samples kept, and r g b a the
    // filtered channels.
    bool separableColourAndAlpha_ = false;
    size_t Stride() const { return 2 + size_t(filtered_); }  // doubles a pixel in sums_

    // Scratch for AddAnyChannels, sized once: the columns of pixels px - xmargin .. px + xmargin
    // that a sample reaches, with its offset from and weight for each, and its filtered channels'
    // values as doubles.
    struct Column {
        int offset;  // of the column from footprint_.min.x
        float dx, weight;
    };
    std::vector<Column> columns_;
    std::vector<double> values_;
    std::vector<Float4> weights_;  // LookUpReachWeights', per sample
};

}  // namespace gonio
