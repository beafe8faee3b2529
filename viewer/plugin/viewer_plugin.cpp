// The viewer plugin's entry point (viewer/viewer_plugin.h says why the viewer is a plugin).
#include "viewer/viewer_plugin.h"

extern "C" __attribute__((visibility("default"))) int GonioRunViewer(
    const gonio::viewer::ServerOptions& options, std::FILE* out) {
    return gonio::viewer::RunViewer(options, out);
}
