#pragma once
// Renders a RIB text in process, every frame with the default settings, for the tests that
// render a scene and read its images back.

#include <memory>
#include <string>

#include "renderer/frame/frame_renderer.h"
#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"
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
        SceneBuilder builder(name, diagnostics, [&](const Frame& frame) {
            RenderStats stats;
            RenderFrame(frame, RenderSettings{}, diagnostics, &stats);
        });
        ParseRibString(rib, name, builder, diagnostics);
        builder.Finish(FileLoc{std::make_shared<const std::string>(name), 0, 0});
        result.errors = diagnostics.ErrorCount();
    }
    result.messages = captured.Text();
    return result;
}

}  // namespace gonio::test
