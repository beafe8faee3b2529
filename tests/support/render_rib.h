#pragma once
// Renders a RIB text in process, every frame with the default settings (and the frames that ask
// for bands built twice, as `gonio render` does), for the tests that render a scene and read its
// images back.

#include <string>

#include "renderer/frame/frame_renderer.h"
#include "renderer/image/texture_making.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_file.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio::test {

struct RibRenderResult {
    int errors = 0;
    std::string messages;  // every diagnostic, as `gonio render` would print them
};

inline RibRenderResult RenderRibString(const std::string& rib, const std::string& name) {
    RibRenderResult result;
    CapturedDiagnostics captured;
    {
        Diagnostics& diagnostics = captured.Get();
        BuildScene(
            name, [&](RiTarget& target, Diagnostics& d) { ParseRibString(rib, name, target, d); },
            diagnostics,
            [&](const Frame& frame) {
                RenderStats stats;
                RenderFrame(frame, RenderSettings{}, diagnostics, &stats);
            },
            [&](const TextureRequest& request) { MakeRequestedTexture(request, diagnostics); });
        result.errors = diagnostics.ErrorCount();
    }
    result.messages = captured.Text();
    return result;
}

}  // namespace gonio::test
