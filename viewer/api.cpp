#include "viewer/api.h"

// Eigen before httplib: httplib brings <resolv.h>, whose macro `_res` breaks Eigen's headers.
#include "viewer/api_handlers.h"
// clang-format off
#include <httplib.h>
// clang-format on

#include <memory>

#include "viewer/json_fields.h"
#include "viewer/web_files.h"

namespace gonio::viewer {

namespace {

constexpr size_t kMaxRequestBytes = 16 << 20;  // a light file or a few hundred numbers suffice

void SendError(httplib::Response& response, int status, const std::string& message) {
    response.status = status;
    response.set_content(nlohmann::json{{"error", message}}.dump(), "application/json");
}

void Send(httplib::Response& response, const Reply& reply) {
    response.status = 200;
    for (const auto& [name, value] : reply.headers) response.set_header(name, value);
    response.set_content(reply.body, reply.contentType);
}

// Runs a handler, turning a ViewerError (a bad request) into a 400 with its message, and any
// other exception into a 500, so that no request brings the server down.
template <typename Handler>
httplib::Server::Handler Guarded(Handler handler) {
    return [handler](const httplib::Request& request, httplib::Response& response) {
        try {
            Send(response, handler(request));
        } catch (const ViewerError& e) {
            SendError(response, 400, e.what());
        } catch (const std::exception& e) {
            SendError(response, 500, std::string("internal error: ") + e.what());
        }
    };
}

// Only the embedded files: a path is looked up in their table, never on disk, so no request
// ("/../", "%2e%2e") can reach another file.
bool ServeWebFile(const httplib::Request& request, httplib::Response& response) {
    const std::string path = request.path == "/" ? "/index.html" : request.path;
    const WebFile* file = FindWebFile(path);
    if (!file) return false;
    response.set_header("Cache-Control", "no-cache");
    response.set_content(std::string(file->content), std::string(ContentType(path)));
    return true;
}

}  // namespace

void RegisterApi(httplib::Server& server, const ReflectanceImage& image) {
    auto api = std::make_shared<ApiHandlers>(image);
    server.set_payload_max_length(kMaxRequestBytes);
    server.Get("/api/image", Guarded([api](const auto&) { return api->Metadata(); }));
    server.Get("/api/image/spectra", Guarded([api](const auto&) { return api->Spectra(); }));
    server.Get("/api/image/coefficients",
               Guarded([api](const auto&) { return api->Coefficients(); }));
    server.Get("/api/illuminants", Guarded([api](const auto&) { return api->Illuminants(); }));
    server.Get(R"(/api/illuminants/([^/]+))",
               Guarded([api](const httplib::Request& r) { return api->Illuminant(r.matches[1]); }));
    server.Post("/api/relight", Guarded([api](const httplib::Request& r) {
                    return api->Relit(ParseJsonObject(r.body));
                }));
    server.Post("/api/export", Guarded([api](const httplib::Request& r) {
                    return api->Export(ParseJsonObject(r.body));
                }));
    server.Post("/api/difference", Guarded([api](const httplib::Request& r) {
                    return api->Difference(ParseJsonObject(r.body));
                }));
    server.Post("/api/light/load", Guarded([api](const httplib::Request& r) {
                    return api->LoadLight(
                        r.body, r.has_param("name") ? r.get_param_value("name") : "light");
                }));
    server.Post("/api/light/save", Guarded([api](const httplib::Request& r) {
                    return api->SaveLight(ParseJsonObject(r.body));
                }));
    server.Post("/api/match", Guarded([api](const httplib::Request& r) {
                    return api->Match(ParseJsonObject(r.body));
                }));
    server.Get(R"(/.*)", [](const httplib::Request& request, httplib::Response& response) {
        if (!ServeWebFile(request, response))
            SendError(response, 404, "no such file or endpoint: " + request.path);
    });
    server.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
        if (response.body.empty())  // httplib's own refusals (405, 413, 400) get a message too
            SendError(response, response.status,
                      "cannot serve " + request.method + " " + request.path);
    });
    server.set_exception_handler(
        [](const httplib::Request&, httplib::Response& response, std::exception_ptr) {
            SendError(response, 500, "internal error");
        });
}

}  // namespace gonio::viewer
