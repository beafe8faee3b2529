#include "base/plugin_path.h"

#include <cstdlib>
#include <filesystem>

namespace gonio {

std::string PluginPath(const char* override, const char* file) {
    if (const char* path = std::getenv(override); path && *path) return path;
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return (error ? std::filesystem::path(file) : exe.parent_path() / file).string();
}

}  // namespace gonio
