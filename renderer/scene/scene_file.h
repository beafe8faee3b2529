#pragma once
// Reading a scene into frames, the way `gonio render` and the tests do: a SceneBuilder fed by the
// RIB parser, with the frames that ask for Option "spectral" "basis" "bands" or "svd" built twice
// (their colour space is chosen from their own spectra, color_plan.h).

#include <functional>
#include <string>

#include "base/diagnostics.h"
#include "renderer/rib/ri_target.h"
#include "renderer/scene/scene_builder.h"

namespace gonio {

// Feeds the scene's requests to a target (ParseRibFile or ParseRibString bound to the input).
// It is called a second time only when a frame asks for bands or svd.
using RibReader = std::function<void(RiTarget& target, Diagnostics& diagnostics)>;

// Hands every frame of the scene named `sceneName` to onFrame once, in order. A frame that asks
// for bands or svd is first built sampled and its colour space chosen; after the whole input has
// been read, it is read again (silently: its messages were reported the first time) and those
// frames alone are handed over, in their colour spaces. The frames in between are handed over from
// the first reading. Texture-making requests go to onTexture (if given) during the first reading
// only, each once, in RIB order.
void BuildScene(const std::string& sceneName, const RibReader& read, Diagnostics& diagnostics,
                const SceneBuilder::FrameHandler& onFrame,
                const SceneBuilder::TextureHandler& onTexture = nullptr);

}  // namespace gonio
