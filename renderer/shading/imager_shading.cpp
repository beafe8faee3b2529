#include "renderer/shading/imager_shading.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "renderer/shading/frame_shaders.h"
#include "renderer/shading/named_textures.h"
#include "renderer/shading/option_query.h"
#include "shaderlang/shading_context.h"
#include "shaderlang/shading_system.h"

namespace gonio {
namespace {

// Pixels run in fixed tiles, so that a pixel's neighbours (for Du/Dv) do not depend on how the
// threads split the work; 256 points keep the interpreter's registers in cache.
constexpr int kTileSize = 16;

// What an imager shader may ask of the renderer: the spaces of a finished image and textures;
// no lights, shadows or traced rays (those belong to the scene, which is gone by now).
class ImagerContext : public sl::ShadingContext {
  public:
    ImagerContext(const Frame& frame, ShadingFiles& textures, Diagnostics& diagnostics)
        : frame_(frame),
          diagnostics_(diagnostics),
          textures_(textures, FrameTextureSearchPath(frame)) {}

    // A batch of a tile of `width` x `height` pixels, row by row, whose random() streams start
    // from `seeds` (one per pixel).
    void Begin(int width, int height, const uint64_t* seeds) {
        n_ = width * height;
        colorComponents_ = frame_.options.colorComponents;
        uNeighbours_.assign(size_t(n_), -1);
        vNeighbours_.assign(size_t(n_), -1);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const int k = y * width + x;
                if (x + 1 < width) uNeighbours_[k] = k + 1;
                if (y + 1 < height) vNeighbours_[k] = k + width;
            }
        }
        // Raster x is "u" and raster y "v": the neighbours are one pixel away along each.
        steps_.assign(4 * size_t(n_), 0.f);
        std::fill_n(steps_.begin(), n_, 1.f);
        std::fill_n(steps_.begin() + 3 * n_, n_, 1.f);
        SeedRandom(seeds);
    }

    bool Option(const std::string& name, const sl::TypeSpec& type, std::vector<float>* floats,
                std::string*) const override {
        return QueryOption(frame_.options, name, type, floats);
    }

    // P is in raster space, so "current" space is raster space here; NDC spans the full frame.
    bool CurrentFromSpace(const std::string& space, int, Imath::M44f* m) const override {
        if (space == "current" || space == "raster") {
            *m = Imath::M44f();
            return true;
        }
        if (space == "NDC") {
            *m = Imath::M44f().setScale(
                Imath::V3f(float(frame_.options.xres), float(frame_.options.yres), 1.f));
            return true;
        }
        return false;
    }
    bool Texture(const std::string& name, int firstChannel, int channels,
                 const TextureWrapModes& wrap, const float* s, const float* t, const float* dsdx,
                 const float* dtdx, const float* dsdy, const float* dtdy, const uint8_t* active,
                 float* out) override {
        return textures_.Texture(*this, n_, name, firstChannel, channels, wrap, s, t, dsdx, dtdx,
                                 dsdy, dtdy, active, out);
    }
    bool Environment(const std::string& name, int firstChannel, int channels,
                     const float* directions, const uint8_t* active, float* out) override {
        return textures_.Environment(*this, n_, name, firstChannel, channels, directions, active,
                                     out);
    }
    std::string FindTexture(const std::string& name) const override { return textures_.Find(name); }
    bool MeasuredBrdf(const std::string& name, int count, const float* wIn, const float* wOut,
                      const uint8_t* active, float* out) override {
        return textures_.MeasuredBrdf(*this, count, name, wIn, wOut, active, out);
    }
    // The texture's matrices take world space to its camera, and an imager has no world.
    bool TextureInfo(const std::string& name, const std::string& dataname,
                     std::vector<float>* floats, std::string* text) override {
        if (dataname == "viewingmatrix" || dataname == "projectionmatrix") return false;
        return textures_.Info(name, dataname, floats, text);
    }
    // At the shader statement, naming the Imager request.
    void RuntimeWarning(const std::string& key, const std::string& message) override {
        const ShaderInstance& request = frame_.options.imager;
        const std::string& where = Statement();
        const FileLoc loc = where.empty() ? request.loc : sl::StatementLoc(where, "");
        diagnostics_.WarningOnce(
            "imager " + where + key, loc,
            message + " (imager \"" + request.name + "\" of " + request.loc.ToString() + ")");
    }
    const int* UNeighbours() const override { return uNeighbours_.data(); }
    const int* VNeighbours() const override { return vNeighbours_.data(); }
    const float* NeighbourSteps() const override { return steps_.data(); }

  private:
    const Frame& frame_;
    Diagnostics& diagnostics_;
    NamedTextures textures_;
    std::vector<int> uNeighbours_, vNeighbours_;
    std::vector<float> steps_;
};

// The shader's colours from the image's RGB and back: ColorSamples' matrices, or none.
class ColourConversion {
  public:
    explicit ColourConversion(const Options& options)
        : ncomps_(options.colorComponents),
          toRgb_(options.colorToRgb),
          fromRgb_(options.colorFromRgb) {}

    // The shader's colour (ncomps_ floats, each `stride` apart) of an RGB pixel.
    void FromRgb(const float* rgb, float* colour, size_t stride) const {
        for (int i = 0; i < ncomps_; ++i) {
            float value = 0;
            if (fromRgb_.empty()) {
                value = rgb[std::min(i, 2)];
            } else {
                for (int c = 0; c < 3; ++c) value += rgb[c] * fromRgb_[size_t(c) * ncomps_ + i];
            }
            colour[i * stride] = value;
        }
    }

    // The pixel's RGB after the shader changed its colour from `before` to `after`. Without
    // ColorSamples the colour is the RGB; with them only the change goes through nRGB, because
    // nRGB·RGBn need not be the identity and a pixel the shader left alone must stay as it was.
    void ToRgb(const sl::FloatArg& after, const float* before, int point, size_t stride,
               float* rgb) const {
        if (toRgb_.empty()) {
            for (int c = 0; c < 3; ++c) rgb[c] = after.At(std::min(c, ncomps_ - 1), point);
            return;
        }
        for (int i = 0; i < ncomps_; ++i) {
            const float change = after.At(i, point) - before[i * stride];
            for (int c = 0; c < 3; ++c) rgb[c] += change * toRgb_[3 * size_t(i) + c];
        }
    }

  private:
    int ncomps_;
    std::vector<float> toRgb_, fromRgb_;
};

// Runs the imager over tiles; one per thread.
class ImagerWorker {
  public:
    ImagerWorker(const Frame& frame, sl::ShaderInstance& instance, ShadingFiles& textures,
                 Diagnostics& diagnostics)
        : frame_(frame),
          instance_(instance),
          context_(frame, textures, diagnostics),
          colours_(frame.options) {}

    void RunTile(int x0, int y0, int width, int height, uint64_t seed, Image& image);

  private:
    const Frame& frame_;
    sl::ShaderInstance& instance_;
    ImagerContext context_;
    ColourConversion colours_;
    sl::ShaderExecutor executor_;
    std::vector<float> P_, s_, t_, Ci_, Oi_, alpha_;
    std::vector<uint64_t> seeds_;
};

void ImagerWorker::RunTile(int x0, int y0, int width, int height, uint64_t seed, Image& image) {
    const int n = width * height, ncomps = frame_.options.colorComponents;
    P_.assign(3 * size_t(n), 0.f);
    s_.resize(size_t(n));
    t_.resize(size_t(n));
    Ci_.assign(size_t(ncomps) * n, 0.f);
    Oi_.assign(size_t(ncomps) * n, 0.f);
    alpha_.assign(size_t(n), 0.f);
    seeds_.resize(size_t(n));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int k = y * width + x;
            const float* pixel = image.At(x0 + x, y0 + y);
            const int rasterX = image.xorigin + x0 + x, rasterY = image.yorigin + y0 + y;
            P_[k] = rasterX + 0.5f;
            P_[n + k] = rasterY + 0.5f;
            // s, t: the pixel centre across the whole frame (Format), 0 to 1 from the top left,
            // as a full-screen texture lookup in an imager expects.
            s_[k] = P_[k] / float(frame_.options.xres);
            t_[k] = P_[n + k] / float(frame_.options.yres);
            colours_.FromRgb(pixel, &Ci_[k], size_t(n));
            for (int c = 0; c < ncomps; ++c) Oi_[size_t(c) * n + k] = pixel[kChannelA];
            alpha_[k] = pixel[kChannelA];
            seeds_[k] =
                MixBits(seed ^ MixBits((uint64_t(uint32_t(rasterY)) << 32) | uint32_t(rasterX)));
        }
    }
    sl::ShaderGlobals globals;
    globals.n = n;
    globals.P = P_.data();
    globals.s = s_.data();
    globals.t = t_.data();
    globals.Ci = Ci_.data();
    globals.Oi = Oi_.data();
    globals.alphas = alpha_.data();
    globals.time = frame_.options.shutterOpen;
    globals.dtime = frame_.options.shutterClose - frame_.options.shutterOpen;
    context_.Begin(width, height, seeds_.data());
    executor_.Run(instance_, globals, context_);
    const sl::FloatArg Ci = executor_.Output("Ci");
    const sl::FloatArg alpha = executor_.Output("alpha");
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int k = y * width + x;
            float* pixel = image.At(x0 + x, y0 + y);
            if (Ci.data) colours_.ToRgb(Ci, &Ci_[k], k, size_t(n), pixel);
            if (alpha.data) pixel[kChannelA] = alpha.At(0, k);
        }
    }
}

}  // namespace

bool ApplyImager(const Frame& frame, uint64_t seed, Image& image, Diagnostics& diagnostics) {
    const ShaderInstance& request = frame.options.imager;
    if (!request.IsSet() || image.channels <= kChannelA) return false;
    sl::ShadingSystem system(diagnostics, frame.options.colorComponents);
    system.SetSearchPath(ShaderSearchPath(frame));
    // The imager's "shader" space is its current space: raster space, with nothing to move.
    const std::shared_ptr<sl::ShaderInstance> instance =
        LoadShaderInstance(system, request, sl::ShaderType::Imager, Imath::M44f(), Declarations(),
                           frame.options, diagnostics);
    if (!instance) return false;
    instance->Specialize();  // before the threads share it

    const int tilesX = (image.width + kTileSize - 1) / kTileSize;
    const int tilesY = (image.height + kTileSize - 1) / kTileSize;
    ShadingFiles textures;
    tbb::enumerable_thread_specific<std::unique_ptr<ImagerWorker>> workers;
    tbb::parallel_for(0, tilesX * tilesY, [&](int tile) {
        const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
        std::unique_ptr<ImagerWorker>& worker = workers.local();
        if (!worker)
            worker = std::make_unique<ImagerWorker>(frame, *instance, textures, diagnostics);
        worker->RunTile(x0, y0, std::min(kTileSize, image.width - x0),
                        std::min(kTileSize, image.height - y0), seed, image);
    });
    return true;
}

}  // namespace gonio
