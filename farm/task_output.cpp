#include "farm/task_output.h"

#include <filesystem>

#include "brdfsim/photon_map.h"
#include "imageio/oiio_plugin.h"

namespace gonio {
namespace {

std::string CheckPhotonMap(const FarmTask& task, const std::string& path) {
    try {
        PhotonMapReader reader(path);
        if (reader.Header().paths != task.paths)
            return "its header counts " + std::to_string(reader.Header().paths) +
                   " paths, the shard traces " + std::to_string(task.paths);
        std::vector<float> rows;
        while (reader.ReadBatch(1 << 18, rows)) rows.clear();
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

std::string CheckImage(const std::string& path) {
    std::string error;
    try {
        const ImageFileContents image =
            LoadOiioPlugin("checking the farm output \"" + path + "\"").ReadImage(path, &error);
        if (error.empty() && image.pixels.empty()) error = "the image has no pixels";
    } catch (const std::exception& e) {
        error = e.what();
    }
    return error.empty() ? "" : "cannot read the image: " + error;
}

}  // namespace

std::string CheckTaskOutput(const FarmTask& task, const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return "missing";
    return task.kind == TaskKind::kShard ? CheckPhotonMap(task, path) : CheckImage(path);
}

}  // namespace gonio
