#pragma once
// The graphics state behind SceneBuilder, shared by the files that implement its requests
// (scene_builder.cpp: blocks; builder_options.cpp; builder_attributes.cpp;
// builder_primitives.cpp). Not for use outside renderer/scene/.

#include <Imath/ImathMatrix.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "base/file_cache.h"
#include "renderer/scene/depth_map_camera.h"
#include "renderer/scene/primvar_typing.h"
#include "renderer/scene/scene_builder.h"

namespace gonio {

struct SceneBuilder::State {
    Options options;
    std::vector<Options> savedOptions;  // FrameBegin saves, FrameEnd restores
    Attributes attributes;              // change only through SceneBuilder::MutableAttributes()
    // The attributes as the last primitive saw them, shared by primitives until they change.
    std::shared_ptr<const Attributes> snapshot;
    std::vector<Attributes> savedAttributes;
    // Object space to the current base space: camera space before WorldBegin, world space
    // inside it (the camera transform is frozen at WorldBegin).
    M44f transform;
    std::vector<M44f> savedTransforms;
    // Transformation motion blur: the transform at each time of the MotionBegin block that
    // moved it (both empty while it is static), saved and restored with the transform.
    std::vector<float> transformTimes;
    std::vector<M44f> transformSamples;
    std::vector<std::pair<std::vector<float>, std::vector<M44f>>> savedMotion;
    std::vector<float> motionTimes;  // the open MotionBegin block's times
    int primitiveSample = -1;        // the time sample of the primitive being added; -1: static
    std::vector<M44f> motionBase;    // the transform at each of those times when it opened
    std::vector<Block> blocks;
    std::vector<FileLoc> blockLocs;
    bool inWorld = false;
    int frameNumber = 0;
    int worldsBegun = 0;
    ColorPlan colorPlan;
    std::map<int, LazyExpansion> lazyExpansions;  // by frame ordinal
    bool forwardingMessages = false;              // inside an archive of a LazyExpansion::firstRead
    // Procedural keys (lazy_procedurals.h): the key of each procedural being read, outermost
    // first, and how many procedurals each of them (and the world itself, first) has met.
    std::vector<std::string> proceduralKeys;
    std::vector<int> proceduralCounts{0};
    // The current world's choice from colorPlan, or null.
    const ColorChoice* colorChoice = nullptr;
    Frame frame;
    // The depth maps of the frame's Blobby repelling planes, each read once; anew every frame,
    // since an earlier frame may have rendered them again.
    std::unique_ptr<FileCache<DepthMapCamera>> depthMaps =
        std::make_unique<FileCache<DepthMapCamera>>();
    std::map<std::string, M44f> namedSpaces;  // current base space from the named space
    std::map<std::string, int> lightHandles;
    // Lights declared before WorldBegin (Aqsis and PRMan allow it), in camera space; they join
    // every following world.
    std::vector<SceneLight> cameraLights;
    std::map<std::string, std::shared_ptr<ObjectDefinition>> objects;
    std::shared_ptr<ObjectDefinition> openObject;
    std::string openObjectHandle;
    int motionRequestCount = -1;  // requests seen inside a MotionBegin block; -1 outside
    // The open SolidBegin blocks, innermost last: indices into frame.solids, −1 for a block
    // whose solid is not kept (inside ObjectBegin).
    std::vector<int> openSolids;
    std::vector<size_t> solidFirstShapes;  // frame.shapes.size() at each open SolidBegin
};

inline M44f ToM44f(const RtMatrix& m) {
    return M44f(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], m[12],
                m[13], m[14], m[15]);
}

}  // namespace gonio
