#include "render/frame_renderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "image/film.h"
#include "image/image_writer.h"
#include "render/camera.h"
#include "render/progress.h"
#include "render/random.h"
#include "render/ray_scene.h"

namespace gonio {
namespace {

constexpr int kTileSize = 16;
constexpr int kMaxLayers = 64;  // transparent surfaces a camera ray may pass through

// The RenderMan default surface until the shading language lands: a facing ratio,
// Ci = Os·Cs·(Ka + Kd·|N·I|) with Ka = 0.2, Kd = 0.8 (RISpec App. A "defaultsurface").
void ShadeDefaultSurface(const SurfacePoint& sp, const Imath::V3f& dir, float* colour) {
    const float facing = std::fabs(sp.N.dot(dir.normalized()));
    for (size_t c = 0; c < sp.Cs.size(); ++c) colour[c] = sp.Cs[c] * (0.2f + 0.8f * facing);
}

float Average(const std::vector<float>& values) {
    float sum = 0;
    for (float v : values) sum += v;
    return values.empty() ? 0 : sum / values.size();
}

// Follows a camera ray through transparent surfaces, compositing front to back. Writes r g b a z.
int TraceCameraRay(const RayScene& scene, const CameraRay& ray, float* out) {
    float transmittance[3] = {1, 1, 1};
    for (int c = 0; c < kStandardChannelCount; ++c) out[c] = 0;
    out[kChannelZ] = std::numeric_limits<float>::infinity();
    float tnear = ray.tnear;
    int rays = 0;
    for (int layer = 0; layer < kMaxLayers; ++layer) {
        RayHit hit;
        ++rays;
        if (!scene.Intersect(ray.org, ray.dir, tnear, ray.tfar, &hit)) break;
        tnear = hit.t + std::max(1e-5f, 1e-5f * hit.t);
        const SurfacePoint sp = scene.Evaluate(ray.org, ray.dir, hit);
        const Attributes& attributes = *sp.shape->attributes;
        if (!attributes.twoSided && sp.Ng.dot(ray.dir) > 0) continue;  // Sides 1: a back face
        if (std::isinf(out[kChannelZ])) out[kChannelZ] = hit.t;
        float colour[3] = {0, 0, 0};
        if (!attributes.matte) ShadeDefaultSurface(sp, ray.dir, colour);
        float remaining = 0;
        for (int c = 0; c < 3; ++c) {
            const float opacity = std::clamp(c < int(sp.Os.size()) ? sp.Os[c] : 1.f, 0.f, 1.f);
            // A matte object hides what lies behind it and contributes nothing itself.
            if (!attributes.matte) out[c] += transmittance[c] * opacity * colour[c];
            transmittance[c] *= 1 - opacity;
            remaining = std::max(remaining, transmittance[c]);
        }
        if (remaining < 1e-4f) break;
    }
    const float t = (transmittance[0] + transmittance[1] + transmittance[2]) / 3;
    out[kChannelA] = 1 - t;
    return rays;
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
    for (const DisplayRequest& d : frame.options.displays)
        displays.push_back({d.name, d.type, d.mode, d.params, d.loc});
    if (displays.empty()) {
        // RISpec's default display is the framebuffer; we have none, so name a file after the
        // scene.
        std::string stem = std::filesystem::path(frame.sceneFile).stem().string();
        if (stem.empty() || stem == "-") stem = "gonio";
        displays.push_back({stem + ".tif", "file", "rgba", {}, FileLoc{}});
        diagnostics.NoteOnce("no display", FileLoc{},
                             "no Display given: writing " + displays.back().name);
    }
    if (!settings.outputOverride.empty())
        displays[0].name = OutputName(settings.outputOverride, frame.number);
    return displays;
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
    const FilmSpec spec = FilmSpec::FromCropWindow(
        options.xres, options.yres, options.cropWindow[0], options.cropWindow[1],
        options.cropWindow[2], options.cropWindow[3], xsamples, ysamples, kStandardChannelCount);
    Film film(spec, MakeFilter(options, diagnostics));
    const Imath::Box2i range = film.PixelRange();
    const int width = range.max.x - range.min.x + 1, height = range.max.y - range.min.y + 1;

    Progress progress("render", uint64_t(width) * height, settings.progress);
    std::atomic<uint64_t> raysTraced{0};
    tbb::parallel_for(tbb::blocked_range2d<int>(range.min.y, range.max.y + 1, kTileSize,
                                                range.min.x, range.max.x + 1, kTileSize),
                      [&](const tbb::blocked_range2d<int>& tile) {
                          uint64_t rays = 0;
                          float values[kStandardChannelCount];
                          for (int py = tile.rows().begin(); py < tile.rows().end(); ++py) {
                              for (int px = tile.cols().begin(); px < tile.cols().end(); ++px) {
                                  for (int sy = 0, s = 0; sy < ysamples; ++sy) {
                                      for (int sx = 0; sx < xsamples; ++sx, ++s) {
                                          SampleRandom random(settings.seed, px, py, s);
                                          // Stratified: one jittered sample in each cell of the
                                          // pixel's grid.
                                          const float x = px + (sx + random.Next()) / xsamples;
                                          const float y = py + (sy + random.Next()) / ysamples;
                                          const float lensU = random.Next(), lensV = random.Next();
                                          const CameraRay ray =
                                              camera.GenerateRay(x, y, lensU, lensV);
                                          rays += TraceCameraRay(scene, ray, values);
                                          film.SetSample(px, py, s, x, y, values);
                                      }
                                  }
                              }
                              progress.Advance(tile.cols().size());
                          }
                          raysTraced += rays;
                      });
    progress.Done();

    const Image image = film.Resolve();
    static const std::vector<std::string> kChannelNames = {"r", "g", "b", "a", "z"};
    Exposure exposure{options.gain, options.gamma};
    const QuantizeSetting& cq = options.colorQuantize;
    const QuantizeSetting& dq = options.depthQuantize;
    bool ok = true;
    for (const DisplaySpec& display : Displays(frame, settings, diagnostics))
        ok &= WriteDisplay(display, image, kChannelNames, exposure,
                           Quantization{cq.one, cq.min, cq.max, cq.dither},
                           Quantization{dq.one, dq.min, dq.max, dq.dither}, diagnostics);
    if (stats) {
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->cameraRays = uint64_t(width) * height * xsamples * ysamples;
        stats->raysTraced = raysTraced;
        stats->width = spec.WindowWidth();
        stats->height = spec.WindowHeight();
    }
    return ok;
}

}  // namespace gonio
