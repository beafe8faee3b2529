// RayScene's construction: the Embree device, the top-level scene, solids' scene, and the
// levels and instances that place object definitions and moving shapes. Geometry is built in
// ray_scene_geometry.cpp, rays are traced in ray_scene_queries.cpp, hits evaluated in
// ray_scene_evaluation.cpp.

#include "renderer/raytrace/ray_scene.h"

#include <algorithm>
#include <map>
#include <string>

#include "renderer/raytrace/motion.h"
#include "renderer/raytrace/ray_scene_impl.h"

namespace gonio {
namespace {

using Imath::M44f;

void ReportEmbreeError(void* userPtr, RTCError code, const char* message) {
    auto* diagnostics = static_cast<Diagnostics*>(userPtr);
    diagnostics->Error(FileLoc{}, "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                                      (message ? message : ""));
}

}  // namespace

RayScene::RayScene(const Frame& frame, Diagnostics& diagnostics, Traversal traversal)
    : impl_(std::make_unique<Impl>(diagnostics)) {
    Impl& s = *impl_;
    s.sceneFlags = traversal == Traversal::kRobust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
    s.colorComponents = frame.options.colorComponents;
    s.shutterOpen = frame.options.shutterOpen;
    s.shutterClose = std::max(frame.options.shutterClose, frame.options.shutterOpen);
    // A frame with nothing in it (start-up benchmarks, a scene still being written) needs no
    // Embree: its device and an empty scene's commit start oneTBB's workers and allocator, the
    // larger part of such a render's time. Every ray then misses (Trace, Occluded).
    if (frame.shapes.empty() && frame.instances.empty() && frame.lazyProcedurals.All().empty())
        return;
    s.device = rtcNewDevice(nullptr);
    rtcSetDeviceErrorFunction(s.device, ReportEmbreeError, &diagnostics);
    s.top.scene = rtcNewScene(s.device);
    rtcSetSceneFlags(s.top.scene, s.sceneFlags);
    if (!frame.solids.empty()) {
        s.solids.scene = rtcNewScene(s.device);
        rtcSetSceneFlags(s.solids.scene, s.sceneFlags);
        s.trees = std::make_unique<SolidTrees>(frame.solids);
    }
    for (const SceneShape& shape : frame.shapes) {
        if (shape.solid >= 0) {
            // The builder keeps solids' surfaces static (builder_solids.cpp).
            s.AddShape(s.solids, shape, shape.worldFromObject);
        } else if (shape.worldFromObjectMotion.empty()) {
            s.AddShape(s.top, shape, shape.worldFromObject);
        } else {
            // A moving shape is placed like an object instance whose placement moves.
            s.Place(s.NewLevel({&shape}, true), M44f(), nullptr, shape.motionTimes,
                    shape.worldFromObjectMotion);
        }
    }
    // Each object definition becomes one Embree scene, placed by instance geometries.
    std::map<const ObjectDefinition*, int> levelOf;
    for (const ObjectInstanceUse& use : frame.instances) {
        auto it = levelOf.find(use.definition.get());
        if (it == levelOf.end()) {
            std::vector<const SceneShape*> shapes;
            for (const SceneShape& shape : use.definition->shapes) shapes.push_back(&shape);
            it = levelOf.emplace(use.definition.get(), s.NewLevel(shapes, false)).first;
        }
        s.Place(it->second, use.worldFromDefinition, &use, use.motionTimes,
                use.worldFromDefinitionMotion);
    }
    rtcCommitScene(s.top.scene);
    if (s.solids.scene) rtcCommitScene(s.solids.scene);
    if (!frame.lazyProcedurals.All().empty()) s.WatchLazyProcedurals(frame.lazyProcedurals);
}

int RayScene::Impl::NewLevel(const std::vector<const SceneShape*>& shapes, bool inObjectSpace) {
    SceneLevel level;
    level.scene = rtcNewScene(device);
    rtcSetSceneFlags(level.scene, sceneFlags);
    for (const SceneShape* shape : shapes)
        AddShape(level, *shape, inObjectSpace ? M44f() : shape->worldFromObject);
    rtcCommitScene(level.scene);
    definitions.push_back(std::move(level));
    return static_cast<int>(definitions.size()) - 1;
}

void RayScene::Impl::Place(int level, const M44f& worldFromDefinition, const ObjectInstanceUse* use,
                           const std::vector<float>& motionTimes, const std::vector<M44f>& motion) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, definitions[level].scene);
    // Imath's row-vector matrix, read column-major, is the column-vector matrix Embree wants.
    if (motion.empty()) {
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                                worldFromDefinition.getValue());
    } else {
        // Embree's time steps divide its time [0, 1], which is our shutter interval.
        const unsigned steps = std::max<unsigned>(2, motion.size());
        rtcSetGeometryTimeStepCount(g, steps);
        for (unsigned i = 0; i < steps; ++i) {
            const float time = shutterOpen + (shutterClose - shutterOpen) * i / (steps - 1);
            rtcSetGeometryTransform(g, i, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                                    TransformAt(motionTimes, motion, time).getValue());
        }
    }
    auto record = std::make_unique<GeometryRecord>();
    record->instance = static_cast<int>(instances.size());
    instances.push_back(
        {level, worldFromDefinition, worldFromDefinition.inverse(), use, motionTimes, motion});
    Attach(top, g, std::move(record));
}

RayScene::~RayScene() = default;

size_t RayScene::GeometryCount() const {
    size_t n = impl_->top.records.size() + impl_->solids.records.size();
    for (const SceneLevel& level : impl_->definitions) n += level.records.size();
    return n;
}

}  // namespace gonio
