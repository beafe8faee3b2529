#include "base/search_path.h"

#include <filesystem>
#include <system_error>

namespace gonio {

std::vector<std::string> ExpandSearchPath(const std::string& text,
                                          const std::vector<std::string>& previous,
                                          const std::vector<std::string>& standard) {
    std::vector<std::string> folders;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(':', start), text.size());
        const std::string entry = text.substr(start, end - start);
        if (entry == "&")
            folders.insert(folders.end(), previous.begin(), previous.end());
        else if (entry == "@")
            folders.insert(folders.end(), standard.begin(), standard.end());
        else if (!entry.empty())
            folders.push_back(entry);
        start = end + 1;
    }
    return folders;
}

std::string SubstitutePreviousPath(const std::string& text, const std::string& previous) {
    std::string result;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(':', start), text.size());
        const std::string entry = text.substr(start, end - start);
        if (!result.empty() || start > 0) result += ':';
        result += entry == "&" ? previous : entry;
        start = end + 1;
    }
    return result;
}

std::string FindOnSearchPath(const std::string& name, const std::vector<std::string>& folders) {
    if (name.empty()) return {};
    std::error_code error;
    if (name[0] == '/') return std::filesystem::is_regular_file(name, error) ? name : std::string();
    for (const std::string& folder : folders) {
        const std::string candidate = folder + "/" + name;
        if (std::filesystem::is_regular_file(candidate, error)) return candidate;
    }
    return {};
}

}  // namespace gonio
