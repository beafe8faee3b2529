// The procedurals of RISpec 3.2 §5.7 as the parser offers them to its target: the target calls
// ProceduralReader::Read when it wants the RIB (SceneBuilder: when the bound can be seen), and
// the session reads it in place, through the same include stack as ReadArchive, so that nested
// procedurals and archives share one depth limit and one cycle check.

#include <cstdio>
#include <filesystem>
#include <memory>

#include "renderer/rib/procedural_program.h"
#include "renderer/rib/rib_file_parser.h"
#include "renderer/rib/rib_session.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

class SessionProcedural final : public ProceduralReader {
  public:
    SessionProcedural(RibSession& session, const std::string& name,
                      const std::vector<std::string>& args, const FileLoc& loc)
        : session_(session), name_(name), args_(args), loc_(loc) {}
    void Read(float detail, double timeoutSeconds) override {
        session_.ReadProcedural(name_, args_, detail, timeoutSeconds, loc_);
    }

  private:
    RibSession& session_;
    const std::string& name_;
    const std::vector<std::string>& args_;
    const FileLoc& loc_;
};

// RISpec App. C.3: the request a RunProgram program reads, "detail datablock\n".
std::string ProgramRequest(float detail, const std::string& data) {
    char number[32];
    std::snprintf(number, sizeof number, "%g", static_cast<double>(detail));
    return std::string(number) + " " + data + "\n";
}

}  // namespace

void RibSession::Procedural(const std::string& name, const std::vector<std::string>& args,
                            const std::vector<float>& bound6, const FileLoc& loc) {
    SessionProcedural reader(*this, name, args, loc);
    target_.Procedural(name, args, bound6, reader, loc);
}

void RibSession::ReadProcedural(const std::string& name, const std::vector<std::string>& args,
                                float detail, double timeoutSeconds, const FileLoc& loc) {
    if (name == "DelayedReadArchive") {
        if (args.size() != 1)
            return Error(loc,
                         "Procedural \"DelayedReadArchive\" takes one argument, the archive "
                         "to read, got " +
                             std::to_string(args.size()));
        return ReadArchive(args[0], loc);
    }
    if (name == "RunProgram") {
        if (args.size() != 2)
            return Error(loc,
                         "Procedural \"RunProgram\" takes two arguments, the program and "
                         "its data, got " +
                             std::to_string(args.size()));
        return RunProgram(args, detail, timeoutSeconds, loc);
    }
    if (name == "DynamicLoad")
        return Error(loc,
                     "Procedural \"DynamicLoad\" is not supported: gonio has no C "
                     "RenderMan Interface (RiSphere, ...) for a plug-in's Subdivide to "
                     "call; a RunProgram program that writes RIB does the same work");
    Error(loc, "unknown procedural \"" + name +
                   "\" (known: DelayedReadArchive, RunProgram, DynamicLoad)");
}

std::string RibSession::ResolveProgram(const std::string& command) const {
    const std::size_t end = command.find_first_of(" \t");
    const std::string program = command.substr(0, end);
    if (program.empty() || program.find('/') != std::string::npos) return command;
    const fs::path folder = fs::path(inputs_.back().path).parent_path();
    std::error_code error;
    const fs::path beside = (folder.empty() ? fs::path(".") : folder) / program;
    if (!fs::is_regular_file(beside, error)) return command;  // left to the PATH
    return beside.string() + (end == std::string::npos ? "" : command.substr(end));
}

void RibSession::RunProgram(const std::vector<std::string>& args, float detail,
                            double timeoutSeconds, const FileLoc& loc) {
    const std::string& command = args[0];
    const std::string shown = "RunProgram \"" + command + "\"";
    if (!CheckDepth(shown, loc)) return;
    const ProgramRun run = RunProceduralProgram(ResolveProgram(command),
                                                ProgramRequest(detail, args[1]), timeoutSeconds);
    if (!run.ok) return Error(loc, "Procedural " + shown + " " + run.error);
    // The answer's archives resolve against the including file's folder; it has no cycle check
    // of its own (a program may run itself), only the depth limit.
    inputs_.push_back({inputs_.back().path, ""});
    const int errorsBefore = errors_;
    RibFileParser(*this, std::make_shared<const std::string>("<" + shown + " output>"), run.rib)
        .Parse();
    inputs_.pop_back();
    if (errors_ > errorsBefore) Error(loc, "Procedural " + shown + " wrote bad RIB (see above)");
}

}  // namespace gonio
