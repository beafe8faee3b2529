#pragma once
// `gonio render` of a frame with Option "BRDFLight": trace the photons, write the photon map
// (temporary name, then rename) and print a summary instead of rendering an image.

#include "base/diagnostics.h"
#include "renderer/photon/brdflight_options.h"
#include "renderer/photon/photon_tracer.h"
#include "renderer/scene/frame.h"
#include "renderer/scene/render_settings.h"

namespace gonio {

// Reads the options, traces and writes the map. Returns false only when the map could not be
// written (an output error, exit 2). Scene errors (bad options, no geometry, a bad micro BRDF,
// more photons than memory holds) are reported, nothing is traced, and it returns true: the
// error count gives exit 1. The summary goes to stderr; `stats`, when given, receives the counts.
bool TracePhotonFrame(const Frame& frame, const RenderSettings& settings, Diagnostics& diagnostics,
                      PhotonStats* stats = nullptr);

// The summary line of a run, as printed.
std::string PhotonSummary(const std::string& output, const PhotonStats& stats);

}  // namespace gonio
