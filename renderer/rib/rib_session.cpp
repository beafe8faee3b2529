// Opening RIB inputs (files, gzip files, standard input, strings), following ReadArchive with
// its search path and cycle check, and the error budget of one parse.

#include "renderer/rib/rib_session.h"

#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>

#include "base/search_path.h"
#include "renderer/rib/declarations.h"
#include "renderer/rib/rib_file_parser.h"
#include "renderer/rib/rib_parser.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

// Past this many errors the rest of the input is skipped: a binary or badly broken file would
// otherwise bury the first, useful messages.
constexpr int kMaxErrors = 100;
// Deeper ReadArchive nesting than this is almost surely a runaway chain of generated files.
constexpr std::size_t kMaxArchiveDepth = 64;
// Smaller than the lexer's reads, so that zlib reads plain files straight into the lexer's buffer.
constexpr unsigned kGzipBufferSize = 1 << 16;

std::string Canonical(const std::string& path) {
    std::error_code error;
    const fs::path canonical = fs::weakly_canonical(path, error);
    return error ? fs::path(path).lexically_normal().string() : canonical.string();
}

bool IsRegularFile(const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error);
}

// The folder archives named in `path` are resolved against ("." for standard input).
fs::path FolderOf(const std::string& path) {
    const fs::path folder = fs::path(path).parent_path();
    return folder.empty() ? fs::path(".") : folder;
}

std::string ShortPath(const fs::path& path) {
    std::string text = path.lexically_normal().string();
    return text.rfind("./", 0) == 0 ? text.substr(2) : text;
}

}  // namespace

void RibSession::Error(const FileLoc& loc, const std::string& message) {
    if (stopped_) return;
    diagnostics_.Error(loc, message);
    if (++errors_ >= kMaxErrors) {
        diagnostics_.Note(loc, "too many errors; the rest of the input is skipped");
        stopped_ = true;
    }
}

bool RibSession::ParseFile(const std::string& path) {
    const bool isStdin = path == "-";
    gzFile input = isStdin ? gzdopen(dup(0), "rb") : gzopen(path.c_str(), "rb");
    const auto name = std::make_shared<const std::string>(isStdin ? "<stdin>" : path);
    if (!input) {
        Error(FileLoc{name, 0, 0}, std::string("cannot open the file: ") + std::strerror(errno));
        return false;
    }
    gzbuffer(input, kGzipBufferSize);
    inputs_.push_back({isStdin ? std::string() : path, isStdin ? "" : Canonical(path)});
    RibFileParser(*this, name, input).Parse();
    inputs_.pop_back();
    gzclose(input);
    return errors_ == 0;
}

bool RibSession::ParseString(const std::string& text, const std::string& name) {
    inputs_.push_back({name, name.empty() ? "" : Canonical(name)});
    RibFileParser(*this, std::make_shared<const std::string>(name), text).Parse();
    inputs_.pop_back();
    return errors_ == 0;
}

bool RibSession::FindArchive(const std::string& name, const std::string& includingPath,
                             std::string* found, std::string* searched) const {
    std::vector<fs::path> candidates;
    if (fs::path(name).is_absolute()) {
        candidates.push_back(name);
    } else {
        candidates.push_back(FolderOf(includingPath) / name);
        for (const std::string& folder : archivePath_)
            candidates.push_back(fs::path(folder) / name);
    }
    for (const fs::path& candidate : candidates) {
        if (IsRegularFile(candidate)) {
            *found = ShortPath(candidate);
            return true;
        }
        if (!searched->empty()) *searched += ", ";
        *searched += ShortPath(candidate);
    }
    return false;
}

std::string RibSession::Chain(const std::string& last) const {
    std::string chain;
    for (const Input& input : inputs_)
        chain += (input.path.empty() ? "<stdin>" : input.path) + " -> ";
    return chain + last;
}

bool RibSession::CheckDepth(const std::string& next, const FileLoc& loc) {
    if (inputs_.size() < kMaxArchiveDepth) return true;
    Error(loc, "ReadArchive and procedurals nested more than " + std::to_string(kMaxArchiveDepth) +
                   " inputs deep: " + Chain(next));
    return false;
}

void RibSession::ReadArchive(const std::string& name, const FileLoc& loc) {
    if (!CheckDepth(name, loc)) return;
    std::string path, searched;
    if (!FindArchive(name, inputs_.back().path, &path, &searched)) {
        Error(loc, "cannot find archive \"" + name + "\" (looked for " + searched + ")");
        return;
    }
    const std::string canonical = Canonical(path);
    for (const Input& input : inputs_) {
        if (input.canonical == canonical) {
            Error(loc, "ReadArchive cycle: " + Chain(path));
            return;
        }
    }
    gzFile input = gzopen(path.c_str(), "rb");
    if (!input) {
        Error(loc, "cannot open archive \"" + path + "\": " + std::strerror(errno));
        return;
    }
    gzbuffer(input, kGzipBufferSize);
    inputs_.push_back({path, canonical});
    RibFileParser(*this, std::make_shared<const std::string>(path), input).Parse();
    inputs_.pop_back();
    gzclose(input);
}

// `Option "searchpath" "archive" "a:b:&"`: '&' stands for the previous path, '@' for the default
// (empty: archives are looked for next to the including file first in any case).
void RibSession::OptionSeen(const std::string& name, const ParamList& params) {
    if (name != "searchpath") return;
    for (const Param& param : params) {
        if (TokenName(param.token) != "archive" || !param.isString || param.strings.empty())
            continue;
        archivePath_ = ExpandSearchPath(param.strings[0], archivePath_, {});
    }
}

void RibSession::ColorSamplesSeen(int ncomps) {
    if (ncomps >= 1) ncomps_ = ncomps;
}

void RibSession::Ignore(const char* request, const FileLoc& loc) {
    diagnostics_.WarningOnce(std::string("rib-ignored:") + request, loc,
                             std::string(request) + " is not supported and is ignored");
}

void RibSession::Unsupported(const char* request, const FileLoc& loc) {
    Error(loc, std::string(request) + " is not supported");
}

bool ParseRibFile(const std::string& path, RiTarget& target, Diagnostics& diagnostics) {
    return RibSession(target, diagnostics).ParseFile(path);
}

bool ParseRibString(const std::string& text, const std::string& name, RiTarget& target,
                    Diagnostics& diagnostics) {
    return RibSession(target, diagnostics).ParseString(text, name);
}

}  // namespace gonio
