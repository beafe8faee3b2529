// gonio view IMAGE.exr [--port N] [--bind ADDRESS]: the spectral viewer (thesis §6.2, Appendix
// D.1) as a local web page. Exit status: 0 after Ctrl-C or SIGTERM, 1 a bad image (the message
// names the file), 2 a bad command line or an address that cannot be bound.

#include <cstdio>
#include <memory>

#include "commands.h"
#include "viewer/viewer_server.h"

namespace gonio {

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
    cmd->callback([options, exitCode] { *exitCode = viewer::RunViewer(*options, stdout); });
}

}  // namespace gonio
