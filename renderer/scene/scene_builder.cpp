#include "renderer/scene/scene_builder.h"

#include "renderer/scene/scene_builder_state.h"

namespace gonio {
namespace {

const char* BlockName(int block) {
    static const char* const kNames[] = {"Frame",  "World",  "Attribute", "Transform",
                                         "Object", "Motion", "Solid"};
    return kNames[block];
}

std::string HandleText(const RtHandle& handle) {
    return handle.isString ? "\"" + handle.text + "\"" : handle.text;
}

bool SameShader(const ShaderInstance& a, const ShaderInstance& b) {
    return a.name == b.name && a.loc.line == b.loc.line && a.loc.column == b.loc.column &&
           a.loc.file == b.loc.file;
}

// What a definition's shape is shaded with at an instance: the instance's attributes, with
// every attribute the definition changed after ObjectBegin taken from the definition.
Attributes InstanceAttributes(const Attributes& instance, const Attributes& begin,
                              const Attributes& shape) {
    Attributes merged = instance;
    if (shape.color != begin.color) merged.color = shape.color;
    if (shape.opacity != begin.opacity) merged.opacity = shape.opacity;
    if (shape.textureCoordinates != begin.textureCoordinates)
        merged.textureCoordinates = shape.textureCoordinates;
    if (!SameShader(shape.surface, begin.surface)) merged.surface = shape.surface;
    if (!SameShader(shape.displacement, begin.displacement))
        merged.displacement = shape.displacement;
    if (!SameShader(shape.atmosphere, begin.atmosphere)) merged.atmosphere = shape.atmosphere;
    if (shape.activeLights != begin.activeLights) merged.activeLights = shape.activeLights;
    if (shape.twoSided != begin.twoSided) merged.twoSided = shape.twoSided;
    if (shape.matte != begin.matte) merged.matte = shape.matte;
    if (shape.identifier != begin.identifier) merged.identifier = shape.identifier;
    return merged;
}

}  // namespace

SceneBuilder::SceneBuilder(std::string sceneFile, Diagnostics& diagnostics, FrameHandler onFrame)
    : sceneFile_(std::move(sceneFile)),
      diagnostics_(diagnostics),
      onFrame_(std::move(onFrame)),
      state_(std::make_unique<State>()) {
    MutableAttributes().ubasis = MutableAttributes().vbasis = *NamedBasis("bezier");
}

SceneBuilder::~SceneBuilder() = default;

Attributes& SceneBuilder::MutableAttributes() {
    state_->snapshot.reset();
    return state_->attributes;
}

void SceneBuilder::SaveTransform() {
    state_->savedTransforms.push_back(state_->transform);
    state_->savedMotion.emplace_back(state_->transformTimes, state_->transformSamples);
}

void SceneBuilder::RestoreTransform() {
    state_->transform = state_->savedTransforms.back();
    state_->savedTransforms.pop_back();
    std::tie(state_->transformTimes, state_->transformSamples) = state_->savedMotion.back();
    state_->savedMotion.pop_back();
}

void SceneBuilder::Finish(const FileLoc& endOfInput) {
    for (size_t i = state_->blocks.size(); i-- > 0;)
        diagnostics_.Error(state_->blockLocs[i],
                           std::string(BlockName(static_cast<int>(state_->blocks[i]))) +
                               "Begin is never closed (input ends at " + endOfInput.ToString() +
                               ")");
}

// ---- scope checks ---------------------------------------------------------------------------

bool SceneBuilder::RequireWorld(const char* request, const FileLoc& loc) {
    if (state_->inWorld) return true;
    diagnostics_.Error(loc, std::string(request) + " is only valid inside WorldBegin/WorldEnd");
    return false;
}

bool SceneBuilder::RequireOptions(const char* request, const FileLoc& loc) {
    if (!state_->inWorld) return true;
    diagnostics_.Error(
        loc, std::string(request) + " is an option and is not valid inside WorldBegin/WorldEnd");
    return false;
}

void SceneBuilder::PushBlock(Block block, const FileLoc& loc) {
    state_->blocks.push_back(block);
    state_->blockLocs.push_back(loc);
}

bool SceneBuilder::PopBlock(Block block, const char* request, const FileLoc& loc) {
    if (state_->blocks.empty() || state_->blocks.back() != block) {
        const std::string open =
            state_->blocks.empty()
                ? std::string("no block is open")
                : std::string(BlockName(static_cast<int>(state_->blocks.back()))) + "Begin at " +
                      state_->blockLocs.back().ToString() + " is still open";
        diagnostics_.Error(loc, std::string(request) + " does not match: " + open);
        return false;
    }
    state_->blocks.pop_back();
    state_->blockLocs.pop_back();
    return true;
}

void SceneBuilder::IgnoredRequest(const char* request, const FileLoc& loc) {
    diagnostics_.NoteOnce(request, loc,
                          std::string(request) + " is accepted and ignored by this ray tracer");
}

// ---- block structure ------------------------------------------------------------------------

void SceneBuilder::FrameBegin(int frame, const FileLoc& loc) {
    if (!RequireOptions("FrameBegin", loc)) return;
    PushBlock(Block::Frame, loc);
    state_->frameNumber = frame;
    state_->savedOptions.push_back(state_->options);
    state_->savedAttributes.push_back(state_->attributes);
    SaveTransform();
}

void SceneBuilder::FrameEnd(const FileLoc& loc) {
    if (!PopBlock(Block::Frame, "FrameEnd", loc)) return;
    state_->options = state_->savedOptions.back();
    state_->savedOptions.pop_back();
    MutableAttributes() = state_->savedAttributes.back();
    state_->savedAttributes.pop_back();
    RestoreTransform();
}

void SceneBuilder::WorldBegin(const FileLoc& loc) {
    if (!RequireOptions("WorldBegin", loc)) return;
    PushBlock(Block::World, loc);
    state_->savedAttributes.push_back(state_->attributes);
    SaveTransform();
    state_->options.cameraFromWorld = state_->transform;
    state_->options.cameraMotionTimes = state_->transformTimes;
    state_->options.cameraMotion = state_->transformSamples;
    state_->inWorld = true;
    ApplyColorPlan(state_->worldsBegun);
    state_->frame = Frame();
    state_->openSolids.clear();
    state_->solidFirstShapes.clear();
    state_->frame.number = state_->frameNumber;
    state_->frame.ordinal = state_->worldsBegun++;
    state_->frame.options = state_->options;
    state_->frame.sceneFile = sceneFile_;
    state_->depthMaps = std::make_unique<FileCache<DepthMapCamera>>();
    state_->proceduralKeys.clear();
    state_->proceduralCounts.assign(1, 0);
    // Spaces named before WorldBegin were relative to camera space; re-express them in world.
    const M44f worldFromCamera = state_->transform.inverse();
    for (const auto& [name, m] : state_->namedSpaces)
        state_->frame.namedSpaces[name] = m * worldFromCamera;
    state_->frame.namedSpaces["camera"] = worldFromCamera;
    state_->transform = M44f();
    state_->transformTimes.clear();
    state_->transformSamples.clear();
    state_->lightHandles.clear();
    for (SceneLight light : state_->cameraLights) {
        light.light.shader.worldFromShader = light.light.shader.worldFromShader * worldFromCamera;
        AddLight(std::move(light));
    }
}

void SceneBuilder::WorldEnd(const FileLoc& loc) {
    if (!PopBlock(Block::World, "WorldEnd", loc)) return;
    state_->inWorld = false;
    MutableAttributes() = state_->savedAttributes.back();
    state_->savedAttributes.pop_back();
    RestoreTransform();
    if (onFrame_) onFrame_(state_->frame);
    state_->frame = Frame();
}

void SceneBuilder::AttributeBegin(const FileLoc& loc) {
    PushBlock(Block::Attribute, loc);
    state_->savedAttributes.push_back(state_->attributes);
    SaveTransform();
}

void SceneBuilder::AttributeEnd(const FileLoc& loc) {
    if (!PopBlock(Block::Attribute, "AttributeEnd", loc)) return;
    MutableAttributes() = state_->savedAttributes.back();
    state_->savedAttributes.pop_back();
    RestoreTransform();
}

void SceneBuilder::TransformBegin(const FileLoc& loc) {
    PushBlock(Block::Transform, loc);
    SaveTransform();
}

void SceneBuilder::TransformEnd(const FileLoc& loc) {
    if (!PopBlock(Block::Transform, "TransformEnd", loc)) return;
    RestoreTransform();
}

// Shapes inside ObjectBegin/End are recorded relative to the transform current at ObjectBegin;
// ObjectInstance places the definition with the transform current at the instance.
void SceneBuilder::ObjectBegin(const RtHandle& handle, const FileLoc& loc) {
    if (state_->openObject) {
        diagnostics_.Error(loc, "ObjectBegin inside another ObjectBegin block");
        return;
    }
    PushBlock(Block::Object, loc);
    state_->savedAttributes.push_back(state_->attributes);
    SaveTransform();
    state_->transform = M44f();
    state_->transformTimes.clear();
    state_->transformSamples.clear();
    state_->openObject = std::make_shared<ObjectDefinition>();
    state_->openObject->base = std::make_shared<const Attributes>(state_->attributes);
    state_->openObjectHandle = handle.text;
}

void SceneBuilder::ObjectEnd(const FileLoc& loc) {
    if (!PopBlock(Block::Object, "ObjectEnd", loc)) return;
    state_->objects[state_->openObjectHandle] = std::move(state_->openObject);
    state_->openObject.reset();
    MutableAttributes() = state_->savedAttributes.back();
    state_->savedAttributes.pop_back();
    RestoreTransform();
}

void SceneBuilder::ObjectInstance(const RtHandle& handle, const FileLoc& loc) {
    auto it = state_->objects.find(handle.text);
    if (it == state_->objects.end()) {
        diagnostics_.Error(
            loc, "ObjectInstance: no object was defined with handle " + HandleText(handle));
        return;
    }
    if (state_->openObject) {
        // An instance inside a definition: copy its shapes, composed with the transform.
        for (SceneShape shape : it->second->shapes) {
            shape.worldFromObject = shape.worldFromObject * state_->transform;
            state_->openObject->shapes.push_back(std::move(shape));
        }
        return;
    }
    if (!RequireWorld("ObjectInstance", loc)) return;
    if (state_->attributes.areaLight >= 0)
        diagnostics_.WarningOnce("area light instance", loc,
                                 "an object instance is not area light geometry: it is "
                                 "rendered, but does not emit");
    ObjectInstanceUse use{
        it->second, state_->transform, {}, state_->transformTimes, state_->transformSamples};
    const ObjectDefinition& definition = *it->second;
    for (size_t i = 0; i < definition.shapes.size(); ++i) {
        const auto& own = definition.shapes[i].attributes;
        if (i > 0 && own == definition.shapes[i - 1].attributes) {
            use.shapeAttributes.push_back(use.shapeAttributes.back());
            continue;
        }
        use.shapeAttributes.push_back(std::make_shared<const Attributes>(
            InstanceAttributes(state_->attributes, *definition.base, *own)));
    }
    if (!state_->openSolids.empty() && state_->openSolids.back() >= 0) {
        // Inside a solid the instance's shapes are copied into the frame, to join it as
        // surfaces of their own (the CSG resolves shapes, not instances).
        for (size_t i = 0; i < definition.shapes.size(); ++i) {
            SceneShape shape = definition.shapes[i];
            shape.worldFromObject = shape.worldFromObject * state_->transform;
            shape.attributes = use.shapeAttributes[i];
            JoinSolid(&shape);
            state_->frame.shapes.push_back(std::move(shape));
        }
        return;
    }
    state_->frame.instances.push_back(std::move(use));
}

// Motion blocks: transformations move (the transform is kept at each of the block's times);
// a moving primitive (deformation) uses its first sample.
void SceneBuilder::MotionBegin(const std::vector<float>& times, const FileLoc& loc) {
    PushBlock(Block::Motion, loc);
    if (times.empty()) {
        diagnostics_.Error(loc, "MotionBegin needs at least one time");
        return;
    }
    state_->motionRequestCount = 0;
    state_->motionTimes = times;
    const bool sameTimes = state_->transformTimes == times;
    state_->motionBase =
        sameTimes ? state_->transformSamples : std::vector<M44f>(times.size(), state_->transform);
}

void SceneBuilder::MotionEnd(const FileLoc& loc) {
    if (!PopBlock(Block::Motion, "MotionEnd", loc)) return;
    state_->motionRequestCount = -1;
}

}  // namespace gonio
