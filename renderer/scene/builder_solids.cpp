// SceneBuilder: solids and spatial set operations (RISpec 3.2 §5.9). SolidBegin opens a node of
// a CSG tree (Frame::solids); the shapes declared inside become the surfaces of its primitive
// solids, which the ray tracer combines by ray intervals (renderer/raytrace/solid_tree.h).

#include <optional>
#include <string>
#include <vector>

#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/solid_closure.h"

namespace gonio {
namespace {

// Deeper trees are refused: SolidTrees evaluates a tree recursively for every ray crossing.
constexpr size_t kMaxSolidDepth = 1000;

std::optional<SolidNode::Operation> OperationNamed(const std::string& name) {
    using Op = SolidNode::Operation;
    if (name == "primitive") return Op::Primitive;
    if (name == "union") return Op::Union;
    if (name == "intersection") return Op::Intersection;
    if (name == "difference") return Op::Difference;
    return std::nullopt;
}

}  // namespace

void SceneBuilder::SolidBegin(const std::string& operation, const FileLoc& loc) {
    PushBlock(Block::Solid, loc);
    std::optional<SolidNode::Operation> op = OperationNamed(operation);
    if (!op) {
        diagnostics_.Error(loc, "SolidBegin: unknown operation \"" + operation +
                                    "\" (expected \"primitive\", \"union\", \"intersection\" or "
                                    "\"difference\")");
        op = SolidNode::Operation::Union;
    }
    std::vector<int>& open = state_->openSolids;
    state_->solidFirstShapes.push_back(state_->frame.shapes.size());
    if (open.size() >= kMaxSolidDepth) {
        diagnostics_.Error(loc, "SolidBegin nested more than " + std::to_string(kMaxSolidDepth) +
                                    " deep (a ray resolves the tree recursively)");
        open.push_back(-1);
        return;
    }
    if (state_->openObject || !state_->inWorld || (!open.empty() && open.back() < 0)) {
        diagnostics_.WarningOnce("solid in object", loc,
                                 "SolidBegin inside ObjectBegin (or outside WorldBegin) is not "
                                 "resolved as CSG: its solids are rendered as a union");
        open.push_back(-1);
        return;
    }
    std::vector<SolidNode>& solids = state_->frame.solids;
    const int parent = open.empty() ? -1 : open.back();
    if (parent >= 0 && solids[size_t(parent)].operation == SolidNode::Operation::Primitive)
        diagnostics_.WarningOnce("solid in primitive", loc,
                                 "a solid inside SolidBegin \"primitive\": the primitive is the "
                                 "union of its own surfaces' volume and its inner solids");
    SolidNode node;
    node.operation = *op;
    node.parent = parent;
    node.loc = loc;
    const int index = static_cast<int>(solids.size());
    solids.push_back(std::move(node));
    if (parent >= 0) solids[size_t(parent)].children.push_back(index);
    open.push_back(index);
}

void SceneBuilder::SolidEnd(const FileLoc& loc) {
    if (!PopBlock(Block::Solid, "SolidEnd", loc) || state_->openSolids.empty()) return;
    const int solid = state_->openSolids.back();
    const size_t firstShape = state_->solidFirstShapes.back();
    state_->openSolids.pop_back();
    state_->solidFirstShapes.pop_back();
    if (solid < 0) return;
    const SolidNode& node = state_->frame.solids[size_t(solid)];
    if (node.operation != SolidNode::Operation::Primitive) return;
    std::vector<const SceneShape*> surfaces;
    for (size_t i = firstShape; i < state_->frame.shapes.size(); ++i)
        if (state_->frame.shapes[i].solid == solid) surfaces.push_back(&state_->frame.shapes[i]);
    CheckClosed(node, surfaces);
}

void SceneBuilder::JoinSolid(SceneShape* shape) {
    if (state_->openSolids.empty() || state_->openSolids.back() < 0) return;
    std::vector<SolidNode>& solids = state_->frame.solids;
    int solid = state_->openSolids.back();
    if (solids[size_t(solid)].operation != SolidNode::Operation::Primitive) {
        // A primitive solid of its own, whose one surface is known now.
        SolidNode node;
        node.parent = solid;
        node.loc = shape->loc;
        solids[size_t(solid)].children.push_back(static_cast<int>(solids.size()));
        solid = static_cast<int>(solids.size());
        solids.push_back(std::move(node));
        CheckClosed(solids.back(), {shape});
    }
    shape->solid = solid;
    if (!shape->worldFromObjectMotion.empty()) {
        diagnostics_.WarningOnce("solid motion", shape->loc,
                                 "a moving primitive inside SolidBegin is not motion blurred: it "
                                 "stays where it is at the start of its motion block");
        shape->worldFromObject = shape->worldFromObjectMotion.front();
        shape->motionTimes.clear();
        shape->worldFromObjectMotion.clear();
    }
}

void SceneBuilder::CheckClosed(const SolidNode& node,
                               const std::vector<const SceneShape*>& surfaces) {
    if (surfaces.empty()) {
        if (node.children.empty())
            diagnostics_.Warning(node.loc, "SolidBegin \"primitive\" has no surfaces: it is empty");
        return;
    }
    if (Enclosure(surfaces) == Closure::Open)
        diagnostics_.Warning(surfaces.front()->loc,
                             "a primitive solid whose surfaces do not enclose a volume (RISpec "
                             "leaves CSG with it undefined): inside and outside follow the "
                             "direction of its normals");
}

}  // namespace gonio
