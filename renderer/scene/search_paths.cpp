#include "renderer/scene/search_paths.h"

#include <filesystem>

#include "base/search_path.h"

namespace gonio {

std::string SceneFolder(const std::string& sceneFile) {
    const std::string folder = std::filesystem::path(sceneFile).parent_path().string();
    return folder.empty() ? "." : folder;
}

std::vector<std::string> OptionSearchPath(const Options& options, const std::string& kind,
                                          const std::vector<std::string>& standard) {
    auto it = options.user.find("searchpath");
    if (it == options.user.end() || !it->second.Has(kind)) return standard;
    return ExpandSearchPath(it->second.GetString(kind, ""), standard, standard);
}

std::vector<std::string> TextureSearchPath(const Options& options, const std::string& sceneFile) {
    return OptionSearchPath(options, "texture", {".", SceneFolder(sceneFile)});
}

}  // namespace gonio
