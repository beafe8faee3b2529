#include "renderer/image/film.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

namespace gonio {
namespace {

PixelFilter MakeFilter(const std::string& name, float xwidth, float ywidth) {
    std::string error;
    auto filter = PixelFilter::FromRib(name, xwidth, ywidth, error);
    EXPECT_TRUE(filter.has_value()) << error;
    return filter.value_or(PixelFilter());
}

FilmSpec SmallSpec(int xres, int yres, int xsamples, int ysamples, int channels) {
    return FilmSpec::FromCropWindow(xres, yres, 0, 1, 0, 1, xsamples, ysamples, channels);
}

struct TestSample {
    int px, py;
    float x, y;
    std::vector<float> values;
};

// Splats each sample into the tile of its pixel, tiles in parallel (in whatever order threads
// take them), as the renderer does: a run of samples of one pixel together.
void Splat(Film& film, const std::vector<TestSample>& samples) {
    tbb::parallel_for(0, film.TileCount(), [&](int tile) {
        FilmTile filmTile = film.StartTile(tile);
        std::vector<float> positions, values;
        for (size_t first = 0, next; first < samples.size(); first = next) {
            positions.clear(), values.clear();
            for (next = first; next < samples.size() && samples[next].px == samples[first].px &&
                               samples[next].py == samples[first].py;
                 ++next) {
                positions.insert(positions.end(), {samples[next].x, samples[next].y});
                values.insert(values.end(), samples[next].values.begin(),
                              samples[next].values.end());
            }
            filmTile.AddPixelSamples(samples[first].px, samples[first].py, int(next - first),
                                     positions.data(), values.data());
        }
        film.StoreTile(std::move(filmTile));
    });
}

using SampleValues = std::function<void(int px, int py, int s, float* values)>;

// Stratified (cell-centred, jittered by a fixed pattern) samples over the whole pixel range.
std::vector<TestSample> FieldSamples(const Film& film, const SampleValues& valuesOf) {
    const FilmSpec& spec = film.Spec();
    Imath::Box2i range = film.PixelRange();
    std::vector<TestSample> samples;
    for (int py = range.min.y; py <= range.max.y; ++py) {
        for (int px = range.min.x; px <= range.max.x; ++px) {
            for (int sy = 0; sy < spec.ysamples; ++sy) {
                for (int sx = 0; sx < spec.xsamples; ++sx) {
                    int s = sy * spec.xsamples + sx;
                    float jx = 0.25f + 0.5f * ((px * 7 + py * 3 + s) % 5) / 5.0f;
                    float jy = 0.25f + 0.5f * ((px * 2 + py * 5 + s) % 7) / 7.0f;
                    TestSample sample{px, py, px + (sx + jx) / spec.xsamples,
                                      py + (sy + jy) / spec.ysamples,
                                      std::vector<float>(size_t(spec.channels))};
                    valuesOf(px, py, s, sample.values.data());
                    samples.push_back(std::move(sample));
                }
            }
        }
    }
    return samples;
}

void FillFilm(Film& film, const SampleValues& valuesOf) {
    Splat(film, FieldSamples(film, valuesOf));
}

class ConstantField : public ::testing::TestWithParam<const char*> {};

TEST_P(ConstantField, ResolvesToTheConstantEverywhere) {
    const float constant[5] = {0.25f, 0.5f, 2.0f, 1.0f, 7.0f};
    for (auto crop : {std::array<float, 4>{0, 1, 0, 1}, std::array<float, 4>{0.3f, 0.7f, 0, 0.2f},
                      std::array<float, 4>{0.9f, 1, 0.8f, 1}}) {
        FilmSpec spec =
            FilmSpec::FromCropWindow(20, 15, crop[0], crop[1], crop[2], crop[3], 3, 2, 5);
        Film film(spec, MakeFilter(GetParam(), 3, 2.5f));
        FillFilm(film, [&](int, int, int, float* v) { std::copy(constant, constant + 5, v); });
        Image image = film.Resolve();
        ASSERT_EQ(image.width, spec.WindowWidth());
        ASSERT_EQ(image.height, spec.WindowHeight());
        EXPECT_EQ(image.xorigin, spec.xmin);
        EXPECT_EQ(image.yorigin, spec.ymin);
        EXPECT_EQ(image.fullWidth, 20);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 5; ++c)
                    ASSERT_NEAR(image.At(x, y)[c], constant[c], 1e-5)
                        << GetParam() << " pixel " << x << "," << y << " channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Film, ConstantField,
                         ::testing::Values("box", "triangle", "gaussian", "catmull-rom", "sinc",
                                           "disk", "mitchell"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& ch : name)
                                 if (ch == '-') ch = '_';
                             return name;
                         });

// Every window pixel is the plain weighted mean of the samples within the filter's reach, each
// weighted by the film's tabulated axes (or the disk's own weight): a reference that weighs every
// sample against every pixel, so that the splat's shortcuts (the columns it skips, the rows it
// stops at, the batch sums of narrow filters) can neither drop a sample nor count one twice.
void ExpectPlainWeightedMeans(const char* name, float xwidth, float ywidth) {
    const PixelFilter filter = MakeFilter(name, xwidth, ywidth);
    const FilmSpec spec = SmallSpec(11, 7, 3, 2, 5);
    Film film(spec, filter);
    const std::vector<TestSample> samples = FieldSamples(film, [](int px, int py, int s, float* v) {
        for (int c = 0; c < 5; ++c) v[c] = float((px * 13 + py * 7 + s * 3 + c * 5) % 17) / 8;
    });
    Splat(film, samples);
    const Image image = film.Resolve();
    const FilterTable xTable(filter.XRadius(), [&](float d) { return filter.XWeight(d); });
    const FilterTable yTable(filter.YRadius(), [&](float d) { return filter.YWeight(d); });
    const float xr = filter.XRadius(), yr = filter.YRadius();
    for (int py = spec.ymin; py <= spec.ymax; ++py)
        for (int px = spec.xmin; px <= spec.xmax; ++px) {
            double sum[5] = {}, weights = 0, absWeights = 0;
            for (const TestSample& s : samples) {
                const float dx = s.x - (px + 0.5f), dy = s.y - (py + 0.5f);
                if (dx < -xr || dx >= xr || dy < -yr || dy >= yr) continue;
                const float w =
                    filter.Separable() ? xTable(dx) * yTable(dy) : filter.Evaluate(dx, dy);
                weights += w, absWeights += std::fabs(w);
                for (int c = 0; c < 5; ++c) sum[c] += double(w) * s.values[size_t(c)];
            }
            if (std::fabs(weights) < 1e-3 * absWeights) continue;  // the nearest-sample fallback
            for (int c = 0; c < 4; ++c)  // channel 4 is depth, filtered by "min"
                ASSERT_NEAR(image.At(px, py)[c], sum[c] / weights, 1e-5)
                    << name << " " << xwidth << " pixel " << px << "," << py << " channel " << c;
        }
}

// Narrow (FilterReachTable: radius ≤ 1.5) and wide (the per-sample path) footprints.
TEST_P(ConstantField, PixelsAreThePlainWeightedMeanOfTheirSamples) {
    ExpectPlainWeightedMeans(GetParam(), 3, 2.5f);
    ExpectPlainWeightedMeans(GetParam(), 5, 4);
}

// One sample per pixel at its centre: a single bright sample reaches each pixel with the filter's
// weight at their offset, divided by the (here equal for every pixel) sum of weights.
TEST(Film, SingleSampleSpreadsAsTheFilterSays) {
    PixelFilter filter = MakeFilter("gaussian", 3, 3);
    FilmSpec spec = SmallSpec(9, 9, 1, 1, 4);
    Film film(spec, filter);
    Imath::Box2i range = film.PixelRange();
    std::vector<TestSample> samples;
    for (int py = range.min.y; py <= range.max.y; ++py) {
        for (int px = range.min.x; px <= range.max.x; ++px) {
            std::vector<float> v = {0, 0, 0, 0};
            if (px == 4 && py == 4) v[0] = 1.0f;
            samples.push_back({px, py, px + 0.5f, py + 0.5f, v});
        }
    }
    Splat(film, samples);
    double weightSum = 0.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) weightSum += filter.Evaluate(float(i), float(j));
    Image image = film.Resolve();
    double total = 0.0;
    for (int y = 0; y < 9; ++y) {
        for (int x = 0; x < 9; ++x) {
            float expected = filter.Evaluate(float(x - 4), float(y - 4)) / float(weightSum);
            if (std::abs(x - 4) > 1 || std::abs(y - 4) > 1) expected = 0.0f;
            EXPECT_NEAR(image.At(x, y)[0], expected, 1e-6) << x << "," << y;
            total += image.At(x, y)[0];
        }
    }
    EXPECT_NEAR(total, 1.0, 1e-5);  // the sample's energy is kept
    EXPECT_GT(image.At(4, 3)[0], image.At(3, 3)[0]);
}

// A pixel's samples go to the film together, but each reaches only the pixels within its own
// filter radius: an infinite sample leaves a neighbour that only its batch-mates reach finite.
TEST(Film, ASampleOutOfReachAddsNothingToItsBatchMatesPixels) {
    const PixelFilter filter = MakeFilter("gaussian", 2, 2);  // radius 1
    const FilmSpec spec = SmallSpec(3, 1, 2, 1, 4);
    Film film(spec, filter);
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<TestSample> samples;
    for (int px = -1; px <= 3; ++px)
        for (int s = 0; s < 2; ++s)
            samples.push_back({px,
                               0,
                               px + (s == 0 ? 0.1f : 0.9f),
                               0.5f,
                               {px == 1 && s == 0 ? inf : 1.0f, 1, 1, 1}});
    Splat(film, samples);
    const Image image = film.Resolve();
    // Pixel 1's first sample (at 1.1) lies 1.4 from pixel 2's centre, beyond the radius.
    EXPECT_EQ(image.At(1, 0)[0], inf);
    EXPECT_FLOAT_EQ(image.At(2, 0)[0], 1.0f);
    EXPECT_EQ(image.At(0, 0)[0], inf);  // 0.6 from pixel 0's centre: within reach
}

// The film's size grows with the window and the filter's margin, so that a render can refuse
// a film it cannot hold before allocating it.
TEST(Film, BytesNeededCountsTheMarginAndTheChannels) {
    const PixelFilter box = MakeFilter("box", 1, 1), wide = MakeFilter("box", 9, 9);
    const double small = Film::BytesNeeded(SmallSpec(10, 10, 1, 1, 4), box);
    EXPECT_DOUBLE_EQ(Film::BytesNeeded(SmallSpec(20, 10, 1, 1, 4), box), 2 * small);
    EXPECT_GT(Film::BytesNeeded(SmallSpec(10, 10, 1, 1, 8), box), 1.5 * small);
    const Film film(SmallSpec(10, 10, 1, 1, 4), wide);
    const Imath::Box2i range = film.PixelRange();
    const double pixels = double(range.max.x - range.min.x + 1) * (range.max.y - range.min.y + 1);
    EXPECT_DOUBLE_EQ(Film::BytesNeeded(SmallSpec(10, 10, 1, 1, 4), wide), small * pixels / 100);
    EXPECT_GT(Film::BytesNeeded(SmallSpec(1000000, 1000000, 1, 1, 5), box), 1e13);
}

TEST(Film, CancelledWeightsFallBackToTheNearestSample) {
    PixelFilter filter = MakeFilter("catmull-rom", 4, 4);
    // Find the offset whose weight cancels the negative lobe at 1.5 pixels.
    float lo = 0.5f, hi = 1.0f;
    for (int i = 0; i < 60; ++i) {
        float mid = 0.5f * (lo + hi);
        (filter.Evaluate(mid, 0) > -filter.Evaluate(1.5f, 0) ? lo : hi) = mid;
    }
    FilmSpec spec = SmallSpec(8, 1, 1, 1, 4);
    Film film(spec, filter);
    const float cx = 3.5f;  // centre of pixel 3
    const float xNear = cx + lo, xFar = cx - 1.5f;
    Splat(film, {{int(std::floor(xNear)), 0, xNear, 0.5f, {10, 10, 10, 1}},
                 {int(std::floor(xFar)), 0, xFar, 0.5f, {20, 20, 20, 1}}});
    Image image = film.Resolve();
    EXPECT_FLOAT_EQ(image.At(3, 0)[0], 10.0f);
    // A pixel that no set sample reaches is black.
    EXPECT_FLOAT_EQ(image.At(7, 0)[0], 0.0f);
}

TEST(Film, KeepsNearestSamplesOnlyWhereWeightsCanCancel) {
    auto canCancel = [](const char* name, float width) {
        std::string error;
        return Film::WeightsCanCancel(*PixelFilter::FromRib(name, width, width, error));
    };
    EXPECT_FALSE(canCancel("gaussian", 2));
    EXPECT_FALSE(canCancel("box", 1.5f));
    EXPECT_FALSE(canCancel("triangle", 1.5f));
    EXPECT_FALSE(canCancel("disk", 1.5f));  // a pixel's corners lie 0.71 from its centre
    EXPECT_TRUE(canCancel("catmull-rom", 4));
    EXPECT_TRUE(canCancel("sinc", 4));
    EXPECT_TRUE(canCancel("mitchell", 4));
    EXPECT_TRUE(canCancel("triangle", 1));  // a sample on the pixel's left edge weighs 0
    EXPECT_TRUE(canCancel("disk", 1.2f));
    EXPECT_TRUE(canCancel("gaussian", 0.5f));
}

TEST(Film, DepthIsTheNearestOfThePixelsOwnSamples) {
    const float inf = std::numeric_limits<float>::infinity();
    FilmSpec spec = SmallSpec(3, 1, 2, 2, 5);
    Film film(spec, MakeFilter("gaussian", 2, 2));
    FillFilm(film, [&](int px, int, int s, float* v) {
        v[0] = v[1] = v[2] = v[3] = 1.0f;
        if (px == 0) v[4] = s == 2 ? 3.0f : (s == 1 ? 5.0f : inf);
        if (px == 1) v[4] = inf;  // nothing hit
        if (px == 2) v[4] = 1.0f + s;
    });
    Image image = film.Resolve();
    EXPECT_FLOAT_EQ(image.At(0, 0)[kChannelZ], 3.0f);
    EXPECT_EQ(image.At(1, 0)[kChannelZ], inf);
    EXPECT_FLOAT_EQ(image.At(2, 0)[kChannelZ], 1.0f);
    EXPECT_FLOAT_EQ(image.At(1, 0)[kChannelR], 1.0f);
}

// Tiles are splatted by whichever thread takes them, in any order, and small tiles (5 pixels
// here, against a 2-pixel filter radius) make most pixels sum several tiles: the image must not
// change by a bit.
TEST(Film, ImageIsIdenticalWhateverTheThreadCount) {
    FilmSpec spec = FilmSpec::FromCropWindow(96, 64, 0.1f, 0.9f, 0, 1, 3, 3, 6);
    auto render = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        Film film(spec, MakeFilter("catmull-rom", 4, 4), 5);
        FillFilm(film, [](int px, int py, int s, float* v) {
            for (int c = 0; c < 6; ++c)
                v[c] = std::sin(0.37f * px + 0.91f * py + 1.3f * s + c) * 100.0f + 1.0f / (1 + c);
        });
        return film.Resolve();
    };
    const Image one = render(1), many = render(8);
    ASSERT_EQ(one.pixels.size(), many.pixels.size());
    EXPECT_EQ(std::memcmp(one.pixels.data(), many.pixels.data(), one.pixels.size() * sizeof(float)),
              0);
}

// The tile size only changes the order of the sums.
TEST(Film, TileSizeDoesNotChangeTheImage) {
    FilmSpec spec = FilmSpec::FromCropWindow(40, 30, 0, 1, 0.2f, 1, 2, 2, 5);
    auto render = [&](int tileSize) {
        Film film(spec, MakeFilter("gaussian", 3, 3), tileSize);
        FillFilm(film, [](int px, int py, int s, float* v) {
            for (int c = 0; c < 5; ++c) v[c] = std::cos(0.21f * px - 0.5f * py + s + c);
        });
        return film.Resolve();
    };
    const Image small = render(3), whole = render(1000);
    ASSERT_EQ(small.pixels.size(), whole.pixels.size());
    for (size_t i = 0; i < small.pixels.size(); ++i)
        ASSERT_NEAR(small.pixels[i], whole.pixels[i], 1e-5f) << i;
}

TEST(Film, TilesCoverThePixelRangeOnce) {
    FilmSpec spec = SmallSpec(37, 21, 1, 1, 4);
    Film film(spec, MakeFilter("gaussian", 2, 2), 8);
    const Imath::Box2i range = film.PixelRange();
    std::vector<int> covered(size_t(range.size().x + 1) * (range.size().y + 1), 0);
    for (int tile = 0; tile < film.TileCount(); ++tile) {
        const Imath::Box2i pixels = film.TilePixels(tile);
        ASSERT_TRUE(range.intersects(pixels.min) && range.intersects(pixels.max)) << tile;
        for (int y = pixels.min.y; y <= pixels.max.y; ++y)
            for (int x = pixels.min.x; x <= pixels.max.x; ++x)
                ++covered[size_t(y - range.min.y) * (range.size().x + 1) + (x - range.min.x)];
    }
    for (int count : covered) ASSERT_EQ(count, 1);
}

TEST(Film, SamplesOfPixelsOutsideTheTileAreDropped) {
    FilmSpec spec = SmallSpec(4, 4, 1, 1, 4);
    Film film(spec, MakeFilter("box", 1, 1), 2);
    FilmTile tile = film.StartTile(0);  // pixels (0..1, 0..1)
    const float v[4] = {1, 1, 1, 1};
    tile.AddSample(3, 3, 3.5f, 3.5f, v);
    tile.AddSample(-5, 0, -4.5f, 0.5f, v);
    film.StoreTile(std::move(tile));
    const Image image = film.Resolve();
    EXPECT_FLOAT_EQ(image.At(3, 3)[0], 0.0f);
    EXPECT_FLOAT_EQ(image.At(0, 0)[0], 0.0f);
}

}  // namespace
}  // namespace gonio
