// gonio farm plan | task | assemble | submit | status: BRDFLight shards, frames and image tiles
// as Slurm job arrays (farm/, docs/farm.md).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>

#include "commands.h"
#include "farm/assemble.h"
#include "farm/job_status.h"
#include "farm/local_backend.h"
#include "farm/planner.h"
#include "farm/slurm.h"
#include "farm/task_runner.h"
#include "frame_range.h"
#include "renderer/photon/brdflight_options.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_file.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

struct PlanOptions {
    std::string scene, jobDir, frames, tiles, brdf;
    PlanRequest request;
};

// Runs a farm command, turning a FarmError (which names its file) into exit status 1.
int Guarded(const std::function<int()>& body) {
    try {
        return body();
    } catch (const FarmError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}

// The frames of the scene that the job renders, as the planner needs them.
bool ReadSceneFrames(const std::string& scene, const FrameRange& range,
                     std::vector<SceneFrame>* frames) {
    Diagnostics diagnostics;
    BuildScene(
        scene, [&](RiTarget& target, Diagnostics& d) { ParseRibFile(scene, target, d); },
        diagnostics,
        [&](const Frame& frame) {
            if (!range.Contains(frame.number)) return;
            SceneFrame f;
            f.number = frame.number;
            f.brdfLight = IsBrdfLightFrame(frame);
            BrdfLightOptions brdfLight;
            if (f.brdfLight && ReadBrdfLightOptions(frame, diagnostics, &brdfLight)) {
                f.rays = uint64_t(brdfLight.rays);
                f.fileName = brdfLight.textureName;
            } else if (!frame.options.displays.empty()) {
                f.fileName = frame.options.displays.front().name;
            }
            frames->push_back(f);
        });
    return diagnostics.ErrorCount() == 0;
}

// "CxR" into the request; false when malformed.
bool ParseTiles(const std::string& text, PlanRequest* request) {
    char x = 0, rest = 0;
    return text.empty() || (std::sscanf(text.c_str(), "%d%c%d%c", &request->tileColumns, &x,
                                        &request->tileRows, &rest) == 3 &&
                            (x == 'x' || x == 'X'));
}

int RunPlan(PlanOptions& o) {
    FrameRange range;
    const std::string rangeError = o.frames.empty() ? "" : ParseFrameRange(o.frames, &range);
    if (!rangeError.empty() || !ParseTiles(o.tiles, &o.request)) {
        std::fprintf(stderr, "gonio farm plan: %s\n",
                     rangeError.empty() ? "--tiles expects CxR, e.g. 4x4" : rangeError.c_str());
        return 2;
    }
    if (!fs::is_regular_file(o.scene)) {
        std::fprintf(stderr, "gonio farm plan: cannot open scene file '%s'\n", o.scene.c_str());
        return 2;
    }
    if (fs::exists(ManifestPath(o.jobDir))) {
        std::fprintf(stderr,
                     "gonio farm plan: %s already holds a job (%s): its outputs would be taken "
                     "for this one's; choose a new folder or remove it\n",
                     o.jobDir.c_str(), kManifestName);
        return 2;
    }
    std::vector<SceneFrame> frames;
    if (!ReadSceneFrames(o.scene, range, &frames)) return 1;
    std::istringstream brdf(o.brdf);
    for (std::string word; brdf >> word;) o.request.brdf.push_back(word);
    o.request.scene = fs::absolute(o.scene).lexically_normal().string();
    o.request.gonio = fs::read_symlink("/proc/self/exe").string();
    return Guarded([&] {
        const FarmManifest manifest = PlanJob(o.request, frames);
        std::error_code error;
        fs::create_directories(o.jobDir, error);
        WriteManifest(o.jobDir, manifest);
        WriteSlurmScripts(o.jobDir, manifest);
        std::printf("%s: %zu tasks as %d array tasks (%zu merged maps, %zu joined images)\n",
                    ManifestPath(o.jobDir).c_str(), manifest.tasks.size(), manifest.ArrayTasks(),
                    manifest.merges.size(), manifest.images.size());
        return 0;
    });
}

// Render threads of a task: --threads, else Slurm's CPUs for the task, else all cores.
int TaskThreads(int threads) {
    if (threads > 0) return threads;
    const char* cpus = std::getenv("SLURM_CPUS_PER_TASK");
    return cpus ? std::max(0, std::atoi(cpus)) : 0;
}

void AddPlan(CLI::App& farm, int* exitCode) {
    auto o = std::make_shared<PlanOptions>();
    PlanRequest& r = o->request;
    CLI::App* cmd = farm.add_subcommand("plan",
                                        "Cut a scene into farm tasks: JOBDIR/manifest.json "
                                        "and the Slurm batch scripts");
    cmd->add_option("scene", o->scene, "RIB file")->required();
    cmd->add_option("-o,--output", o->jobDir, "The job folder (new)")->required();
    cmd->add_option("--photon-shards", r.photonShards,
                    "Cut each BRDFLight frame's paths into N shards");
    cmd->add_option("--frames", o->frames, "Only the frames A-B (FrameBegin numbers) or A");
    cmd->add_option("--tiles", o->tiles, "Render each image frame as CxR tiles, e.g. 4x4");
    cmd->add_option("--chunk", r.chunk, "Tasks per Slurm array task (default 1)");
    cmd->add_option("--retries", r.retries, "Attempts after the first, inside a task (default 2)");
    cmd->add_option("--seed", r.seed, "gonio render --seed of every task (default 0)");
    cmd->add_option("--brdf", o->brdf,
                    "Reduce each merged map with this gonio brdf tool, e.g. \"iopt 8 24 0.5 0\"");
    cmd->add_option("--partition", r.slurm.partition, "Slurm partition");
    cmd->add_option("--account", r.slurm.account, "Slurm account");
    cmd->add_option("--throttle", r.slurm.throttle, "Array tasks at once (--array=0-N%M)");
    cmd->add_option("--cpus-per-task", r.slurm.cpusPerTask, "Slurm CPUs (render threads) per task")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--time", r.slurm.time, "Slurm time limit per array task, e.g. 2:00:00");
    cmd->add_option("--mem", r.slurm.memory, "Slurm memory per array task, e.g. 8G");
    cmd->callback([o, exitCode] { *exitCode = RunPlan(*o); });
}

void AddTask(CLI::App& farm, int* exitCode) {
    auto jobDir = std::make_shared<std::string>();
    auto index = std::make_shared<int>(0);
    auto threads = std::make_shared<int>(0);
    CLI::App* cmd = farm.add_subcommand("task", "Run one array task of a job (what Slurm runs)");
    cmd->add_option("jobdir", *jobDir, "The job folder")->required();
    cmd->add_option("index", *index, "The array index ($SLURM_ARRAY_TASK_ID)")->required();
    cmd->add_option("--threads", *threads,
                    "Render threads (default $SLURM_CPUS_PER_TASK, else all cores)");
    cmd->callback([=] {
        *exitCode = Guarded([&] {
            const FarmManifest manifest = ReadManifest(*jobDir);
            return RunArrayTask(*jobDir, manifest, *index, TaskThreads(*threads), stderr) == 0 ? 0
                                                                                               : 1;
        });
    });
}

void AddAssemble(CLI::App& farm, int* exitCode) {
    auto jobDir = std::make_shared<std::string>();
    CLI::App* cmd = farm.add_subcommand(
        "assemble", "Check every task's output, merge the shards, join the tiles");
    cmd->add_option("jobdir", *jobDir, "The job folder")->required();
    cmd->callback([=] {
        *exitCode = Guarded([&] { return AssembleJob(*jobDir, ReadManifest(*jobDir), stderr); });
    });
}

void AddSubmit(CLI::App& farm, int* exitCode) {
    auto jobDir = std::make_shared<std::string>();
    auto backend = std::make_shared<std::string>("slurm");
    auto jobs = std::make_shared<int>(0);
    CLI::App* cmd = farm.add_subcommand(
        "submit", "Submit a job to Slurm (sbatch), or run it here with --backend local");
    cmd->add_option("jobdir", *jobDir, "The job folder")->required();
    cmd->add_option("--backend", *backend, "slurm (default) or local")
        ->check(CLI::IsMember({"slurm", "local"}));
    cmd->add_option("--jobs", *jobs,
                    "local: array tasks at once (default: the plan's --throttle, else 1)");
    cmd->callback([=] {
        *exitCode = Guarded([&] {
            const FarmManifest manifest = ReadManifest(*jobDir);
            RemoveAssembledOutputs(*jobDir, manifest);
            if (*backend == "local")
                return RunLocally(*jobDir, manifest,
                                  *jobs > 0 ? *jobs : std::max(1, manifest.slurm.throttle), stderr);
            const SubmittedJobs submitted = SubmitToSlurm(*jobDir);
            std::printf("submitted %d array tasks as Slurm job %s, assemble as job %s\n",
                        manifest.ArrayTasks(), submitted.tasks.c_str(), submitted.assemble.c_str());
            return 0;
        });
    });
}

void AddStatus(CLI::App& farm, int* exitCode) {
    auto jobDir = std::make_shared<std::string>();
    CLI::App* cmd = farm.add_subcommand("status", "A job's progress: outputs done, Slurm states");
    cmd->add_option("jobdir", *jobDir, "The job folder")->required();
    cmd->callback([=] {
        *exitCode = Guarded([&] {
            std::printf("%s\n", StatusLine(*jobDir, ReadManifest(*jobDir)).c_str());
            return 0;
        });
    });
}

}  // namespace

void AddFarmCommand(CLI::App& app, int* exitCode) {
    CLI::App* farm = app.add_subcommand(
        "farm",
        "BRDFLight shards, frames and image tiles as Slurm job arrays: plan, task, "
        "assemble, submit, status");
    farm->require_subcommand(1);
    AddPlan(*farm, exitCode);
    AddTask(*farm, exitCode);
    AddAssemble(*farm, exitCode);
    AddSubmit(*farm, exitCode);
    AddStatus(*farm, exitCode);
}

}  // namespace gonio
