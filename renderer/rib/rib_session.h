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
