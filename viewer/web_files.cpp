#include "viewer/web_files.h"

namespace gonio::viewer {

std::string_view ContentType(std::string_view path) {
    auto endsWith = [&](std::string_view suffix) {
        return path.size() >= suffix.size() && path.substr(path.size() - suffix.size()) == suffix;
    };
    if (endsWith(".html")) return "text/html; charset=utf-8";
    if (endsWith(".mjs") || endsWith(".js")) return "text/javascript; charset=utf-8";
    if (endsWith(".css")) return "text/css; charset=utf-8";
    return "application/octet-stream";
}

}  // namespace gonio::viewer
