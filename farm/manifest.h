#pragma once
// The manifest of a farm job (JOBDIR/manifest.json): what `gonio farm plan` decided and every
// other farm command reads. Each task is one `gonio render` run (a photon shard, a frame or a
// tile of a frame) with its output; the assemble step joins the outputs. Paths of outputs are
// relative to the job folder, so a job folder can be moved (or mounted elsewhere on the nodes)
// as a whole.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace gonio {

// A bad manifest, task output or job folder; what() names the file.
class FarmError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

enum class TaskKind { kShard, kFrame, kTile };

struct FarmTask {
    TaskKind kind = TaskKind::kFrame;
    std::string name;               // for messages: "frame 1 shard 3/16", "frame 2 tile 1,0"
    std::string output;             // relative to the job folder
    std::vector<std::string> args;  // gonio's arguments, without -o and --threads
    int frame = 0;                  // FrameBegin number
    uint64_t paths = 0;             // a shard: the paths its map's header must count
    int retries = 2;                // attempts after the first, inside the task
};

// The shards of one BRDFLight frame, merged into one map (and optionally reduced to a grid).
struct FarmMerge {
    int frame = 0;
    std::string output;             // the merged photon map
    std::vector<int> shards;        // task indices, in path order
    std::vector<std::string> brdf;  // `gonio brdf` tool and arguments ("iopt 8 24 0.5 0"), or {}
    std::string brdfOutput;         // the .grd it writes
};

// The tiles of one frame, joined into its image.
struct FarmImage {
    int frame = 0;
    std::string output;
    std::vector<int> tiles;  // task indices
};

struct SlurmSettings {
    std::string partition, account, time, memory;  // "" leaves each to the cluster's default
    int throttle = 0;                              // array tasks at once (%M); 0: no limit
    int cpusPerTask = 1;
};

struct FarmManifest {
    std::string scene;  // absolute
    std::string gonio;  // the executable that planned the job, absolute
    int chunk = 1;      // tasks per array task
    SlurmSettings slurm;
    std::vector<FarmTask> tasks;
    std::vector<FarmMerge> merges;
    std::vector<FarmImage> images;

    // Slurm array tasks: each runs `chunk` consecutive tasks.
    int ArrayTasks() const { return int((tasks.size() + chunk - 1) / chunk); }
};

inline constexpr const char* kManifestName = "manifest.json";

std::string ManifestPath(const std::string& jobDir);
// An output path of the manifest, resolved against the job folder.
std::string JobPath(const std::string& jobDir, const std::string& relative);

// Writes JOBDIR/manifest.json (temporary name, then rename). Throws FarmError.
void WriteManifest(const std::string& jobDir, const FarmManifest& manifest);
// Reads and checks it; a missing, malformed or inconsistent manifest throws FarmError
// "JOBDIR/manifest.json: error: ...".
FarmManifest ReadManifest(const std::string& jobDir);

const char* TaskKindName(TaskKind kind);

}  // namespace gonio
