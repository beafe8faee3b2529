// What the built-in drivers share with OpenImageIO's conventions.
#include <cctype>
#include <cstdlib>
#include <ctime>

#include "imageio/builtin_drivers.h"

namespace gonio {

std::string CurrentDateTime() {
    // SOURCE_DATE_EPOCH (reproducible-builds.org's convention, in UTC) fixes the stamp, so that
    // two renders of a scene give byte-identical TIFF and OpenEXR files.
    std::tm time{};
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch && *epoch) {
        const std::time_t fixed = std::strtoll(epoch, nullptr, 10);
        gmtime_r(&fixed, &time);
    } else {
        const std::time_t now = std::time(nullptr);
        localtime_r(&now, &time);
    }
    char text[32];
    std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &time);
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
