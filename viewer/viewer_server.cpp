#include "viewer/viewer_server.h"

// Eigen (through the reflectance image) before httplib: httplib brings <resolv.h>, whose macro
// `_res` breaks Eigen's headers.
#include "viewer/api.h"
#include "viewer/reflectance_image.h"
// clang-format off
#include <httplib.h>
// clang-format on
#include <signal.h>

#include <thread>

namespace gonio::viewer {

namespace {

// Blocks SIGINT and SIGTERM in this thread and every thread started after it (the server's
// workers), so that only StopOnSignal's sigwait receives them: a handler could not safely stop
// the server.
sigset_t BlockStopSignals() {
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    return signals;
}

int Bind(httplib::Server& server, const ServerOptions& options) {
    if (options.port == 0) return server.bind_to_any_port(options.bind);
    return server.bind_to_port(options.bind, options.port) ? options.port : -1;
}

std::string Url(const std::string& host, int port) {
    const bool ipv6 = host.find(':') != std::string::npos;
    return "http://" + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port) + "/";
}

}  // namespace

int RunViewer(const ServerOptions& options, std::FILE* out) {
    ReflectanceImage image;
    try {
        image = ReadReflectanceImage(options.image);
    } catch (const ViewerError& e) {
        std::fprintf(stderr, "gonio view: %s\n", e.what());
        return 1;
    }
    const sigset_t stopSignals = BlockStopSignals();
    httplib::Server server;
    RegisterApi(server, image);
    const int port = Bind(server, options);
    if (port <= 0) {
        std::fprintf(stderr, "gonio view: cannot listen on %s port %d\n", options.bind.c_str(),
                     options.port);
        return 2;
    }
    std::fprintf(out, "gonio view: %s\n", Url(options.bind, port).c_str());
    std::fflush(out);
    std::thread listener([&server] { server.listen_after_bind(); });
    int received = 0;
    sigwait(&stopSignals, &received);
    server.stop();
    listener.join();
    std::fprintf(out, "gonio view: stopped (%s)\n", received == SIGINT ? "SIGINT" : "SIGTERM");
    std::fflush(out);
    return 0;
}

}  // namespace gonio::viewer
