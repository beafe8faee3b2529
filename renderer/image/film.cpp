#include "renderer/image/film.h"

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

// One sample's share of one pixel (FilmTile::sums_) on the per-sample path: sum[0] += w,
// sum[1] += |w| and sum[2 + c] += w·values[c].
void AddWeighted(float w, const double* __restrict values, int channels, double* __restrict sum) {
    sum[0] += w;
    sum[1] += std::fabs(w);
    for (int c = 0; c < channels; ++c) sum[2 + c] += double(w) * values[c];
}

// The filtered channels without AOVs: r g b a.
constexpr int kColourAndAlpha = 4;

}  // namespace

void ComposeCropWindow(const float window[4], const float part[4], float out[4]) {
    for (int i = 0; i < 4; ++i) {
        const float lo = window[i & 2], hi = window[(i & 2) + 1];
        // The whole window's own edges stay exact (no rounding of lo + 1 * (hi - lo)).
        out[i] = part[i] == 0 ? lo : part[i] == 1 ? hi : lo + part[i] * (hi - lo);
    }
}

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

Film::Film(const FilmSpec& spec, const PixelFilter& filter, int tileSize)
    : spec_(spec),
      filter_(filter),
      xWeight_(filter.XRadius(), [&](float d) { return filter.XWeight(d); }),
      yWeight_(filter.YRadius(), [&](float d) { return filter.YWeight(d); }),
      narrow_(filter.Separable() && FilterReachTable::Covers(filter.XRadius()) &&
              FilterReachTable::Covers(filter.YRadius())),
      tileSize_(std::max(1, tileSize)),
      xmargin_(FilterMargin(filter.XRadius())),
      ymargin_(FilterMargin(filter.YRadius())),
      xReach_(narrow_ ? FilterReachTable(filter.XRadius(), xmargin_,
                                         [&](float d) { return filter.XWeight(d); })
                      : FilterReachTable()),
      yReach_(narrow_ ? FilterReachTable(filter.YRadius(), ymargin_,
                                         [&](float d) { return filter.YWeight(d); })
                      : FilterReachTable()),
      keepNearest_(WeightsCanCancel(filter)),
      range_(Imath::V2i(spec.xmin - xmargin_, spec.ymin - ymargin_),
             Imath::V2i(spec.xmax + xmargin_, spec.ymax + ymargin_)),
      tilesX_((range_.max.x - range_.min.x + tileSize_) / tileSize_),
      tilesY_((range_.max.y - range_.min.y + tileSize_) / tileSize_),
      reachX_((xmargin_ + tileSize_ - 1) / tileSize_),
      reachY_((ymargin_ + tileSize_ - 1) / tileSize_),
      tiles_(size_t(tilesX_) * tilesY_),
      stored_(tiles_.size(), 0),
      resolved_(tiles_.size(), 0) {
    image_.width = spec_.WindowWidth();
    image_.height = spec_.WindowHeight();
    image_.channels = spec_.channels;
    image_.xorigin = spec_.xmin;
    image_.yorigin = spec_.ymin;
    image_.fullWidth = spec_.xres;
    image_.fullHeight = spec_.yres;
    image_.pixels.resize(size_t(image_.width) * image_.height * image_.channels);
}

double Film::BytesNeeded(const FilmSpec& spec, const PixelFilter& filter) {
    const double width = spec.WindowWidth() + 2.0 * FilterMargin(filter.XRadius());
    const double height = spec.WindowHeight() + 2.0 * FilterMargin(filter.YRadius());
    // A tile's sums (double per filtered channel, two weights), nearest samples and depth
    // (float), and the resolved image (float per channel).
    const double perPixel =
        8.0 * spec.FilteredChannels() + 16 + 4.0 * spec.channels + 4 + 4.0 * spec.channels;
    return width * height * perPixel;
}

Imath::Box2i Film::PixelRange() const { return range_; }

Imath::Box2i Film::TilePixels(int tile) const {
    const Imath::V2i min(range_.min.x + (tile % tilesX_) * tileSize_,
                         range_.min.y + (tile / tilesX_) * tileSize_);
    const Imath::V2i max(std::min(min.x + tileSize_ - 1, range_.max.x),
                         std::min(min.y + tileSize_ - 1, range_.max.y));
    return Imath::Box2i(min, max);
}

Imath::Box2i Film::Footprint(const Imath::Box2i& pixels) const {
    return Imath::Box2i(Imath::V2i(std::max(pixels.min.x - xmargin_, spec_.xmin),
                                   std::max(pixels.min.y - ymargin_, spec_.ymin)),
                        Imath::V2i(std::min(pixels.max.x + xmargin_, spec_.xmax),
                                   std::min(pixels.max.y + ymargin_, spec_.ymax)));
}

bool Film::WeightsCanCancel(const PixelFilter& filter) {
    if (!filter.NeverNegative()) return true;
    // A pixel's own samples lie at offsets in [-0.5, 0.5) on both axes. When all of them lie
    // strictly inside the footprint, each weighs more than 0, and so does their sum.
    const float x = 0.5f / filter.XRadius(), y = 0.5f / filter.YRadius();
    const bool ownSamplesInside = filter.Separable() ? x < 1 && y < 1 : x * x + y * y < 1;
    return !ownSamplesInside;
}

FilmTile Film::StartTile(int tile) const { return FilmTile(*this, tile); }

void Film::StoreTile(FilmTile&& tile) {
    if (tile.film_ != this || tile.index_ < 0 || tile.index_ >= TileCount()) return;
    const int index = tile.index_;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stored_[size_t(index)]) return;
    tiles_[size_t(index)] = std::move(tile);
    stored_[size_t(index)] = 1;
    ResolveReadyTiles(index);
}

Imath::Box2i Film::TilesInReach(int tile) const {
    const int tx = tile % tilesX_, ty = tile / tilesX_;
    return Imath::Box2i(
        Imath::V2i(std::max(0, tx - reachX_), std::max(0, ty - reachY_)),
        Imath::V2i(std::min(tilesX_ - 1, tx + reachX_), std::min(tilesY_ - 1, ty + reachY_)));
}

bool Film::AllInReach(int tile, const std::vector<uint8_t>& flags) const {
    const Imath::Box2i reach = TilesInReach(tile);
    for (int ty = reach.min.y; ty <= reach.max.y; ++ty)
        for (int tx = reach.min.x; tx <= reach.max.x; ++tx)
            if (!flags[size_t(ty) * tilesX_ + tx]) return false;
    return true;
}

void Film::ResolveReadyTiles(int stored) {
    const Imath::Box2i reach = TilesInReach(stored);
    std::vector<int> resolvedNow;
    for (int ty = reach.min.y; ty <= reach.max.y; ++ty)
        for (int tx = reach.min.x; tx <= reach.max.x; ++tx) {
            const int t = ty * tilesX_ + tx;
            if (resolved_[size_t(t)] || !AllInReach(t, stored_)) continue;
            ResolveTile(t);
            resolvedNow.push_back(t);
        }
    // A stored tile whose every neighbour is resolved is read by no pixel any more.
    for (int t : resolvedNow) {
        const Imath::Box2i around = TilesInReach(t);
        for (int ty = around.min.y; ty <= around.max.y; ++ty)
            for (int tx = around.min.x; tx <= around.max.x; ++tx) {
                const int n = ty * tilesX_ + tx;
                if (tiles_[size_t(n)].film_ && AllInReach(n, resolved_))
                    tiles_[size_t(n)] = FilmTile();
            }
    }
}

void Film::ResolveTile(int tile) {
    const Imath::Box2i pixels = TilePixels(tile);
    const int xmin = std::max(pixels.min.x, spec_.xmin), xmax = std::min(pixels.max.x, spec_.xmax);
    const int ymin = std::max(pixels.min.y, spec_.ymin), ymax = std::min(pixels.max.y, spec_.ymax);
    std::vector<double> sums(size_t(spec_.channels));
    for (int y = ymin; y <= ymax; ++y)
        for (int x = xmin; x <= xmax; ++x)
            ResolvePixel(x, y, sums, image_.At(x - spec_.xmin, y - spec_.ymin));
    resolved_[size_t(tile)] = 1;
}

FilmTile::FilmTile(const Film& film, int index)
    : film_(&film),
      index_(index),
      pixels_(film.TilePixels(index)),
      footprint_(film.Footprint(pixels_)),
      channels_(film.Spec().channels),
      filtered_(film.Spec().FilteredChannels()),
      depthChannel_(film.Spec().DepthChannelOrNone()),
      separableColourAndAlpha_(film.narrow_ && !film.keepNearest_ && filtered_ == kColourAndAlpha &&
                               (depthChannel_ < 0 || depthChannel_ >= kColourAndAlpha)),
      columns_(size_t(2 * film.xmargin_ + 1)),
      values_(size_t(filtered_)) {
    // A tile wholly in the margin beyond a corner may reach no window pixel.
    const size_t pixels = footprint_.isEmpty()
                              ? 0
                              : size_t(footprint_.max.x - footprint_.min.x + 1) *
                                    size_t(footprint_.max.y - footprint_.min.y + 1);
    sums_.assign(pixels * Stride(), 0.0);
    if (film.keepNearest_) {
        nearest_.assign(pixels * (1 + channels_), 0.0f);
        for (size_t i = 0; i < pixels; ++i)
            nearest_[i * (1 + channels_)] = std::numeric_limits<float>::infinity();
    }
    depth_.assign(pixels, std::numeric_limits<float>::infinity());
}

void FilmTile::AddSample(int px, int py, float x, float y, const float* values) {
    const float position[2] = {x, y};
    AddPixelSamples(px, py, 1, position, values);
}

void FilmTile::AddPixelSamples(int px, int py, int count, const float* positions,
                               const float* values) {
    if (!film_ || count <= 0 || !pixels_.intersects(Imath::V2i(px, py))) return;
    if (depthChannel_ >= 0 && footprint_.intersects(Imath::V2i(px, py))) {
        float& depth = depth_[PixelIndex(px, py)];
        for (int i = 0; i < count; ++i)
            depth = std::min(depth, values[size_t(i) * channels_ + depthChannel_]);
    }
    const Imath::Box2i reach(Imath::V2i(std::max(footprint_.min.x, px - film_->xmargin_),
                                        std::max(footprint_.min.y, py - film_->ymargin_)),
                             Imath::V2i(std::min(footprint_.max.x, px + film_->xmargin_),
                                        std::min(footprint_.max.y, py + film_->ymargin_)));
    if (reach.isEmpty()) return;
    if (separableColourAndAlpha_ && LookUpReachWeights(px, py, count, positions, values)) {
        if (film_->xmargin_ == 0)
            AddReachRows<1>(px, py, reach, count, values);
        else
            AddReachRows<3>(px, py, reach, count, values);
        return;
    }
    for (int i = 0; i < count; ++i)
        AddAnyChannels(reach, positions[2 * i], positions[2 * i + 1],
                       values + size_t(i) * channels_);
}

// The sample counts for pixel q when -radius <= x - (q + 0.5) < radius.
template <bool kKeepZeroWeights>
inline int FilmTile::FindColumns(const Imath::Box2i& reach, float x) {
    const float xr = film_->filter_.XRadius();
    int columns = 0;
    for (int qx = reach.min.x; qx <= reach.max.x; ++qx) {
        const float dx = x - (qx + 0.5f);
        if (dx < -xr || dx >= xr) continue;
        const float weight = film_->xWeight_(dx);
        if (kKeepZeroWeights || weight != 0.0f)
            columns_[size_t(columns++)] = {qx - footprint_.min.x, dx, weight};
    }
    return columns;
}

// For the batch the usual splat takes, looks up each sample's weights for the pixels it
// reaches into weights_, one FilterReachTable lookup per axis: each sample within its own
// pixel, which the table assumes, and its colour and alpha finite, as a sample of weight 0 adds
// 0·value to every sum (an infinite or NaN value must not turn a pixel out of the sample's
// reach into NaN; the per-sample path skips such pixels). False for any other batch.
bool FilmTile::LookUpReachWeights(int px, int py, int count, const float* positions,
                                  const float* values) {
    const Film& film = *film_;
    weights_.resize(2 * size_t(count));  // per sample, its columns' weights, then its rows'
    Int4 finite = ~Int4{};
    for (int i = 0; i < count; ++i) {
        const float fx = positions[2 * i] - float(px), fy = positions[2 * i + 1] - float(py);
        if (!(fx >= 0 && fx <= 1 && fy >= 0 && fy <= 1)) return false;
        weights_[2 * size_t(i)] = film.xReach_(fx);
        weights_[2 * size_t(i) + 1] = film.yReach_(fy);
        const Float4 rgba = Load4(values + size_t(i) * channels_);  // r g b a lead
        finite &= rgba - rgba == Float4{};                          // NaN for inf and NaN
    }
    return finite[0] & finite[1] & finite[2] & finite[3];
}

// A pixel's samples all reach the same pixels, and a reach pixel sums the whole batch in float
// before the sums are added, once, to its double sums_. A separable filter's weight is the
// product of the column's and the row's (weights_). A row of the reach at a time: per column,
// its r g b a sums side by side, and the sums of the columns' weights and |weights| across.
template <int kColumns>
void FilmTile::AddReachRows(int px, int py, const Imath::Box2i& reach, int count,
                            const float* values) {
    const Film& film = *film_;
    constexpr size_t kStride = 2 + kColourAndAlpha;
    const size_t width = size_t(footprint_.max.x - footprint_.min.x + 1);
    for (int qy = reach.min.y; qy <= reach.max.y; ++qy) {
        const int j = qy - (py - film.ymargin_);
        Float4 weight = {}, absWeight = {}, colour[kColumns] = {};
        for (int i = 0; i < count; ++i) {
            const Float4 w = weights_[2 * size_t(i)] * weights_[2 * size_t(i) + 1][j];
            weight += w;
            absWeight += Abs4(w);
            const Float4 rgba = Load4(values + size_t(i) * channels_);
            for (int k = 0; k < kColumns; ++k) colour[k] += w[k] * rgba;
        }
        double* sums = sums_.data() + (size_t(qy - footprint_.min.y) * width +
                                       size_t(reach.min.x - footprint_.min.x)) *
                                          kStride;
        for (int qx = reach.min.x; qx <= reach.max.x; ++qx, sums += kStride) {
            const int k = qx - (px - film.xmargin_);
            sums[0] += weight[k];
            sums[1] += absWeight[k];
            for (int c = 0; c < kColourAndAlpha; ++c) sums[2 + c] += colour[k][c];
        }
    }
}

// The general case, a sample at a time: the columns in reach and their weights are found once
// per sample, columns of weight 0 are skipped where they add nothing, and the values are made
// doubles once. The sums are the same, added in the same order, as weighting every pixel of
// the margin in turn.
void FilmTile::AddAnyChannels(const Imath::Box2i& reach, float x, float y, const float* values) {
    const PixelFilter& filter = film_->Filter();
    const float yr = filter.YRadius();
    const bool separable = filter.Separable(), keepNearest = !nearest_.empty();
    // A column of weight 0 adds nothing to a separable filter's sums, but its pixels may still
    // take the sample as their nearest, and a non-separable filter weighs it in two dimensions.
    const int columns =
        !separable || keepNearest ? FindColumns<true>(reach, x) : FindColumns<false>(reach, x);
    // All the values but depth.
    const int beforeDepth = depthChannel_ >= 0 ? depthChannel_ : channels_;
    std::copy(values, values + beforeDepth, values_.begin());
    if (beforeDepth < channels_)
        std::copy(values + beforeDepth + 1, values + channels_, values_.begin() + beforeDepth);
    const size_t stride = Stride(), width = size_t(footprint_.max.x - footprint_.min.x + 1);
    for (int qy = reach.min.y; qy <= reach.max.y; ++qy) {
        const float dy = y - (qy + 0.5f);
        if (dy < -yr || dy >= yr) continue;
        const float yWeight = film_->yWeight_(dy);
        const size_t row = size_t(qy - footprint_.min.y) * width;
        for (int k = 0; k < columns; ++k) {
            const size_t pixel = row + size_t(columns_[size_t(k)].offset);
            const float dx = columns_[size_t(k)].dx;
            if (keepNearest) KeepNearest(pixel, dx * dx + dy * dy, values);
            const float w =
                separable ? columns_[size_t(k)].weight * yWeight : filter.Evaluate(dx, dy);
            if (w != 0.0f) AddWeighted(w, values_.data(), filtered_, &sums_[pixel * stride]);
        }
    }
}

void FilmTile::KeepNearest(size_t pixel, float distance, const float* values) {
    float* nearest = &nearest_[pixel * (1 + channels_)];
    if (distance < nearest[0]) {
        nearest[0] = distance;
        std::copy(values, values + channels_, nearest + 1);
    }
}

void Film::ResolvePixel(int px, int py, std::vector<double>& sum, float* out) const {
    const int channels = spec_.channels;
    std::fill(sum.begin(), sum.end(), 0.0);
    double weightSum = 0.0, absWeightSum = 0.0;
    const float* nearest = nullptr;
    float nearestDistance = std::numeric_limits<float>::infinity();
    float depth = std::numeric_limits<float>::infinity();
    // The tiles whose samples reach (px, py), in tile order, so the floating-point sums never
    // depend on threads.
    const int txmin = std::max(0, (px - xmargin_ - range_.min.x) / tileSize_);
    const int txmax = std::min(tilesX_ - 1, (px + xmargin_ - range_.min.x) / tileSize_);
    const int tymin = std::max(0, (py - ymargin_ - range_.min.y) / tileSize_);
    const int tymax = std::min(tilesY_ - 1, (py + ymargin_ - range_.min.y) / tileSize_);
    for (int ty = tymin; ty <= tymax; ++ty) {
        for (int tx = txmin; tx <= txmax; ++tx) {
            const FilmTile& tile = tiles_[size_t(ty) * tilesX_ + tx];
            if (!tile.film_ || !tile.footprint_.intersects(Imath::V2i(px, py))) continue;
            const size_t pixel = tile.PixelIndex(px, py);
            const float* tileNearest =
                tile.nearest_.empty() ? nullptr : &tile.nearest_[pixel * (1 + channels)];
            if (tileNearest && tileNearest[0] < nearestDistance) {
                nearestDistance = tileNearest[0];
                nearest = tileNearest + 1;
            }
            depth = std::min(depth, tile.depth_[pixel]);
            const double* sums = &tile.sums_[pixel * tile.Stride()];
            weightSum += sums[0];
            absWeightSum += sums[1];
            for (int k = 0; k < tile.filtered_; ++k) sum[k] += sums[2 + k];
        }
    }
    const bool cancelled =
        absWeightSum == 0.0 || std::fabs(weightSum) < kCancelledWeightFraction * absWeightSum;
    const int depthChannel = spec_.DepthChannelOrNone();
    for (int c = 0, k = 0; c < channels; ++c) {
        if (c == depthChannel)
            out[c] = depth;
        else if (!cancelled)
            out[c] = float(sum[size_t(k++)] / weightSum);
        else
            out[c] = nearest ? nearest[c] : 0.0f;
    }
}

Image Film::Resolve() {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (int t = 0; t < TileCount(); ++t)
        if (!resolved_[size_t(t)]) ResolveTile(t);
    return std::move(image_);
}

}  // namespace gonio
