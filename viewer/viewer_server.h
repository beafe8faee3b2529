#pragma once
// `gonio view`: loads a reflectance image and serves the viewer until SIGINT or SIGTERM.

#include <cstdio>
#include <string>

namespace gonio::viewer {

struct ServerOptions {
    std::string image;
    std::string bind = "127.0.0.1";  // loopback unless the user asks for another interface
    int port = 0;                    // 0: an ephemeral port, printed in the URL
};

// Prints "gonio view: http://HOST:PORT/" to `out` (flushed) once the port is bound, then serves
// until SIGINT or SIGTERM. Returns 0 after a clean stop, 1 when the image is bad (message on
// stderr, naming the file), 2 when the address cannot be bound.
int RunViewer(const ServerOptions& options, std::FILE* out);

}  // namespace gonio::viewer
