#pragma once
// The HTTP/JSON API behind the page, which scripts can use too (docs/viewer.md lists it):
//
//   GET  /api/image              metadata: size, wavelengths, the RGB conversion matrices
//   GET  /api/image/spectra      the samples, little-endian float32, pixel-major, top row first
//   GET  /api/image/coefficients an image in a basis: its k coefficients per pixel, likewise
//   GET  /api/illuminants        the preset names; /api/illuminants/NAME one preset
//   POST /api/relight            {light, conversion} → linear RGB, little-endian float32
//   POST /api/export             {light, conversion, format: png|exr} → the image file
//   POST /api/difference         {lightA, lightB} → the ΔE2000 map, little-endian float32
//   POST /api/light/load?name=F  a cspec/curve file's text → the light as JSON
//   POST /api/light/save         the light as JSON → a cspec/curve file's text
//   POST /api/match              {light, target, conversion} → the matched light (§6.2.2)
//
// and the page's own embedded files; nothing else. A bad request is a 4xx whose body is
// {"error": "..."}; a handler never lets an exception reach the server.

#include "viewer/reflectance_image.h"

namespace httplib {
class Server;
}

namespace gonio::viewer {

// Registers every route on `server`; `image` must outlive it.
void RegisterApi(httplib::Server& server, const ReflectanceImage& image);

}  // namespace gonio::viewer
