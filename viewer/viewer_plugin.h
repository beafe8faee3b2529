#pragma once
// `gonio view` lives in a plugin, libgonio_viewer.so, opened with dlopen by the view command
// only: the viewer serves HTTP through cpp-httplib, whose Debian build brings OpenSSL and
// Brotli, and loading and initialising those cost every other gonio command about a third of
// its start-up. The plugin's one entry point runs RunViewer (viewer_server.h).

#include <cstdio>

#include "viewer/viewer_server.h"

namespace gonio::viewer {

using ViewerPluginEntry = int (*)(const ServerOptions& options, std::FILE* out);
inline constexpr const char* kViewerPluginEntry = "GonioRunViewer";

}  // namespace gonio::viewer
