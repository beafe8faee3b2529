#pragma once
// Builds the frames of a world (the RIB between WorldBegin and WorldEnd, as "test.rib") with the
// scene builder alone, for the tests that look at Frames or trace rays through them.

#include <string>
#include <vector>

#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio::test {

struct BuiltWorld {
    std::vector<Frame> frames;
    std::string messages;  // every diagnostic
    int errors = 0;
};

inline BuiltWorld ParseWorld(const std::string& world) {
    BuiltWorld built;
    CapturedDiagnostics captured;
    {
        SceneBuilder builder("test.rib", captured.Get(),
                             [&](const Frame& frame) { built.frames.push_back(frame); });
        ParseRibString("WorldBegin\n" + world + "WorldEnd\n", "test.rib", builder, captured.Get());
        built.errors = captured.Get().ErrorCount();
    }
    built.messages = captured.Text();
    return built;
}

}  // namespace gonio::test
