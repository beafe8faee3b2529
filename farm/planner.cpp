#include "farm/planner.h"

#include <cstdio>
#include <filesystem>

#include "base/shard_range.h"

namespace gonio {
namespace {

std::string Padded(int value, int width) {
    char text[32];
    std::snprintf(text, sizeof text, "%0*d", width, value);
    return text;
}

// Exactly the float the renderer will parse: tiles that share an edge print the same text.
std::string EdgeText(int i, int n) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(float(i) / float(n)));
    return text;
}

std::string Extension(const std::string& fileName) {
    const std::string ext = std::filesystem::path(fileName).extension().string();
    return ext.empty() ? ".tif" : ext;  // a Display without an extension writes TIFF
}

// A task of `frame`: its name ("frame 3" and `what`), and the render of that frame with the
// job's seed followed by `extra` arguments.
FarmTask NewTask(const PlanRequest& request, TaskKind kind, int frame, const std::string& what,
                 const std::string& output, const std::vector<std::string>& extra) {
    FarmTask task;
    task.kind = kind;
    task.frame = frame;
    task.name = "frame " + std::to_string(frame) + what;
    task.output = output;
    task.retries = request.retries;
    task.args = {"render",   request.scene,
                 "--frames", std::to_string(frame),
                 "--seed",   std::to_string(request.seed)};
    task.args.insert(task.args.end(), extra.begin(), extra.end());
    return task;
}

void PlanShards(const PlanRequest& request, const SceneFrame& frame, FarmManifest* m) {
    const std::string stem = "frame_" + Padded(frame.number, 4);
    FarmMerge merge;
    merge.frame = frame.number;
    merge.output = "photons/" + stem + ".pm";
    if (!request.brdf.empty()) {
        merge.brdf = request.brdf;
        merge.brdfOutput = "photons/" + stem + ".grd";
    }
    const int n = request.photonShards;
    for (int s = 0; s < n; ++s) {
        const std::string shard = std::to_string(s) + "/" + std::to_string(n);
        FarmTask task =
            NewTask(request, TaskKind::kShard, frame.number, " shard " + shard,
                    "shards/" + stem + "_shard_" + Padded(s, 4) + ".pm", {"--photon-shard", shard});
        task.paths = ShardOf(frame.rays, s, n).count;  // as gonio render --photon-shard cuts
        merge.shards.push_back(int(m->tasks.size()));
        m->tasks.push_back(task);
    }
    m->merges.push_back(merge);
}

void PlanTiles(const PlanRequest& request, const SceneFrame& frame, FarmManifest* m) {
    const std::string ext = Extension(frame.fileName);
    if (ext == ".png" || ext == ".PNG")
        throw FarmError("frame " + std::to_string(frame.number) + " writes PNG (\"" +
                        frame.fileName +
                        "\"), which cannot record where a tile lies in the image: render it to "
                        "TIFF or OpenEXR to split it into tiles");
    const std::string stem = "frame_" + Padded(frame.number, 4);
    FarmImage image;
    image.frame = frame.number;
    image.output = "images/" + stem + ext;
    const int cols = request.tileColumns, rows = request.tileRows;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const FarmTask task =
                NewTask(request, TaskKind::kTile, frame.number,
                        " tile " + std::to_string(c) + "," + std::to_string(r),
                        "tiles/" + stem + "_tile_" + Padded(r, 3) + "_" + Padded(c, 3) + ext,
                        {"--crop", EdgeText(c, cols), EdgeText(c + 1, cols), EdgeText(r, rows),
                         EdgeText(r + 1, rows)});
            image.tiles.push_back(int(m->tasks.size()));
            m->tasks.push_back(task);
        }
    }
    m->images.push_back(image);
}

void PlanFrame(const PlanRequest& request, const SceneFrame& frame, FarmManifest* m) {
    m->tasks.push_back(
        NewTask(request, TaskKind::kFrame, frame.number, "",
                "images/frame_" + Padded(frame.number, 4) + Extension(frame.fileName), {}));
}

}  // namespace

FarmManifest PlanJob(const PlanRequest& request, const std::vector<SceneFrame>& frames) {
    if (frames.empty()) throw FarmError(request.scene + ": error: no frame to plan");
    if (request.photonShards < 1 || request.tileColumns < 1 || request.tileRows < 1 ||
        request.chunk < 1 || request.retries < 0)
        throw FarmError("shards, tiles and chunk must be at least 1, retries at least 0");
    FarmManifest m;
    m.scene = request.scene;
    m.gonio = request.gonio;
    m.chunk = request.chunk;
    m.slurm = request.slurm;
    const bool tiled = request.tileColumns * request.tileRows > 1;
    for (const SceneFrame& frame : frames) {
        if (frame.brdfLight)
            PlanShards(request, frame, &m);
        else if (tiled)
            PlanTiles(request, frame, &m);
        else
            PlanFrame(request, frame, &m);
    }
    if (request.photonShards > 1 && m.merges.empty())
        throw FarmError(request.scene +
                        ": error: --photon-shards needs a frame with Option \"BRDFLight\"");
    if (!request.brdf.empty() && m.merges.empty())
        throw FarmError(request.scene + ": error: --brdf needs a frame with Option \"BRDFLight\"");
    return m;
}

}  // namespace gonio
