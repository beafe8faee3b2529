#include "renderer/scene/scene_file.h"

#include <memory>

#include "spectral/spectral_error.h"

namespace gonio {
namespace {

FileLoc EndOf(const std::string& sceneName) {
    return FileLoc{std::make_shared<const std::string>(sceneName), 0, 0};
}

}  // namespace

void BuildScene(const std::string& sceneName, const RibReader& read, Diagnostics& diagnostics,
                const SceneBuilder::FrameHandler& onFrame,
                const SceneBuilder::TextureHandler& onTexture) {
    ColorPlan plan;
    SceneBuilder builder(sceneName, diagnostics, [&](const Frame& frame) {
        if (!frame.options.FitsColorSpaceToFrame()) return onFrame(frame);
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
    Diagnostics silent(nullptr);
    SceneBuilder fitted(sceneName, silent, [&](const Frame& frame) {
        if (plan.count(frame.ordinal)) onFrame(frame);
    });
    fitted.SetColorPlan(plan);
    // The textures were made in the first reading; the second one passes their requests by.
    fitted.SetTextureHandler([](const TextureRequest&) {});
    read(fitted, silent);
    fitted.Finish(EndOf(sceneName));
}

}  // namespace gonio
