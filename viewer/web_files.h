#pragma once
// The page's files (viewer/web/), embedded into the binary at build time by
// embed_web_files.cmake, so that `gonio view` needs no install path and serves nothing else.

#include <string_view>

namespace gonio::viewer {

struct WebFile {
    std::string_view path;  // "/index.html", "/editor.mjs", ...
    std::string_view content;
};

// nullptr for a path that is not one of the embedded files.
const WebFile* FindWebFile(std::string_view path);

// The MIME type of a page file by its extension (.html, .mjs, .css).
std::string_view ContentType(std::string_view path);

}  // namespace gonio::viewer
