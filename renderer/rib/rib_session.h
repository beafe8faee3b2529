#pragma once
// What the parsers of one ParseRib* call share: the target, the diagnostics, the include stack
// of ReadArchive with its cycle check, the archive search path taken from `Option "searchpath"
// "archive"`, and the number of colour components set by ColorSamples.

#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "renderer/rib/request_table.h"
#include "renderer/rib/ri_target.h"

namespace gonio {

class RibSession : public ParserHooks {
  public:
    RibSession(RiTarget& target, Diagnostics& diagnostics)
        : target_(target), diagnostics_(diagnostics) {}

    bool ParseFile(const std::string& path);
    bool ParseString(const std::string& text, const std::string& name);

    RiTarget& Target() { return target_; }
    int ColorComponents() const { return ncomps_; }
    void Error(const FileLoc& loc, const std::string& message);
    bool Stopped() const { return stopped_; }

    void ReadArchive(const std::string& name, const FileLoc& loc) override;
    void Procedural(const std::string& name, const std::vector<std::string>& args,
                    const std::vector<float>& bound6, const FileLoc& loc) override;
    // What ProceduralReader::Read does for the session's procedurals (rib_procedurals.cpp).
    void ReadProcedural(const std::string& name, const std::vector<std::string>& args, float detail,
                        double timeoutSeconds, const FileLoc& loc);
    void OptionSeen(const std::string& name, const ParamList& params) override;
    void ColorSamplesSeen(int ncomps) override;
    void Ignore(const char* request, const FileLoc& loc) override;
    void Unsupported(const char* request, const FileLoc& loc) override;

  private:
    struct Input {
        std::string path;       // as shown in messages; archives resolve against its folder
        std::string canonical;  // for the cycle check; empty for standard input
    };
    bool FindArchive(const std::string& name, const std::string& includingPath, std::string* found,
                     std::string* searched) const;
    bool CheckDepth(const std::string& next, const FileLoc& loc);
    void RunProgram(const std::vector<std::string>& args, float detail, double timeoutSeconds,
                    const FileLoc& loc);
    // The program of a RunProgram command, found next to the including file when it is there.
    std::string ResolveProgram(const std::string& command) const;
    std::string Chain(const std::string& last) const;

    RiTarget& target_;
    Diagnostics& diagnostics_;
    std::vector<Input> inputs_;
    std::vector<std::string> archivePath_;
    int ncomps_ = 3;
    int errors_ = 0;
    bool stopped_ = false;
};

}  // namespace gonio
