// gonio view IMAGE.exr [--port N] [--bind ADDRESS]: the spectral viewer (thesis §6.2, Appendix
// D.1) as a local web page. Exit status: 0 after Ctrl-C or SIGTERM, 1 a bad image (the message
// names the file), 2 a bad command line or an address that cannot be bound.

#include <cstdio>
#include <memory>
#include <string>

#include "base/plugin_path.h"
#include "commands.h"
#include "viewer/viewer_plugin.h"

namespace gonio {
namespace {

// Opens libgonio_viewer.so and runs the viewer; 2 when the plugin cannot be opened.
int RunViewerPlugin(const viewer::ServerOptions& options) {
    std::string error;
    auto entry = reinterpret_cast<viewer::ViewerPluginEntry>(OpenPluginEntry(
        "GONIO_VIEWER_PLUGIN", "libgonio_viewer.so", viewer::kViewerPluginEntry, &error));
    if (!entry) {
        std::fprintf(stderr, "gonio view: cannot open the viewer plugin: %s\n", error.c_str());
        return 2;
    }
    return entry(options, stdout);
}

}  // namespace

void AddViewCommand(CLI::App& app, int* exitCode) {
    auto options = std::make_shared<viewer::ServerOptions>();
    CLI::App* cmd = app.add_subcommand(
        "view",
        "Serve the spectral viewer for a reflectance image (a spectral EXR) on a local "
        "web page: relight it with any light, edit the light's spectrum");
    cmd->add_option("image", options->image,
                    "Spectral OpenEXR (Display \"openexr\" \"spectral\"), rendered under the "
                    "equal-energy light \"E\"")
        ->required();
    cmd->add_option("--port", options->port, "TCP port (default 0: an ephemeral one, printed)")
        ->check(CLI::Range(0, 65535));
    cmd->add_option("--bind", options->bind,
                    "Address to listen on (default 127.0.0.1, loopback only)");
    cmd->callback([options, exitCode] { *exitCode = RunViewerPlugin(*options); });
}

}  // namespace gonio
