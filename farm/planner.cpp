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

std::vector<std::string> RenderArgs(const PlanRequest& request, int frame) {
    return {"render",   request.scene,
            "--frames", std::to_string(frame),
            "--seed",   std::to_string(request.seed)};
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
        FarmTask task;
        task.kind = TaskKind::kShard;
        task.frame = frame.number;
        task.name = "frame " + std::to_string(frame.number) + " shard " + std::to_string(s) + "/" +
                    std::to_string(n);
        task.output = "shards/" + stem + "_shard_" + Padded(s, 4) + ".pm";
        task.args = RenderArgs(request, frame.number);
        task.args.insert(task.args.end(),
                         {"--photon-shard", std::to_string(s) + "/" + std::to_string(n)});
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
            FarmTask task;
            task.kind = TaskKind::kTile;
            task.frame = frame.number;
            task.name = "frame " + std::to_string(frame.number) + " tile " + std::to_string(c) +
                        "," + std::to_string(r);
            task.output = "tiles/" + stem + "_tile_" + Padded(r, 3) + "_" + Padded(c, 3) + ext;
            task.args = RenderArgs(request, frame.number);
            task.args.insert(task.args.end(), {"--crop", EdgeText(c, cols), EdgeText(c + 1, cols),
                                               EdgeText(r, rows), EdgeText(r + 1, rows)});
            image.tiles.push_back(int(m->tasks.size()));
            m->tasks.push_back(task);
        }
    }
    m->images.push_back(image);
}

void PlanFrame(const PlanRequest& request, const SceneFrame& frame, FarmManifest* m) {
    FarmTask task;
    task.kind = TaskKind::kFrame;
    task.frame = frame.number;
    task.name = "frame " + std::to_string(frame.number);
    task.output = "images/frame_" + Padded(frame.number, 4) + Extension(frame.fileName);
    task.args = RenderArgs(request, frame.number);
    m->tasks.push_back(task);
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
    m.retries = request.retries;
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
