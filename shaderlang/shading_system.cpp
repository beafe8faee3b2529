// ShadingSystem: NAME.sl on the search path, compiled once per run.

#include "shaderlang/shading_system.h"

#include "base/search_path.h"
#include "shaderlang/compiler/preprocessor.h"

namespace gonio::sl {

ShadingSystem::ShadingSystem(Diagnostics& diagnostics, int colorComponents)
    : diagnostics_(diagnostics), colorComponents_(colorComponents) {}

void ShadingSystem::SetSearchPath(const std::string& path) {
    std::lock_guard<std::mutex> lock(mutex_);
    searchPath_ = ExpandSearchPath(path, searchPath_, {});
}

void ShadingSystem::SetSearchPath(std::vector<std::string> folders) {
    std::lock_guard<std::mutex> lock(mutex_);
    searchPath_ = std::move(folders);
}

std::shared_ptr<const Shader> ShadingSystem::Load(const std::string& name, const FileLoc& where) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto cached = cache_.find(name);
    if (cached != cache_.end()) return cached->second;
    const bool hasSuffix = name.size() > 3 && name.compare(name.size() - 3, 3, ".sl") == 0;
    const std::string file = hasSuffix ? name : name + ".sl";
    std::string source;
    std::string found = FindOnSearchPath(file, searchPath_);
    if (!found.empty() && !ReadTextFile(found, &source)) found.clear();
    std::shared_ptr<const Shader> shader;
    if (found.empty()) {
        std::string dirs;
        for (const std::string& d : searchPath_) dirs += (dirs.empty() ? "" : ", ") + d;
        diagnostics_.Error(
            where, "cannot find shader '" + name + "' (looked for " + file + " in " + dirs + ")");
    } else {
        CompileOptions options;
        options.includeDirs = searchPath_;
        options.colorComponents = colorComponents_;
        shader = CompileShaderSource(source, found, options, diagnostics_);
        if (!shader) diagnostics_.Note(where, "shader '" + name + "' failed to compile");
    }
    cache_[name] = shader;
    return shader;
}

}  // namespace gonio::sl
