#include "renderer/scene/scene_file.h"

#include <functional>
#include <memory>
#include <set>

#include "spectral/spectral_error.h"

namespace gonio {
namespace {

// How many times one frame is read again for archives its rays reached: each reading expands
// one more level of archives nested in archives out of view.
constexpr int kMaxLazyReadings = 8;

FileLoc EndOf(const std::string& sceneName) {
    return FileLoc{std::make_shared<const std::string>(sceneName), 0, 0};
}

// The reading of a scene and where its frames go.
struct SceneReading {
    const std::string& sceneName;
    const RibReader& read;
    Diagnostics& diagnostics;
    const SceneBuilder::FrameHandler& onFrame;
    const ColorPlan& plan;

    // Hands `frame` over; then, while its rays reached DelayedReadArchives it has not read
    // (lazy_procedurals.h), reads the scene again with those expanded too, and hands that frame
    // over instead. Silently, but for the archives read for the first time: the rest of the
    // scene's messages were reported by the first reading.
    void HandOver(const Frame& frame, std::set<std::string> expanded, int readings) const {
        onFrame(frame);
        const std::vector<std::string> reached = frame.lazyProcedurals.ReachedKeys();
        if (reached.empty()) return;
        if (readings == kMaxLazyReadings) {
            diagnostics.Warning(EndOf(sceneName),
                                "frame " + std::to_string(frame.number) +
                                    ": rays still reach DelayedReadArchives not read after " +
                                    std::to_string(kMaxLazyReadings) +
                                    " readings of nested archives; they are left out");
            return;
        }
        expanded.insert(reached.begin(), reached.end());
        SceneBuilder::LazyExpansion expansion;
        expansion.keys = expanded;
        expansion.firstRead = {reached.begin(), reached.end()};
        expansion.report = &diagnostics;
        ReadAgain(
            [&](const Frame& f) {
                if (f.ordinal == frame.ordinal) HandOver(f, expanded, readings + 1);
            },
            [&](SceneBuilder& again) {
                again.SetLazyExpansion(frame.ordinal, std::move(expansion));
            });
    }

    // Reads the scene again, silently (the first reading reported its messages), with the colour
    // plan; `configure` sets up the builder further.
    void ReadAgain(const SceneBuilder::FrameHandler& handler,
                   const std::function<void(SceneBuilder&)>& configure = {}) const {
        Diagnostics silent(nullptr);
        SceneBuilder again(sceneName, silent, handler);
        again.SetColorPlan(plan);
        // The textures were made in the first reading; a later one passes their requests by.
        again.SetTextureHandler([](const TextureRequest&) {});
        if (configure) configure(again);
        read(again, silent);
        again.Finish(EndOf(sceneName));
    }
};

}  // namespace

void BuildScene(const std::string& sceneName, const RibReader& read, Diagnostics& diagnostics,
                const SceneBuilder::FrameHandler& onFrame,
                const SceneBuilder::TextureHandler& onTexture) {
    ColorPlan plan;
    const SceneReading reading{sceneName, read, diagnostics, onFrame, plan};
    SceneBuilder builder(sceneName, diagnostics, [&](const Frame& frame) {
        if (!frame.options.FitsColorSpaceToFrame()) return reading.HandOver(frame, {}, 0);
        try {
            plan[frame.ordinal] = ChooseColorSpace(frame);
        } catch (const spectral::SpectralError& e) {
            diagnostics.Error(EndOf(sceneName), "frame " + std::to_string(frame.number) +
                                                    " is not rendered: " + e.what());
        }
    });
    builder.SetTextureHandler(onTexture);
    read(builder, diagnostics);
    builder.Finish(EndOf(sceneName));
    if (plan.empty()) return;
    // The frames that fit their colour space, read again with the plan.
    reading.ReadAgain([&](const Frame& frame) {
        if (plan.count(frame.ordinal)) reading.HandOver(frame, {}, 0);
    });
}

}  // namespace gonio
