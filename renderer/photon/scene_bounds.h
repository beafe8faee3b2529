#pragma once
// The world-space bounding box of a frame's geometry, for placing the photon tracer's beams
// outside the micro geometry and for the vertical extent of a periodic tile.

#include <Imath/ImathBox.h>

#include "renderer/scene/frame.h"

namespace gonio {

// Empty when the frame has no geometry. Conservative: control hulls for curved primitives.
Imath::Box3f WorldBounds(const Frame& frame);

}  // namespace gonio
