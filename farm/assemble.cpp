#include "farm/assemble.h"

#include <filesystem>

#include "brdfsim/photon_map_merge.h"
#include "farm/process.h"
#include "farm/task_output.h"
#include "farm/tile_join.h"

namespace gonio {
namespace {

std::vector<std::string> OutputsOf(const std::string& jobDir, const FarmManifest& m,
                                   const std::vector<int>& tasks) {
    std::vector<std::string> paths;
    for (int i : tasks) paths.push_back(JobPath(jobDir, m.tasks[i].output));
    return paths;
}

void CreateFolderOf(const std::string& path) {
    std::error_code error;  // a failure shows when the file is written
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), error);
}

// "" on success, else why not.
std::string Merge(const std::string& jobDir, const FarmManifest& m, const FarmMerge& merge,
                  std::FILE* log) {
    const std::string output = JobPath(jobDir, merge.output);
    CreateFolderOf(output);
    try {
        const PhotonMapHeader total = MergePhotonMaps(OutputsOf(jobDir, m, merge.shards), output);
        std::fprintf(log, "farm assemble: %s: %llu photons of %llu paths from %zu shards\n",
                     merge.output.c_str(), static_cast<unsigned long long>(total.count),
                     static_cast<unsigned long long>(total.paths), merge.shards.size());
    } catch (const std::exception& e) {
        return e.what();
    }
    if (merge.brdf.empty()) return "";
    std::vector<std::string> argv = {m.gonio, "brdf"};
    argv.insert(argv.end(), merge.brdf.begin(), merge.brdf.end());
    argv.insert(argv.end(), {output, JobPath(jobDir, merge.brdfOutput)});
    std::string error;
    const pid_t pid = StartProcess(argv, &error);
    if (pid < 0) return error;
    const ChildStatus status = WaitProcess(pid);
    return status.Ok() ? "" : "gonio brdf " + merge.brdf.front() + ": " + status.Describe();
}

}  // namespace

std::vector<std::string> IncompleteTasks(const std::string& jobDir, const FarmManifest& m) {
    std::vector<std::string> lines;
    for (size_t i = 0; i < m.tasks.size(); ++i) {
        const FarmTask& task = m.tasks[i];
        const std::string reason = CheckTaskOutput(task, JobPath(jobDir, task.output));
        if (!reason.empty())
            lines.push_back("task " + std::to_string(i) + " (" + task.name + "): " + task.output +
                            ": " + reason);
    }
    return lines;
}

void RemoveAssembledOutputs(const std::string& jobDir, const FarmManifest& m) {
    std::error_code error;  // absent already: nothing to remove
    for (const FarmMerge& merge : m.merges) {
        std::filesystem::remove(JobPath(jobDir, merge.output), error);
        if (!merge.brdfOutput.empty())
            std::filesystem::remove(JobPath(jobDir, merge.brdfOutput), error);
    }
    for (const FarmImage& image : m.images)
        std::filesystem::remove(JobPath(jobDir, image.output), error);
}

int AssembleJob(const std::string& jobDir, const FarmManifest& m, std::FILE* log) {
    const std::vector<std::string> incomplete = IncompleteTasks(jobDir, m);
    for (const std::string& line : incomplete)
        std::fprintf(log, "%s: error: %s\n", ManifestPath(jobDir).c_str(), line.c_str());
    if (!incomplete.empty()) {
        std::fprintf(log,
                     "farm assemble: %zu of %zu tasks incomplete; nothing assembled (run them "
                     "again: gonio farm submit %s skips the complete ones)\n",
                     incomplete.size(), m.tasks.size(), jobDir.c_str());
        return 1;
    }
    int failed = 0;
    for (const FarmMerge& merge : m.merges) {
        const std::string error = Merge(jobDir, m, merge, log);
        if (!error.empty())
            std::fprintf(log, "farm assemble: %s: error: %s\n", merge.output.c_str(),
                         error.c_str());
        failed += !error.empty();
    }
    for (const FarmImage& image : m.images) {
        const std::string output = JobPath(jobDir, image.output);
        CreateFolderOf(output);
        const std::string error = JoinTiles(OutputsOf(jobDir, m, image.tiles), output);
        if (error.empty())
            std::fprintf(log, "farm assemble: %s: joined %zu tiles\n", image.output.c_str(),
                         image.tiles.size());
        else
            std::fprintf(log, "farm assemble: error: %s\n", error.c_str());
        failed += !error.empty();
    }
    return failed == 0 ? 0 : 1;
}

}  // namespace gonio
