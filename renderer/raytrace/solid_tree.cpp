#include "renderer/raytrace/solid_tree.h"

namespace gonio {

SolidTrees::SolidTrees(const std::vector<SolidNode>& nodes) : nodes_(nodes), rootOf_(nodes.size()) {
    // Parents come before their children (SolidBegin opens them in that order).
    for (size_t i = 0; i < nodes_.size(); ++i)
        rootOf_[i] = nodes_[i].parent < 0 ? int(i) : rootOf_[size_t(nodes_[i].parent)];
}

bool SolidTrees::Inside(int node, const std::vector<uint8_t>& inside) const {
    const SolidNode& n = nodes_[size_t(node)];
    using Op = SolidNode::Operation;
    switch (n.operation) {
        case Op::Primitive:
        case Op::Union:
            // A primitive is the volume of its own surfaces and of any solids inside it.
            if (inside[size_t(node)]) return true;
            for (int child : n.children)
                if (Inside(child, inside)) return true;
            return false;
        case Op::Intersection:
            if (n.children.empty()) return false;
            for (int child : n.children)
                if (!Inside(child, inside)) return false;
            return true;
        case Op::Difference:
            if (n.children.empty() || !Inside(n.children.front(), inside)) return false;
            for (size_t k = 1; k < n.children.size(); ++k)
                if (Inside(n.children[k], inside)) return false;
            return true;
    }
    return false;
}

int SolidTrees::FirstBoundary(const std::vector<SolidCrossing>& crossings, float tfar,
                              bool* flip) const {
    // Each primitive's state along the ray, per thread and all zero (outside) between calls:
    // a ray touches only the entries of the primitives it crosses, whatever the frame holds.
    thread_local std::vector<uint8_t> inside;
    if (inside.size() < nodes_.size()) inside.resize(nodes_.size(), 0);
    // Where the ray starts: inside each primitive whose first crossing is an exit (set from the
    // last crossing back, so that the first one's word stands).
    for (size_t k = crossings.size(); k-- > 0;)
        inside[size_t(crossings[k].solid)] = !crossings[k].entering;
    int found = -1;
    for (size_t k = 0; k < crossings.size() && crossings[k].t <= tfar; ++k) {
        const SolidCrossing& c = crossings[k];
        const int root = rootOf_[size_t(c.solid)];
        const bool before = Inside(root, inside);
        inside[size_t(c.solid)] = c.entering;
        const bool after = Inside(root, inside);
        if (before == after) continue;
        // The combined solid is entered where `after` holds: its outward normal faces against
        // the ray there, as the crossed surface's does when the ray enters that.
        *flip = after != c.entering;
        found = int(k);
        break;
    }
    for (const SolidCrossing& c : crossings) inside[size_t(c.solid)] = 0;
    return found;
}

}  // namespace gonio
