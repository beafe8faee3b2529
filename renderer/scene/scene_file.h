#pragma once
// Reading a scene into frames, the way `gonio render` and the tests do: a SceneBuilder fed by the
// RIB parser, with the frames that ask for Option "spectral" "basis" "bands" built twice (their
// bands are chosen from their own spectra, band_plan.h).

#include <functional>
#include <string>

#include "base/diagnostics.h"
#include "renderer/rib/ri_target.h"
#include "renderer/scene/scene_builder.h"

namespace gonio {

// Feeds the scene's requests to a target (ParseRibFile or ParseRibString bound to the input).
// It is called a second time only when a frame asks for bands.
using RibReader = std::function<void(RiTarget& target, Diagnostics& diagnostics)>;

// Hands every frame of the scene named `sceneName` to onFrame once, in order. A frame that asks
// for bands is first built sampled and its bands chosen; after the whole input has been read,
// it is read again (silently: its messages were reported the first time) and those frames
// alone are handed over, with their bands. The frames in between are handed over from the
// first reading.
void BuildScene(const std::string& sceneName, const RibReader& read, Diagnostics& diagnostics,
                const SceneBuilder::FrameHandler& onFrame);

}  // namespace gonio
