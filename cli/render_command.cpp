// gonio render SCENE.rib [-o OUT] [--threads N] [--seed S] [--progress] [--stats] [--strict]
//                        [--frames A-B] [--crop X0 X1 Y0 Y1] [--photon-shard I/N]

#include <tbb/global_control.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "commands.h"
#include "frame_range.h"
#include "renderer/frame/frame_renderer.h"
#include "renderer/image/texture_making.h"
#include "renderer/photon/photon_frame.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_file.h"
#include "renderer/scene/unused_parameters.h"

namespace gonio {
namespace {

struct RenderOptions {
    std::string scene;
    std::string output;
    int threads = 0;
    uint64_t seed = 0;
    bool progress = false;
    bool stats = false;
    bool strict = false;
    std::string frames;  // "A-B": render only these FrameBegin numbers
    std::vector<float> crop;
    std::string photonShard;  // "I/N"
};

// "I/N" with 0 <= I < N into the settings; the reason on failure, "" on success.
std::string ParsePhotonShard(const std::string& text, RenderSettings* settings) {
    unsigned long long shard = 0, shards = 0;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%llu/%llu%c", &shard, &shards, &rest) != 2 || shards == 0 ||
        shard >= shards || text.find('-') != std::string::npos)
        return "--photon-shard expects I/N with 0 <= I < N, got '" + text + "'";
    settings->photonShard = shard;
    settings->photonShards = shards;
    return "";
}

// The command-line settings beyond the seed and output; the reason on failure, "" on success.
std::string ReadSettings(const RenderOptions& options, RenderSettings* settings,
                         FrameRange* frames) {
    if (!options.frames.empty()) {
        const std::string error = ParseFrameRange(options.frames, frames);
        if (!error.empty()) return "--frames: " + error;
    }
    if (!options.crop.empty()) {
        const std::vector<float>& c = options.crop;
        if (!(0 <= c[0] && c[0] < c[1] && c[1] <= 1 && 0 <= c[2] && c[2] < c[3] && c[3] <= 1))
            return "--crop expects X0 X1 Y0 Y1 with 0 <= X0 < X1 <= 1 and 0 <= Y0 < Y1 <= 1";
        std::copy(c.begin(), c.end(), settings->crop);
    }
    return options.photonShard.empty() ? "" : ParsePhotonShard(options.photonShard, settings);
}

// The breakdown names only the kinds of ray the frame traced; its parts sum to the total.
void PrintStats(const Frame& frame, const RenderStats& stats) {
    const RayCounts& rays = stats.rays;
    const std::pair<const char*, uint64_t> kinds[] = {{"camera", rays.camera},
                                                      {"trace", rays.trace},
                                                      {"shadow", rays.shadow},
                                                      {"sampled", rays.sampled},
                                                      {"differential", rays.differential},
                                                      {"path", rays.path}};
    std::string breakdown;
    for (const auto& [name, count] : kinds) {
        if (count == 0) continue;
        breakdown += (breakdown.empty() ? " (" : ", ") + std::to_string(count) + " " + name;
    }
    if (!breakdown.empty()) breakdown += ")";
    const uint64_t total = rays.Total();
    std::fprintf(
        stderr, "frame %d: %dx%d, %.3f s, %llu camera rays, %llu rays traced%s, %.2f Mrays/s\n",
        frame.number, stats.width, stats.height, stats.seconds,
        static_cast<unsigned long long>(stats.cameraRays), static_cast<unsigned long long>(total),
        breakdown.c_str(), stats.seconds > 0 ? total / stats.seconds * 1e-6 : 0.0);
}

// The scene file; standard input can be read only once, and a scene with bands or svd, or whose
// rays reach a DelayedReadArchive out of view, is read again.
RibReader ReaderOf(const std::string& scene, Diagnostics& reported) {
    auto reads = std::make_shared<int>(0);
    return [scene, reads, &reported](RiTarget& target, Diagnostics& diagnostics) {
        if (scene == "-" && (*reads)++ > 0) {
            reported.Error(FileLoc{std::make_shared<const std::string>("<stdin>"), 0, 0},
                           "a frame with Option \"spectral\" \"basis\" \"bands\" or \"svd\", "
                           "or whose rays reach a DelayedReadArchive out of view, is read "
                           "again, and standard input only once: give the scene as a file");
            return;
        }
        ParseRibFile(scene, target, diagnostics);
    };
}

int RunRender(const RenderOptions& options) {
    if (options.scene != "-" && !std::filesystem::is_regular_file(options.scene)) {
        std::fprintf(stderr, "gonio render: cannot open scene file '%s'\n", options.scene.c_str());
        return 2;
    }
    std::unique_ptr<tbb::global_control> threadLimit;
    if (options.threads > 0)
        threadLimit = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, options.threads);

    Diagnostics diagnostics;
    RenderSettings settings;
    FrameRange frames;
    const std::string error = ReadSettings(options, &settings, &frames);
    if (!error.empty()) {
        std::fprintf(stderr, "gonio render: %s\n", error.c_str());
        return 2;
    }
    settings.seed = options.seed;
    settings.progress = options.progress;
    settings.outputOverride = options.output;
    bool outputFailed = false;
    int rendered = 0;
    auto renderFrame = [&](const Frame& frame) {
        if (!frames.Contains(frame.number)) return;
        ++rendered;
        const bool abort = options.strict || frame.options.errorHandler == "abort";
        if (diagnostics.ErrorCount() > 0 && abort) {
            std::fprintf(stderr,
                         "gonio render: frame %d not rendered because of the errors above\n",
                         frame.number);
            return;
        }
        if (IsBrdfLightFrame(frame)) {
            outputFailed |= !TracePhotonFrame(frame, settings, diagnostics);
        } else {
            RenderStats stats;
            outputFailed |= !RenderFrame(frame, settings, diagnostics, &stats);
            if (options.stats) PrintStats(frame, stats);
        }
        ReportUnusedParameters(frame, diagnostics);
    };
    int texturesMade = 0;
    auto makeTexture = [&](const TextureRequest& request) {
        if (MakeRequestedTexture(request, diagnostics)) ++texturesMade;
    };
    BuildScene(options.scene, ReaderOf(options.scene, diagnostics), diagnostics, renderFrame,
               makeTexture);
    if (outputFailed) return 2;
    // A RIB that only makes textures (as scenes prepare their maps) has done its work.
    if (rendered == 0 && texturesMade == 0 && diagnostics.ErrorCount() == 0) {
        if (frames.Given()) {
            std::fprintf(stderr, "gonio render: the scene has no frame in --frames %s\n",
                         options.frames.c_str());
            return 2;
        }
        std::fprintf(stderr,
                     "gonio render: error: %s has no WorldBegin ... WorldEnd, so there is no "
                     "image to render\n",
                     options.scene == "-" ? "the standard input" : options.scene.c_str());
        return 1;
    }
    return diagnostics.ErrorCount() > 0 ? 1 : 0;
}

}  // namespace

void AddRenderCommand(CLI::App& app, int* exitCode) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render every frame of a RIB scene");
    cmd->add_option("scene", options->scene, "RIB file, or - for standard input")->required();
    cmd->add_option("-o,--output", options->output,
                    "Write the first Display to this file instead (# becomes the frame number)");
    cmd->add_option("--threads", options->threads, "Worker threads (default: all cores)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--seed", options->seed, "Seed of the sample pattern (default 0)");
    cmd->add_flag("--progress", options->progress, "Show a progress line for long renders");
    cmd->add_flag("--stats", options->stats, "Print time and ray counts per frame");
    cmd->add_flag("--strict", options->strict,
                  "Render no frame after an error (as ErrorHandler \"abort\"); by default bad "
                  "requests are reported, skipped, and rendering goes on");
    cmd->add_option("--frames", options->frames,
                    "Render only the frames A-B (FrameBegin numbers, inclusive) or A");
    cmd->add_option("--crop", options->crop,
                    "Render only this part X0 X1 Y0 Y1 of the scene's CropWindow (fractions of "
                    "it); tiles that share edges join into the whole image exactly")
        ->expected(4);
    cmd->add_option("--photon-shard", options->photonShard,
                    "BRDFLight: trace only shard I/N of the paths; the N maps merged in order "
                    "equal the unsplit map");
    cmd->callback([options, exitCode] { *exitCode = RunRender(*options); });
}

}  // namespace gonio
