#pragma once
// What the pieces of RayScene share (ray_scene.cpp, ray_scene_geometry.cpp,
// ray_scene_queries.cpp, ray_scene_evaluation.cpp, ray_scene_lazy.cpp): the private Impl and the
// records it keeps for each Embree geometry. Only those files include it, and with it Embree
// (STYLE.md habit 3).

#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "renderer/raytrace/ray_scene.h"
#include "renderer/raytrace/shape_evaluation.h"
#include "renderer/raytrace/solid_tree.h"

namespace gonio {

// RayHit::instID of a hit on a solid's surface, which lies in Impl::solids, not in `top`.
constexpr unsigned kSolidLevel = RTC_INVALID_GEOMETRY_ID - 1;
// Crossings of solids' surfaces one ray collects at most; a ray through more sees the rest as
// empty space.
constexpr size_t kMaxSolidCrossings = 1024;

// A quadric placed in a scene: Embree user geometry calls back into it.
struct QuadricGeometry {
    const Quadric* quadric;
    M44f objectFromSpace;
    M44f spaceFromObject;
    // objectFromSpace only moves (its linear part is exactly the identity), as the transform of
    // most quadrics does: the callback then only adds the offset, with the same result.
    bool translationOnly;
    const CompleteSphere* sphere;  // quadric->AsCompleteSphere()
};

// What we keep for each Embree geometry, to evaluate its hits.
struct GeometryRecord {
    const SceneShape* shape = nullptr;  // null for an instance
    M44f spaceFromObject, objectFromSpace;
    PrimVarSet meshVars;  // a TriangleMesh's variables as classes
    const PrimVarSet* vars = nullptr;
    std::unique_ptr<QuadricGeometry> quadric;
    RTCGeometry geometry = nullptr;  // kept for rtcInterpolate on subdivision surfaces
    int instance = -1;               // index into Impl::instances for instance geometries
    // Subdivision surfaces: the vertex-attribute slot of each vertex, varying or facevarying
    // variable (by index into *vars), -1 for the others.
    std::vector<int> attributeSlot;
    // Indices into *vars of the standard variables, -1 when absent.
    int cs = -1, os = -1, st = -1, s = -1, t = -1;
    int quadricN = -1;  // a quadric's N (the one EvaluateQuadricAt interpolates)
    // A triangle mesh whose normal is Embree's Ng, or a quadric whose normal is that of its
    // implicit equation, and whose colour is its attributes' (no N, no Cs primitive
    // variable): EvaluateLean needs nothing else.
    bool flatMesh = false;
    bool plainQuadric = false;
    // A still triangle mesh without normals: its object-space face normal (p1 − p0) × (p2 − p0)
    // carried into the record's space (the inverse transpose) points along Embree's Ng, the
    // same cross product of the vertices as built there, times this sign: +1, or −1 where
    // spaceFromObject mirrors (the cross product of mirrored edges turns round, the inverse
    // transpose does not). 0 for every other shape, whose normal Evaluate derives itself.
    float embreeNgSign = 0;
};

struct SceneLevel {
    RTCScene scene = nullptr;
    std::vector<std::unique_ptr<GeometryRecord>> records;  // indexed by geomID
};

struct InstancePlacement {
    int level;  // index into Impl::definitions
    M44f worldFromDefinition, definitionFromWorld;
    const ObjectInstanceUse* use;  // null for a moving shape placed on its own
    // A moving placement: worldFromDefinition at these times.
    std::vector<float> motionTimes;
    std::vector<M44f> motion;
};

struct RayScene::Impl {
    Diagnostics& diagnostics;
    int colorComponents;
    std::vector<float> defaultCs, defaultOs;
    RTCDevice device = nullptr;
    SceneLevel top;
    // The surfaces of solids (Frame::solids) in world space, apart from `top`: a ray finds its
    // crossings with them here and SolidTrees combines them. Null scene: the frame has none.
    SceneLevel solids;
    std::unique_ptr<SolidTrees> trees;
    std::vector<SceneLevel> definitions;
    std::vector<InstancePlacement> instances;
    // The bounds of the archives not read (Frame::lazyProcedurals); null scene: none.
    RTCScene lazyScene = nullptr;

    RTCSceneFlags sceneFlags = RTC_SCENE_FLAG_ROBUST;  // of every Embree scene it makes
    explicit Impl(Diagnostics& d) : diagnostics(d) {}
    ~Impl() {
        for (SceneLevel& level : definitions) rtcReleaseScene(level.scene);
        if (top.scene) rtcReleaseScene(top.scene);
        if (solids.scene) rtcReleaseScene(solids.scene);
        if (lazyScene) rtcReleaseScene(lazyScene);
        if (device) rtcReleaseDevice(device);
    }

    void AddShape(SceneLevel& level, const SceneShape& shape, const M44f& spaceFromObject);
    // The archives out of view, one Embree user primitive each (ray_scene_lazy.cpp), and the
    // marking of those a ray segment passes through.
    void WatchLazyProcedurals(const LazyProcedurals& lazy);
    void MarkLazyProcedurals(const V3f& org, const V3f& dir, float tnear, float tfar,
                             float time) const;
    void Place(int level, const M44f& worldFromDefinition, const ObjectInstanceUse* use,
               const std::vector<float>& motionTimes, const std::vector<M44f>& motion);
    // A scene of its own for shapes placed by Place: in their definition space, or, for one
    // moving shape (`inObjectSpace`), in its object space.
    int NewLevel(const std::vector<const SceneShape*>& shapes, bool inObjectSpace);
    float EmbreeTime(float time) const {
        return shutterClose > shutterOpen ? (time - shutterOpen) / (shutterClose - shutterOpen)
                                          : 0.f;
    }
    float shutterOpen = 0, shutterClose = 0;
    RTCRay MakeRay(const V3f& org, const V3f& dir, float tnear, float tfar, float time) const {
        RTCRay ray;
        ray.org_x = org.x, ray.org_y = org.y, ray.org_z = org.z;
        ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
        ray.tnear = tnear;
        ray.tfar = tfar;
        ray.time = EmbreeTime(time);
        ray.mask = ~0u;
        ray.id = 0;
        ray.flags = 0;
        return ray;
    }
    // A deforming mesh or cage: its vertex buffer at each of Embree's time steps, which divide
    // the shutter interval. `floatsPerVertex` is 3, or 4 for subdivision (see MakeSubdivision).
    void SetDeformationSteps(RTCGeometry g, const SceneShape& shape, const M44f& m,
                             unsigned floatsPerVertex) const;
    void Attach(SceneLevel& level, RTCGeometry geometry, std::unique_ptr<GeometryRecord> record);
    RTCGeometry MakeMesh(const TriangleMesh& mesh, const M44f& m);
    RTCGeometry MakeQuadric(GeometryRecord& record, const QuadricShape& shape);
    RTCGeometry MakeSubdivision(GeometryRecord& record, const SubdivisionCage& cage, const M44f& m);
    RTCGeometry MakeCurves(const CurveSet& curves, const M44f& m);
    RTCGeometry MakePoints(const PointSet& points, const M44f& m);
    ObjectHit EvaluateSubdivision(const GeometryRecord& record, const RayHit& hit,
                                  const V3f& objectP) const;
    // worldP, worldDir: the hit point and the ray's direction, which spaceFromWorld takes to
    // the record's space.
    ObjectHit EvaluateObject(const GeometryRecord& record, const RayHit& hit, const V3f& worldP,
                             const V3f& worldDir, const M44f& spaceFromWorld) const;
    // The record of a hit's geometry, its attributes (an instance's for the shape, or the
    // shape's own) and the instance that placed it (null at the top level).
    struct ResolvedHit {
        const GeometryRecord* record;
        const Attributes* attributes;
        const InstancePlacement* placement;
    };
    ResolvedHit Resolve(const RayHit& hit) const;
    // The nearest hit in one level's Embree scene (`top` or `solids`).
    bool Trace(const SceneLevel& level, const V3f& org, const V3f& dir, float tnear, float tfar,
               float time, RayHit* hit) const;
    // Embree's hit of a ray found in `level` as a RayHit (Trace and IntersectCoherent).
    void MakeHit(const SceneLevel& level, float tfar, float time, unsigned geomID, unsigned primID,
                 unsigned instID, float u, float v, const V3f& ng, RayHit* hit) const;
    // The nearest point of a combined solid's surface within [tnear, tfar].
    bool IntersectSolids(const V3f& org, const V3f& dir, float tnear, float tfar, float time,
                         RayHit* hit) const;
    // Whether a ray enters the surface it crossed at `hit` (a hit in `solids`).
    bool Enters(const RayHit& hit, const V3f& org, const V3f& dir) const;
    // The hit geometry's record alone (Resolve without the attributes).
    const GeometryRecord& RecordOf(const RayHit& hit) const;
    // The transforms between the world and the space the hit's geometry was built in (the
    // world itself at the top level, an object definition's space in an instance).
    static void SpaceTransforms(const InstancePlacement* placement, float time,
                                M44f* worldFromSpace, M44f* spaceFromWorld);
};

// Inline: every camera hit resolves its record.
inline const GeometryRecord& RayScene::Impl::RecordOf(const RayHit& hit) const {
    if (hit.instID == RTC_INVALID_GEOMETRY_ID) return *top.records[hit.geomID];
    if (hit.instID == kSolidLevel) return *solids.records[hit.geomID];
    const InstancePlacement& placement = instances[top.records[hit.instID]->instance];
    return *definitions[placement.level].records[hit.geomID];
}

inline RayScene::Impl::ResolvedHit RayScene::Impl::Resolve(const RayHit& hit) const {
    const GeometryRecord* record = &RecordOf(hit);
    if (hit.instID == RTC_INVALID_GEOMETRY_ID || hit.instID == kSolidLevel)
        return {record, record->shape->attributes.get(), nullptr};
    const InstancePlacement& placement = instances[top.records[hit.instID]->instance];
    const Attributes* attributes = record->shape->attributes.get();
    if (const ObjectInstanceUse* use = placement.use)
        attributes = use->shapeAttributes[record->shape - use->definition->shapes.data()].get();
    return {record, attributes, &placement};
}

}  // namespace gonio
