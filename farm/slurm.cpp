#include "farm/slurm.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/atomic_file.h"
#include "farm/process.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

// Single quotes for bash: nothing inside them is special but the quote itself.
std::string Quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string Header(const FarmManifest& m, const std::string& jobDir, const std::string& name,
                   const std::string& log) {
    const SlurmSettings& s = m.slurm;
    std::string text =
        "#!/bin/bash\n# Written by gonio farm plan; submit with gonio farm submit.\n";
    text += "#SBATCH --job-name=" + name + "\n";
    text += "#SBATCH --output=" + JobPath(fs::absolute(jobDir).string(), log) + "\n";
    text += "#SBATCH --cpus-per-task=" + std::to_string(s.cpusPerTask) + "\n";
    if (!s.partition.empty()) text += "#SBATCH --partition=" + s.partition + "\n";
    if (!s.account.empty()) text += "#SBATCH --account=" + s.account + "\n";
    if (!s.time.empty()) text += "#SBATCH --time=" + s.time + "\n";
    if (!s.memory.empty()) text += "#SBATCH --mem=" + s.memory + "\n";
    return text;
}

void WriteScript(const std::string& path, const std::string& text) {
    const std::string error = WriteFileAtomically(path, text);
    if (!error.empty()) throw FarmError(path + ": error: cannot write it: " + error);
    fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
}

// The job id of `sbatch --parsable` ("123" or "123;cluster").
std::string Sbatch(const std::vector<std::string>& argv) {
    std::string output;
    const ChildStatus status = RunCapturing(argv, &output);
    const std::string id = output.substr(0, output.find_first_of(";\n"));
    if (!status.Ok() || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw FarmError("sbatch " + argv.back() + ": " + status.Describe() +
                        (output.empty() ? "" : ": " + output));
    return id;
}

}  // namespace

void WriteSlurmScripts(const std::string& jobDir, const FarmManifest& m) {
    std::error_code error;
    fs::create_directories(JobPath(jobDir, "slurm"), error);
    fs::create_directories(JobPath(jobDir, "logs"), error);
    const std::string dir = fs::absolute(jobDir).string();
    const std::string array = "0-" + std::to_string(m.ArrayTasks() - 1) +
                              (m.slurm.throttle > 0 ? "%" + std::to_string(m.slurm.throttle) : "");
    WriteScript(JobPath(jobDir, kTasksScript),
                Header(m, jobDir, "gonio-tasks", "logs/task_%a.out") + "#SBATCH --array=" + array +
                    "\n\nexec " + Quoted(m.gonio) + " farm task " + Quoted(dir) +
                    " \"$SLURM_ARRAY_TASK_ID\"\n");
    WriteScript(JobPath(jobDir, kAssembleScript),
                Header(m, jobDir, "gonio-assemble", "logs/assemble.out") + "\nexec " +
                    Quoted(m.gonio) + " farm assemble " + Quoted(dir) + "\n");
}

SubmittedJobs SubmitToSlurm(const std::string& jobDir) {
    if (!OnPath("sbatch"))
        throw FarmError(
            "gonio farm submit: sbatch is not on PATH (is this a Slurm submit "
            "host?); --backend local runs the job on this machine");
    SubmittedJobs jobs;
    jobs.tasks = Sbatch({"sbatch", "--parsable", JobPath(jobDir, kTasksScript)});
    jobs.assemble = Sbatch({"sbatch", "--parsable", "--dependency=afterok:" + jobs.tasks,
                            JobPath(jobDir, kAssembleScript)});
    const std::string path = JobPath(jobDir, kSubmittedFile);
    const std::string error = WriteFileAtomically(path, jobs.tasks + " " + jobs.assemble + "\n");
    if (!error.empty()) throw FarmError(path + ": error: cannot write it: " + error);
    return jobs;
}

SubmittedJobs ReadSubmitted(const std::string& jobDir) {
    SubmittedJobs jobs;
    std::ifstream in(JobPath(jobDir, kSubmittedFile));
    in >> jobs.tasks >> jobs.assemble;
    return in ? jobs : SubmittedJobs{};
}

QueueState QueryQueue(const SubmittedJobs& jobs) {
    QueueState state;
    std::string output;
    // -r: one line per array task, pending ones too.
    const ChildStatus status = RunCapturing(
        {"squeue", "-h", "-r", "-j", jobs.tasks + "," + jobs.assemble, "-o", "%F %T"}, &output);
    if (!status.Ok()) return state;  // squeue refuses ids that have all left the queue
    std::istringstream lines(output);
    std::string job, slurmState;
    while (lines >> job >> slurmState) {
        if (job == jobs.assemble)
            state.assemble = slurmState;
        else
            ++state.tasks[slurmState];
    }
    return state;
}

}  // namespace gonio
