#include "farm/manifest.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/atomic_file.h"

namespace gonio {
namespace {

using nlohmann::json;

constexpr int kManifestVersion = 1;

const TaskKind kKinds[] = {TaskKind::kShard, TaskKind::kFrame, TaskKind::kTile};

json TaskToJson(const FarmTask& t) {
    json j = {{"kind", TaskKindName(t.kind)},
              {"name", t.name},
              {"output", t.output},
              {"args", t.args},
              {"frame", t.frame},
              {"retries", t.retries}};
    if (t.kind == TaskKind::kShard) j["paths"] = t.paths;
    return j;
}

json ToJson(const FarmManifest& m) {
    json tasks = json::array(), merges = json::array(), images = json::array();
    for (const FarmTask& t : m.tasks) tasks.push_back(TaskToJson(t));
    for (const FarmMerge& g : m.merges)
        merges.push_back({{"frame", g.frame},
                          {"output", g.output},
                          {"shards", g.shards},
                          {"brdf", g.brdf},
                          {"brdfOutput", g.brdfOutput}});
    for (const FarmImage& i : m.images)
        images.push_back({{"frame", i.frame}, {"output", i.output}, {"tiles", i.tiles}});
    const SlurmSettings& s = m.slurm;
    return {{"version", kManifestVersion},
            {"scene", m.scene},
            {"gonio", m.gonio},
            {"chunk", m.chunk},
            {"slurm",
             {{"partition", s.partition},
              {"account", s.account},
              {"time", s.time},
              {"memory", s.memory},
              {"throttle", s.throttle},
              {"cpusPerTask", s.cpusPerTask}}},
            {"tasks", tasks},
            {"merges", merges},
            {"images", images}};
}

// nlohmann's messages name the field's type but not the field: this adds where it was.
template <typename T>
T Field(const json& object, const char* key, const std::string& where) {
    if (!object.is_object() || !object.contains(key))
        throw FarmError(where + ": missing \"" + key + "\"");
    try {
        return object.at(key).get<T>();
    } catch (const json::exception& e) {
        throw FarmError(where + ": \"" + key + "\": " + e.what());
    }
}

TaskKind KindOf(const std::string& name, const std::string& where) {
    for (TaskKind kind : kKinds)
        if (name == TaskKindName(kind)) return kind;
    throw FarmError(where + ": unknown task kind \"" + name + "\" (shard, frame or tile)");
}

// Task indices of a merge or an image must name tasks of the right kind.
void CheckIndices(const std::vector<int>& indices, const std::vector<FarmTask>& tasks,
                  TaskKind kind, const std::string& where) {
    for (int i : indices) {
        if (i < 0 || i >= int(tasks.size()) || tasks[i].kind != kind)
            throw FarmError(where + ": task " + std::to_string(i) + " is not a " +
                            TaskKindName(kind) + " task of this manifest");
    }
}

FarmManifest FromJson(const json& j) {
    FarmManifest m;
    const int version = Field<int>(j, "version", "the manifest");
    if (version != kManifestVersion)
        throw FarmError("version " + std::to_string(version) + ", this gonio reads version " +
                        std::to_string(kManifestVersion));
    m.scene = Field<std::string>(j, "scene", "the manifest");
    m.gonio = Field<std::string>(j, "gonio", "the manifest");
    m.chunk = Field<int>(j, "chunk", "the manifest");
    if (m.chunk < 1) throw FarmError("chunk must be at least 1");
    const json slurm = Field<json>(j, "slurm", "the manifest");
    m.slurm.partition = Field<std::string>(slurm, "partition", "slurm");
    m.slurm.account = Field<std::string>(slurm, "account", "slurm");
    m.slurm.time = Field<std::string>(slurm, "time", "slurm");
    m.slurm.memory = Field<std::string>(slurm, "memory", "slurm");
    m.slurm.throttle = Field<int>(slurm, "throttle", "slurm");
    m.slurm.cpusPerTask = Field<int>(slurm, "cpusPerTask", "slurm");
    const json tasks = Field<json>(j, "tasks", "the manifest");
    for (size_t i = 0; i < tasks.size(); ++i) {
        const std::string where = "task " + std::to_string(i);
        FarmTask t;
        t.kind = KindOf(Field<std::string>(tasks[i], "kind", where), where);
        t.name = Field<std::string>(tasks[i], "name", where);
        t.output = Field<std::string>(tasks[i], "output", where);
        t.args = Field<std::vector<std::string>>(tasks[i], "args", where);
        t.frame = Field<int>(tasks[i], "frame", where);
        if (t.kind == TaskKind::kShard) t.paths = Field<uint64_t>(tasks[i], "paths", where);
        t.retries = Field<int>(tasks[i], "retries", where);
        if (t.retries < 0) throw FarmError(where + ": retries must be at least 0");
        if (t.output.empty() || t.args.empty()) throw FarmError(where + ": no output or no args");
        m.tasks.push_back(t);
    }
    for (const json& g : Field<json>(j, "merges", "the manifest")) {
        FarmMerge merge;
        merge.frame = Field<int>(g, "frame", "a merge");
        merge.output = Field<std::string>(g, "output", "a merge");
        merge.shards = Field<std::vector<int>>(g, "shards", "a merge");
        merge.brdf = Field<std::vector<std::string>>(g, "brdf", "a merge");
        merge.brdfOutput = Field<std::string>(g, "brdfOutput", "a merge");
        CheckIndices(merge.shards, m.tasks, TaskKind::kShard, "the merge into " + merge.output);
        m.merges.push_back(merge);
    }
    for (const json& i : Field<json>(j, "images", "the manifest")) {
        FarmImage image;
        image.frame = Field<int>(i, "frame", "an image");
        image.output = Field<std::string>(i, "output", "an image");
        image.tiles = Field<std::vector<int>>(i, "tiles", "an image");
        CheckIndices(image.tiles, m.tasks, TaskKind::kTile, "the image " + image.output);
        m.images.push_back(image);
    }
    if (m.tasks.empty()) throw FarmError("the manifest has no tasks");
    return m;
}

}  // namespace

const char* TaskKindName(TaskKind kind) {
    switch (kind) {
        case TaskKind::kShard:
            return "shard";
        case TaskKind::kFrame:
            return "frame";
        case TaskKind::kTile:
            return "tile";
    }
    return "?";
}

std::string ManifestPath(const std::string& jobDir) {
    return (std::filesystem::path(jobDir) / kManifestName).string();
}

std::string JobPath(const std::string& jobDir, const std::string& relative) {
    return (std::filesystem::path(jobDir) / relative).string();
}

void WriteManifest(const std::string& jobDir, const FarmManifest& manifest) {
    const std::string path = ManifestPath(jobDir);
    const std::string error = WriteFileAtomically(path, ToJson(manifest).dump(2) + "\n");
    if (!error.empty()) throw FarmError(path + ": error: cannot write it: " + error);
}

FarmManifest ReadManifest(const std::string& jobDir) {
    const std::string path = ManifestPath(jobDir);
    std::ifstream in(path);
    if (!in)
        throw FarmError(path + ": error: cannot read the manifest (is " + jobDir +
                        " a job folder made by gonio farm plan?)");
    std::stringstream text;
    text << in.rdbuf();
    try {
        return FromJson(json::parse(text.str()));
    } catch (const json::parse_error& e) {
        throw FarmError(path + ": error: not valid JSON: " + e.what());
    } catch (const FarmError& e) {
        throw FarmError(path + ": error: " + e.what());
    }
}

}  // namespace gonio
