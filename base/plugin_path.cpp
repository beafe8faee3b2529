#include "base/plugin_path.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>

namespace gonio {

std::string PluginPath(const char* override, const char* file) {
    if (const char* path = std::getenv(override); path && *path) return path;
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return (error ? std::filesystem::path(file) : exe.parent_path() / file).string();
}

void* OpenPluginEntry(const char* override, const char* file, const char* entry,
                      std::string* error) {
    const std::string path = PluginPath(override, file);
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        *error = dlerror();
        return nullptr;
    }
    void* symbol = dlsym(handle, entry);
    if (!symbol) *error = path + ": no " + entry + " in it";
    return symbol;
}

}  // namespace gonio
