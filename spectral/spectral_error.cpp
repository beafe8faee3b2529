#include "spectral/spectral_error.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

namespace gonio::spectral {

void FailAt(const FileLoc& loc, const std::string& message) {
    throw SpectralError(loc.ToString() + ": error: " + message);
}

void FailAt(const std::string& file, int line, const std::string& message) {
    FailAt(FileLoc{std::make_shared<const std::string>(file), line, 0}, message);
}

bool ParseNumber(const std::string& token, double* value) {
    if (token.empty()) return false;
    const char* begin = token.c_str();
    char* end = nullptr;
    errno = 0;
    const double parsed = std::strtod(begin, &end);
    if (end != begin + token.size() || errno == ERANGE || !std::isfinite(parsed)) return false;
    *value = parsed;
    return true;
}

std::vector<std::string> SplitBlanks(const std::string& line) {
    std::vector<std::string> tokens;
    size_t i = 0;
    auto blank = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
    };
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        size_t j = i;
        while (j < line.size() && !blank(line[j])) ++j;
        if (j > i) tokens.push_back(line.substr(i, j - i));
        i = j;
    }
    return tokens;
}

}  // namespace gonio::spectral
