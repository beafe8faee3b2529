#pragma once
// Whether the surfaces of a primitive solid enclose a volume, which CSG needs (RISpec 3.2 §5.9:
// the result of a set operation on an open surface is undefined), so that SolidBegin can warn.

#include <vector>

#include "renderer/scene/frame.h"

namespace gonio {

enum class Closure { Closed, Open, Unknown };

// Closed: one quadric that encloses a volume by itself (QuadricShape::closed), or meshes and
// subdivision cages whose every edge, once coincident vertices are welded in world space, bounds
// an even number of faces. Open: a curve or point set among them, one quadric that does not
// close, or meshes with a boundary edge. Unknown: any other mixture (a cylinder capped by
// disks), which is not checked.
Closure Enclosure(const std::vector<const SceneShape*>& surfaces);

}  // namespace gonio
