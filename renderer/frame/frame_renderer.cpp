#include "renderer/frame/frame_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "base/progress.h"
#include "base/random.h"
#include "base/system_memory.h"
#include "renderer/frame/per_thread.h"
#include "renderer/frame/shading_points.h"
#include "renderer/image/film.h"
#include "renderer/image/image_writer.h"
#include "renderer/pathtrace/path_integrator.h"
#include "renderer/raytrace/camera.h"
#include "renderer/raytrace/ray_scene.h"
#include "renderer/raytrace/transparent_layers.h"
#include "renderer/shading/imager_shading.h"
#include "renderer/shading/surface_shading.h"

namespace gonio {
namespace {

constexpr int kTileSize = 16;

int OutputFloats(const std::vector<ShaderOutput>& outputs) {
    int total = 0;
    for (const ShaderOutput& output : outputs) total += output.width;
    return total;
}

// One camera sample on its way through the scene: transparent surfaces let it go on, so its
// colour is composited front to back over several layers of hits. Trivially copyable (its
// AOVs live in TileRenderer::sampleOutputs_): a tile's samples are filled in place, every field
// set by SampleGenerator (Reset, then the sample's own), never constructed one by one.
struct SampleState {
    CameraRay ray;
    int px, py;
    float x, y;
    float lensU, lensV;
    float colour[3];
    float transmittance[3];
    // Coverage by visible surfaces; matte objects hide what is behind them but add none.
    float alpha;
    float depth;
    // Seeds the random() streams of the points this sample hits, a hash of the render's seed,
    // the pixel and the sample, mixed on at each layer: the seed is MixBits(randomKey) (see
    // SampleRandom::SeedKey), hashed only for the hits that are shaded.
    uint64_t randomKey;
    uint64_t RandomSeed() const { return MixBits(randomKey); }
    int layers;  // how many times its ray has looked for its next hit

    // What nothing has been composited into yet.
    void Reset() {
        for (int c = 0; c < 3; ++c) colour[c] = 0, transmittance[c] = 1;
        lensU = lensV = 0;
        alpha = 0;
        depth = std::numeric_limits<float>::infinity();
        layers = 0;
    }
};

// The camera samples of a tile's pixels: stratified, one jittered sample in each cell of the
// pixel's xsamples x ysamples grid, with lens position and time, all drawn from a random stream
// seeded by the render's seed, the pixel and the sample, so they never depend on threads.
class SampleGenerator {
  public:
    SampleGenerator(uint64_t seed, int xsamples, int ysamples, const Options& options,
                    const Camera& camera)
        : seed_(seed),
          xsamples_(xsamples),
          ysamples_(ysamples),
          cellWidth_(1.0f / float(xsamples)),
          cellHeight_(1.0f / float(ysamples)),
          shutterOpen_(options.shutterOpen),
          shutterLength_(std::max(0.f, options.shutterClose - options.shutterOpen)),
          camera_(camera) {}

    // Makes *samples those of `pixels`, pixel by pixel (its storage is kept from tile to tile).
    void MakeSamples(const Imath::Box2i& pixels, std::vector<SampleState>* samples) const {
        const size_t perPixel = size_t(xsamples_) * size_t(ysamples_);
        samples->resize(size_t(pixels.max.x - pixels.min.x + 1) *
                        size_t(pixels.max.y - pixels.min.y + 1) * perPixel);
        SampleState* sample = samples->data();
        for (int py = pixels.min.y; py <= pixels.max.y; ++py)
            for (int px = pixels.min.x; px <= pixels.max.x; ++px) {
                const uint64_t pixelHash = SampleRandom::PixelHash(seed_, px, py);
                for (int sy = 0, s = 0; sy < ysamples_; ++sy)
                    for (int sx = 0; sx < xsamples_; ++sx, ++s)
                        FillSample(pixelHash, px, py, sx, sy, s, sample++);
            }
    }

  private:
    // Fills sample s = sy * xsamples + sx of pixel (px, py) in place, every field.
    void FillSample(uint64_t pixelHash, int px, int py, int sx, int sy, int s,
                    SampleState* out) const {
        SampleRandom random(pixelHash, s);
        SampleState& sample = *out;
        sample.Reset();
        sample.px = px, sample.py = py;
        sample.randomKey = random.SeedKey();
        sample.x = px + (sx + random.Next()) * cellWidth_;
        sample.y = py + (sy + random.Next()) * cellHeight_;
        // Values nothing reads are not drawn (but skipped: the stream stays the same).
        if (camera_.HasLens())
            sample.lensU = random.Next(), sample.lensV = random.Next();
        else
            random.Skip(2);
        const float time =
            shutterLength_ > 0 ? shutterOpen_ + random.Next() * shutterLength_ : shutterOpen_;
        sample.ray = camera_.GenerateRay(sample.x, sample.y, sample.lensU, sample.lensV, time);
    }

    uint64_t seed_;
    int xsamples_, ysamples_;
    float cellWidth_, cellHeight_;  // of a sample's stratum, in pixels
    float shutterOpen_, shutterLength_;
    const Camera& camera_;
};

// The samples of one tile, shaded layer by layer in batches that share attributes. One per
// thread: its buffers are reused from tile to tile, as allocating them per tile made the kernel
// fault their pages in again each time.
class TileRenderer {
  public:
    TileRenderer(const RayScene& scene, const Camera& camera, ShadingWorker& shading,
                 const Options& options, const std::vector<ShaderOutput>& outputs,
                 PathWorker* paths)
        : scene_(scene),
          camera_(camera),
          shading_(shading),
          outputs_(outputs),
          outputFloats_(OutputFloats(outputs)),
          ncomps_(options.colorComponents),
          colorToRgb_(options.colorToRgb),
          xsamples_(std::max(1, int(std::lround(options.xsamples)))),
          ysamples_(std::max(1, int(std::lround(options.ysamples)))),
          sharing_(PixelFootprint(camera, options)),
          paths_(paths) {}

    // Renders the samples of `pixels` into `film`.
    void Render(const Imath::Box2i& pixels, const SampleGenerator& generator, FilmTile* film);
    // The camera rays (and their continuations) of all tiles rendered so far; shading and the
    // path tracer count their rays in their workers.
    uint64_t CameraRays() const { return cameraRays_; }

  private:
    void TraceAndShade();
    // Under Option "pathtrace": each sample's colour is the path tracer's radiance.
    void TracePaths();
    void Splat(FilmTile* film);
    // The world width of one pixel near the image centre, at distance 0 and its growth per
    // unit distance along the ray (what ShadingPointSharing compares hit distances with).
    static ShadingPointSharing PixelFootprint(const Camera& camera, const Options& options);
    // Fills shaded_ (which members of the group to shade) and shadedBy_ (per member, whose
    // shading it takes: an index into shaded_), by the group's ShadingRate.
    void ChooseShadedPoints(const Attributes& attributes, const std::vector<int>& members);

    std::vector<SampleState> samples_;
    // Per sample, its AOVs (outputFloats_ each), composited front to back like the colour.
    std::vector<float> sampleOutputs_;
    TransparentLayers layers_;  // a layer's hits, by sample: HitAt(k).ray
    ShadingBatch batch_;
    std::vector<float> Ci_, Oi_, outputValues_, filmPositions_, filmValues_;
    std::vector<float> shadedRgb_, shadedOpacityRgb_;  // per shaded point of a group, 3 each
    std::vector<ShadingPointHit> sharingHits_;
    std::vector<int> shaded_, shadedBy_;
    // Shades one group of a layer's hits and composites them into their samples.
    void ShadeGroup(const TransparentLayers::Group& group);
    // The rays one pixel to the right and one down from a sample's, through the same point of
    // the lens at the same time: the ray differentials of shaders that take derivatives.
    NeighbourRays MakeNeighbourRays(const SampleState& sample, float tnear) const;

    // Colours of ColorSamples components to RGB through nRGB (RISpec §4.1.3); opacity is the
    // mean of its components on every channel, as a sum through nRGB is no opacity.
    void ToRgb(const float* colour, float* rgb) const;
    void OpacityToRgb(const float* opacity, float* rgb) const;

    const RayScene& scene_;
    const Camera& camera_;
    ShadingWorker& shading_;
    const std::vector<ShaderOutput>& outputs_;
    int outputFloats_;
    int ncomps_;
    std::vector<float> colorToRgb_;
    int xsamples_, ysamples_;
    ShadingPointSharing sharing_;
    PathWorker* paths_;
    std::vector<float> radiance_;
    // TraceAndShade's first hits of the tile's camera rays.
    std::vector<RayScene::CoherentRay> coherentRays_;
    std::vector<RayHit> firstHits_;
    std::vector<uint8_t> firstFound_;
    uint64_t cameraRays_ = 0;  // all this renderer's tiles'; the path tracer counts its own
};

ShadingPointSharing TileRenderer::PixelFootprint(const Camera& camera, const Options& options) {
    const float x = 0.5f * float(options.xres), y = 0.5f * float(options.yres);
    const float time = options.shutterOpen;
    const CameraRay here = camera.GenerateRay(x, y, 0.5f, 0.5f, time);
    const CameraRay next = camera.GenerateRay(x + 1, y, 0.5f, 0.5f, time);
    return ShadingPointSharing((next.org - here.org).length(),
                               (next.dir.normalized() - here.dir.normalized()).length());
}

void TileRenderer::ChooseShadedPoints(const Attributes& attributes,
                                      const std::vector<int>& members) {
    const int n = int(members.size());
    if (attributes.matte ||
        !ShadingPointSharing::Shares(attributes.shadingRate, xsamples_, ysamples_)) {
        shaded_.resize(size_t(n));
        std::iota(shaded_.begin(), shaded_.end(), 0);
        shadedBy_ = shaded_;
        return;
    }
    // Appended, not resized: groups of alternating sizes would fill the new entries with zeros.
    sharingHits_.clear();
    for (int j = 0; j < n; ++j) {
        const int k = members[j];
        const TransparentLayers::Hit& hit = layers_.HitAt(k);
        const SampleState& sample = samples_[size_t(hit.ray)];
        sharingHits_.push_back({sample.x, sample.y, hit.t, sample.ray.dir, &layers_.PointAt(k)});
    }
    sharing_.Cluster(sharingHits_, attributes.shadingRate, &shaded_, &shadedBy_);
}

void TileRenderer::ToRgb(const float* colour, float* rgb) const {
    if (colorToRgb_.empty()) {
        const int last = ncomps_ - 1;
        rgb[0] = colour[0], rgb[1] = colour[std::min(1, last)], rgb[2] = colour[std::min(2, last)];
        return;
    }
    for (int c = 0; c < 3; ++c) {
        rgb[c] = 0;
        for (int i = 0; i < ncomps_; ++i) rgb[c] += colour[i] * colorToRgb_[3 * i + c];
    }
}

void TileRenderer::OpacityToRgb(const float* opacity, float* rgb) const {
    if (colorToRgb_.empty() && ncomps_ >= 3) {
        for (int c = 0; c < 3; ++c) rgb[c] = opacity[c];
        return;
    }
    float mean = 0;
    for (int i = 0; i < ncomps_; ++i) mean += opacity[i] / ncomps_;
    rgb[0] = rgb[1] = rgb[2] = mean;
}

void TileRenderer::Render(const Imath::Box2i& pixels, const SampleGenerator& generator,
                          FilmTile* film) {
    generator.MakeSamples(pixels, &samples_);
    sampleOutputs_.assign(samples_.size() * size_t(outputFloats_), 0.f);
    if (paths_)
        TracePaths();
    else
        TraceAndShade();
    Splat(film);
}

void TileRenderer::TraceAndShade() {
    // Every sample's first hit together (neighbouring samples' rays share most of their way
    // through the scene), the layers behind it ray by ray.
    const int count = int(samples_.size());
    coherentRays_.resize(size_t(count));
    firstHits_.resize(size_t(count));
    firstFound_.resize(size_t(count));
    for (int i = 0; i < count; ++i) {
        const CameraRay& ray = samples_[size_t(i)].ray;
        coherentRays_[size_t(i)] = {ray.org, ray.dir, ray.tnear, ray.tfar, ray.time};
    }
    scene_.IntersectCoherent(count, coherentRays_.data(), firstHits_.data(), firstFound_.data());
    cameraRays_ += uint64_t(count);
    layers_.Trace(
        count,
        [&](int i, SurfacePoint* sp, TransparentLayers::Hit* hit) {
            SampleState& sample = samples_[size_t(i)];
            CameraRay& ray = sample.ray;
            hit->tnear = ray.tnear;
            // Only the hits ShadeGroup shades need the rest (FinishEvaluate): with ShadingRate
            // sharing, about one in xsamples·ysamples.
            const bool found =
                sample.layers++ == 0
                    ? NextVisibleHitFrom(firstFound_[size_t(i)] ? &firstHits_[size_t(i)] : nullptr,
                                         scene_, ray.org, ray.dir, ray.time, ray.tfar, &ray.tnear,
                                         sp, &hit->t, &cameraRays_, HitEvaluation::kGeometry)
                    : NextVisibleHit(scene_, ray.org, ray.dir, ray.time, ray.tfar, &ray.tnear, sp,
                                     &hit->t, &cameraRays_, HitEvaluation::kGeometry);
            if (!found) return false;
            if (std::isinf(sample.depth)) sample.depth = hit->t;
            return true;
        },
        [&](int, const TransparentLayers::Group& group) { ShadeGroup(group); });
}

void TileRenderer::TracePaths() {
    radiance_.resize(size_t(ncomps_));
    for (SampleState& sample : samples_) {
        float depth = 0;
        if (!paths_->Radiance(sample.ray, sample.RandomSeed(), radiance_.data(), &depth)) continue;
        ToRgb(radiance_.data(), sample.colour);
        sample.alpha = 1;
        sample.depth = depth;
    }
}

void TileRenderer::Splat(FilmTile* film) {
    // The samples come pixel by pixel (SampleGenerator): each pixel's go to the film together,
    // their values in the film's channel order (r g b a z, then the AOVs).
    const size_t channels = kStandardChannelCount + size_t(outputFloats_);
    const size_t perPixel = size_t(xsamples_) * size_t(ysamples_);
    filmPositions_.resize(2 * perPixel);
    filmValues_.resize(channels * perPixel);
    for (size_t first = 0; first < samples_.size();) {
        const SampleState& head = samples_[first];
        size_t count = 0;
        for (; count < perPixel && first + count < samples_.size(); ++count) {
            const SampleState& sample = samples_[first + count];
            if (sample.px != head.px || sample.py != head.py) break;
            float* position = &filmPositions_[2 * count];
            position[0] = sample.x, position[1] = sample.y;
            float* values = &filmValues_[channels * count];
            values[kChannelR] = sample.colour[0];
            values[kChannelG] = sample.colour[1];
            values[kChannelB] = sample.colour[2];
            values[kChannelA] = sample.alpha;
            values[kChannelZ] = sample.depth;
            const float* outputs = &sampleOutputs_[(first + count) * size_t(outputFloats_)];
            std::copy(outputs, outputs + outputFloats_, values + kStandardChannelCount);
        }
        film->AddPixelSamples(head.px, head.py, int(count), filmPositions_.data(),
                              filmValues_.data());
        first += count;
    }
}

NeighbourRays TileRenderer::MakeNeighbourRays(const SampleState& sample, float tnear) const {
    NeighbourRays rays;
    const CameraRay right =
        camera_.GenerateRay(sample.x + 1, sample.y, sample.lensU, sample.lensV, sample.ray.time);
    const CameraRay down =
        camera_.GenerateRay(sample.x, sample.y + 1, sample.lensU, sample.lensV, sample.ray.time);
    rays.org[0] = right.org, rays.dir[0] = right.dir;
    rays.org[1] = down.org, rays.dir[1] = down.dir;
    rays.tnear = tnear;
    rays.time = sample.ray.time;
    return rays;
}

void TileRenderer::ShadeGroup(const TransparentLayers::Group& group) {
    const Attributes* attributes = group.attributes;
    const std::vector<int>& members = group.members;
    ShadingBatch& batch = batch_;
    batch.attributes = attributes;
    batch.points.clear();
    batch.incident.clear();
    batch.depth.clear();
    batch.neighbourRays.clear();
    batch.randomSeeds.clear();
    const bool neighbours = !attributes->matte && shading_.WantsNeighbourRays(attributes);
    ChooseShadedPoints(*attributes, members);
    for (int shadedMember : shaded_) {
        const int k = members[size_t(shadedMember)];
        const TransparentLayers::Hit& hit = layers_.HitAt(k);
        const SampleState& sample = samples_[size_t(hit.ray)];
        scene_.FinishEvaluate(&layers_.PointAt(k));
        batch.points.push_back(&layers_.PointAt(k));
        batch.incident.push_back(sample.ray.dir * hit.t);
        batch.depth.push_back(hit.t);
        if (neighbours) batch.neighbourRays.push_back(MakeNeighbourRays(sample, hit.tnear));
        batch.randomSeeds.push_back(sample.RandomSeed());
    }
    Ci_.assign(shaded_.size() * ncomps_, 0.f);
    Oi_.assign(shaded_.size() * ncomps_, 0.f);
    if (outputFloats_ > 0) {
        outputValues_.assign(shaded_.size() * outputFloats_, 0.f);
        batch.outputs = &outputs_;
        batch.outputValues = outputValues_.data();
    }
    if (!attributes->matte) shading_.Shade(batch, Ci_.data(), Oi_.data());
    // Each shaded point's colour and opacity in RGB, once for all the samples that show it.
    shadedRgb_.resize(3 * shaded_.size());
    shadedOpacityRgb_.resize(3 * shaded_.size());
    for (size_t r = 0; r < shaded_.size(); ++r) {
        // A matte object's opacity is the surface's Os, not a shader's output (and a matte
        // group shades every member).
        const float* opacities = attributes->matte
                                     ? layers_.PointAt(members[size_t(shaded_[r])]).Os.data()
                                     : &Oi_[r * ncomps_];
        ToRgb(&Ci_[r * ncomps_], &shadedRgb_[3 * r]);
        OpacityToRgb(opacities, &shadedOpacityRgb_[3 * r]);
    }
    for (size_t j = 0; j < members.size(); ++j) {
        const int ray = layers_.HitAt(members[j]).ray;
        SampleState& sample = samples_[size_t(ray)];
        const size_t r = size_t(shadedBy_[j]);  // the shaded point this sample shows
        const float* rgb = &shadedRgb_[3 * r];
        const float* opacityRgb = &shadedOpacityRgb_[3 * r];
        float covered = 0;
        for (int c = 0; c < 3; ++c)
            covered += sample.transmittance[c] * std::clamp(opacityRgb[c], 0.f, 1.f);
        covered /= 3;
        if (CompositeLayer(3, rgb, opacityRgb, attributes->matte, sample.colour,
                           sample.transmittance) < kNegligibleTransmittance)
            layers_.Stop(ray);
        else
            sample.randomKey = MixBits(sample.randomKey);  // the next layer's seed's
        if (attributes->matte) continue;
        sample.alpha += covered;
        // AOVs are not premultiplied: each layer adds its value weighted by the coverage it
        // adds, so an opaque surface's AOV is its value.
        float* outputs = &sampleOutputs_[size_t(ray) * size_t(outputFloats_)];
        for (int k = 0; k < outputFloats_; ++k)
            outputs[k] += covered * outputValues_[r * outputFloats_ + k];
    }
}

PixelFilter MakeFilter(const Options& options, Diagnostics& diagnostics) {
    std::string error;
    std::optional<PixelFilter> filter = PixelFilter::FromRib(
        options.filterName, options.filterWidth[0], options.filterWidth[1], error);
    if (filter) return *filter;
    diagnostics.Warning(FileLoc{}, error + "; using gaussian 2 2");
    return PixelFilter();
}

std::string OutputName(const std::string& pattern, int frameNumber) {
    std::string name = pattern;
    const size_t hash = name.find('#');
    if (hash != std::string::npos) name.replace(hash, 1, std::to_string(frameNumber));
    return name;
}

std::vector<DisplaySpec> Displays(const Frame& frame, const RenderSettings& settings,
                                  Diagnostics& diagnostics) {
    std::vector<DisplaySpec> displays;
    // Under "bands" the components are not samples: no wavelength names them.
    const std::vector<double> channelWavelengths =
        frame.options.colorFromSamples.empty() ? frame.options.wavelengths : std::vector<double>();
    for (const DisplayRequest& d : frame.options.displays)
        displays.push_back({d.name, d.type, d.mode, d.params, d.loc, channelWavelengths, {}, {}});
    if (displays.empty()) {
        // RISpec's default display is the framebuffer; we have none, so name a file after the
        // scene.
        std::string stem = std::filesystem::path(frame.sceneFile).stem().string();
        if (stem.empty() || stem == "-") stem = "gonio";
        displays.push_back({stem + ".tif", "file", "rgba", {}, FileLoc{}, {}, {}, {}});
        if (settings.outputOverride.empty())
            diagnostics.NoteOnce("no display", FileLoc{},
                                 "no Display given: writing " + displays.back().name);
    }
    if (!settings.outputOverride.empty()) {
        // `-o out.exr` writes OpenEXR whatever type the scene's Display names: the format
        // follows the extension (docs/user-guide.md).
        displays[0].name = OutputName(settings.outputOverride, frame.number);
        displays[0].type = "file";
    }
    return displays;
}

// The AOVs the displays ask for: every mode that is not made of the standard channels (rgb,
// rgba, z, ...) names a shader variable. Their channels are appended to `channelNames` as
// name (one float), name.r, name.g, ... (colours) or name.x, name.y, ... (the rest); the image
// writer selects them by the mode. A name no shader has gets no channels, and its Display
// then fails with the writer's message.
std::vector<ShaderOutput> OutputsOfDisplays(const std::vector<DisplaySpec>& displays,
                                            const SurfaceShading& shading,
                                            std::vector<std::string>* channelNames) {
    static const std::vector<std::string> kStandard = {"r", "g", "b", "a", "z"};
    std::vector<ShaderOutput> outputs;
    for (const DisplaySpec& display : displays) {
        std::string unused;
        if (!SelectDisplayChannels(display.mode, kStandard, unused).empty()) continue;
        // A spectral display writes Ci's components, one per wavelength (image_writer.h).
        ShaderOutput output{display.mode == "spectral" ? "Ci" : display.mode};
        const bool seen = std::any_of(outputs.begin(), outputs.end(),
                                      [&](const ShaderOutput& o) { return o.name == output.name; });
        if (seen || !shading.DescribeOutput(&output)) continue;
        for (int c = 0; c < output.width; ++c) {
            const char* suffixes = output.isColor ? "rgb" : "xyz";
            const std::string suffix = output.width == 1   ? ""
                                       : output.width <= 3 ? std::string(".") + suffixes[c]
                                                           : "." + std::to_string(c);
            channelNames->push_back(output.name + suffix);
        }
        outputs.push_back(output);
    }
    return outputs;
}

// A located error, instead of std::bad_alloc, for an image this machine cannot hold.
bool FilmFitsInMemory(const FilmSpec& spec, const PixelFilter& filter, const Options& options,
                      Diagnostics& diagnostics) {
    const double needed = Film::BytesNeeded(spec, filter), memory = PhysicalMemoryBytes();
    if (memory == 0 || needed <= memory) return true;
    diagnostics.Error(options.formatLoc,
                      "Format " + std::to_string(options.xres) + " " +
                          std::to_string(options.yres) + ": the image needs " + ByteSize(needed) +
                          " (" + std::to_string(spec.channels) +
                          " channels a pixel, with the filter's margin), more than the " +
                          ByteSize(memory) + " of this machine's memory");
    return false;
}

std::vector<float> RowMajor(const Imath::M44f& m) {
    std::vector<float> values(16);
    for (int i = 0; i < 16; ++i) values[i] = m[i / 4][i % 4];
    return values;
}

// The camera as zfile and shadow displays record it (image_writer.h): world to camera, and
// world to screen with the screen window mapped to [-1, 1]², so that a map's lookup finds its
// pixel from the matrix alone, whatever the window was.
void RecordCamera(const Camera& camera, std::vector<DisplaySpec>* displays) {
    const float* w = camera.ScreenWindow();  // left right bottom top
    const float sx = 2 / (w[1] - w[0]), sy = 2 / (w[3] - w[2]);
    const Imath::M44f unitFromScreen(sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, 1, 0,
                                     -(w[0] + w[1]) / (w[1] - w[0]), -(w[2] + w[3]) / (w[3] - w[2]),
                                     0, 1);
    const Imath::M44f cameraFromWorld = camera.WorldFromCamera().inverse();
    const Imath::M44f unitScreenFromWorld =
        cameraFromWorld * camera.ScreenFromCamera() * unitFromScreen;
    for (DisplaySpec& display : *displays) {
        display.worldToCamera = RowMajor(cameraFromWorld);
        display.worldToScreen = RowMajor(unitScreenFromWorld);
    }
}

}  // namespace

bool RenderFrame(const Frame& frame, const RenderSettings& settings, Diagnostics& diagnostics,
                 RenderStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    const Options& options = frame.options;
    const Camera camera(options);
    const RayScene scene(frame, diagnostics);

    const int xsamples = std::max(1, int(std::lround(options.xsamples)));
    const int ysamples = std::max(1, int(std::lround(options.ysamples)));
    std::vector<DisplaySpec> displays = Displays(frame, settings, diagnostics);
    RecordCamera(camera, &displays);
    std::vector<std::string> channelNames = {"r", "g", "b", "a", "z"};
    // The path tracer reads the shaders itself; the frame loop's shading is then unused.
    const std::unique_ptr<PathIntegrator> paths =
        PathIntegrator::ForFrame(frame, scene, diagnostics);
    const std::unique_ptr<SurfaceShading> shading =
        paths ? MakeDefaultSurfaceShading(options.colorComponents)
              : MakeShaderShading(frame, scene, camera, diagnostics);
    const std::vector<ShaderOutput> outputs = OutputsOfDisplays(displays, *shading, &channelNames);
    float crop[4];
    ComposeCropWindow(options.cropWindow, settings.crop, crop);
    const FilmSpec spec =
        FilmSpec::FromCropWindow(options.xres, options.yres, crop[0], crop[1], crop[2], crop[3],
                                 xsamples, ysamples, int(channelNames.size()));
    const PixelFilter filter = MakeFilter(options, diagnostics);
    if (!FilmFitsInMemory(spec, filter, options, diagnostics)) return true;
    Film film(spec, filter, kTileSize);
    const Imath::Box2i range = film.PixelRange();
    const int width = range.max.x - range.min.x + 1, height = range.max.y - range.min.y + 1;

    // A shader's run-time error (a brdf() file it cannot use) makes the picture wrong: then the
    // frame is not written.
    const int errorsBefore = diagnostics.ErrorCount();
    Progress progress("render", uint64_t(width) * height, settings.progress);
    // What each thread keeps from tile to tile, made at its first tile (the renderer, which
    // uses the workers, is destroyed first).
    struct ThreadState {
        std::unique_ptr<ShadingWorker> worker;
        std::unique_ptr<PathWorker> paths;
        std::unique_ptr<TileRenderer> renderer;
    };
    PerThread<ThreadState> threads;
    const SampleGenerator generator(settings.seed, xsamples, ysamples, options, camera);
    const auto renderTile = [&](int tile) {
        const Imath::Box2i pixels = film.TilePixels(tile);
        ThreadState& thread = threads.Local();
        if (!thread.renderer) {
            thread.worker = shading->MakeWorker();
            if (paths) thread.paths = paths->MakeWorker();
            thread.renderer = std::make_unique<TileRenderer>(scene, camera, *thread.worker, options,
                                                             outputs, thread.paths.get());
        }
        TileRenderer* renderer = thread.renderer.get();
        FilmTile filmTile = film.StartTile(tile);
        renderer->Render(pixels, generator, &filmTile);
        film.StoreTile(std::move(filmTile));
        progress.Advance(uint64_t(pixels.max.x - pixels.min.x + 1) *
                         (pixels.max.y - pixels.min.y + 1));
    };
    // A frame of one tile (a tiny or empty one) is rendered on this thread: a parallel loop
    // would start oneTBB's workers (threads, its allocator) for nothing they could share.
    if (film.TileCount() == 1)
        renderTile(0);
    else
        tbb::parallel_for(tbb::blocked_range<int>(0, film.TileCount(), 1), [&](const auto& tiles) {
            for (int tile = tiles.begin(); tile != tiles.end(); ++tile) renderTile(tile);
        });
    progress.Done();
    shading->FinishFrame(diagnostics);  // point clouds the shaders baked, for later frames
    if (diagnostics.ErrorCount() > errorsBefore) {
        diagnostics.Error(FileLoc{}, "frame " + std::to_string(frame.number) +
                                         " is not written: its shaders met the errors above");
        return true;
    }

    Image image = film.Resolve();
    ApplyImager(frame, settings.seed, image, diagnostics);  // before Exposure: RISpec §4.1.2
    Exposure exposure{options.gain, options.gamma};
    const QuantizeSetting& cq = options.colorQuantize;
    const QuantizeSetting& dq = options.depthQuantize;
    bool ok = true;
    for (const DisplaySpec& display : displays)
        ok &= WriteDisplay(display, image, channelNames, exposure,
                           Quantization{cq.one, cq.min, cq.max, cq.dither},
                           Quantization{dq.one, dq.min, dq.max, dq.dither}, diagnostics);
    if (stats) {
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->cameraRays = uint64_t(width) * height * xsamples * ysamples;
        // Each thread's renderer and workers counted their own rays; the sum does not depend
        // on which thread rendered which tile.
        stats->rays = RayCounts{};
        threads.ForEach([&](const ThreadState& thread) {
            stats->rays.camera += thread.renderer->CameraRays();
            stats->rays += thread.worker->Rays();
            if (thread.paths) stats->rays.path += thread.paths->RaysTraced();
        });
        stats->width = spec.WindowWidth();
        stats->height = spec.WindowHeight();
    }
    return ok;
}

}  // namespace gonio
