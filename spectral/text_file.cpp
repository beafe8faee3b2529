#include "spectral/text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "base/atomic_file.h"
#include "spectral/spectral_error.h"

namespace gonio::spectral {

std::vector<std::string> ReadTextLines(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        FailAt(path, 0, "cannot read it: it is a directory");
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) FailAt(path, 0, std::string("cannot read it: ") + std::strerror(errno));
    std::string text;
    char buffer[1 << 14];
    size_t got;
    while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, got);
    const bool failed = std::ferror(file);
    std::fclose(file);
    if (failed) FailAt(path, 0, "cannot read it: read error");
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

void WriteTextFileAtomically(const std::string& path, const std::string& text) {
    const std::string error = WriteFileAtomically(path, text);
    if (!error.empty()) FailAt(path, 0, "cannot write it: " + error);
}

}  // namespace gonio::spectral
