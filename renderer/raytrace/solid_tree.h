#pragma once
// CSG by ray intervals (RISpec 3.2 §5.9). Along a ray every primitive solid is inside over the
// intervals between its surface's entries and exits; a tree's union, intersection and
// difference combine those states, and the combined solid's surface is where its state
// changes. RayScene collects a ray's crossings of the primitive solids' surfaces and asks here
// which one the ray sees. Knows nothing of Embree.

#include <cstdint>
#include <vector>

#include "renderer/scene/frame.h"

namespace gonio {

// A ray crossing the surface of a primitive solid.
struct SolidCrossing {
    float t;
    int solid;      // the primitive solid (index into Frame::solids)
    bool entering;  // the surface's outward normal faces against the ray
};

class SolidTrees {
  public:
    explicit SolidTrees(const std::vector<SolidNode>& nodes);

    // Of a ray's crossings beyond its start, in order of t (all of them, to the end of the
    // ray: a primitive's first crossing tells whether the ray starts inside it, so that rays
    // from inside a solid, like shadow rays leaving its surface, are resolved too): the index
    // of the first crossing with t <= tfar where a tree's combined solid begins or ends, or -1.
    // *flip: whether the combined solid's outward normal there is the reverse of the crossed
    // surface's (a difference's carved part shows the subtracting solid's surface inside out).
    int FirstBoundary(const std::vector<SolidCrossing>& crossings, float tfar, bool* flip) const;

  private:
    // Whether node is inside along the ray, from its primitive solids' states.
    bool Inside(int node, const std::vector<uint8_t>& inside) const;

    std::vector<SolidNode> nodes_;
    std::vector<int> rootOf_;
};

}  // namespace gonio
