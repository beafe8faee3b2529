// What the built-in drivers share with OpenImageIO's conventions.
#include <cctype>
#include <cstdlib>
#include <ctime>

#include "imageio/builtin_drivers.h"

namespace gonio {

std::string CurrentDateTime() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
    return text;
}

std::pair<std::string, int> SplitCompression(const std::string& compression) {
    // OpenImageIO compares compression names ignoring case.
    const size_t colon = compression.find(':');
    std::string name = compression.substr(0, colon);
    for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (colon == std::string::npos) return {name, -1};
    return {name, std::atoi(compression.c_str() + colon + 1)};
}

}  // namespace gonio
