#pragma once
// What the shading stage knows about a ray hit: the differential geometry in world space and the
// interpolated standard primitive variables, plus the shape so that the shading language can
// fetch any user primitive variable by name.

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <cstdint>
#include <vector>

#include "renderer/raytrace/shape_evaluation.h"
#include "renderer/scene/frame.h"

namespace gonio {

struct GeometryRecord;  // ray_scene_impl.h's record of an Embree geometry

struct SurfacePoint {
    Imath::V3f P, N, Ng, dPdu, dPdv;  // world space; N and Ng unit length, facing "outside"
    float u = 0, v = 0, s = 0, t = 0;
    std::vector<float> Cs, Os;  // ncomps values each
    const SceneShape* shape = nullptr;
    // The attributes the point is shaded with: the shape's, or an object instance's.
    const Attributes* attributes = nullptr;
    Imath::M44f worldFromObject;  // including an object instance's placement

    // Where the hit lies, so that RayScene::InterpolatePrimVar can fetch any primitive variable.
    const GeometryRecord* record = nullptr;
    unsigned primID = 0;
    float hitU = 0, hitV = 0;
    ClassStencils stencils;
    // What a camera hit (RayScene::EvaluateGeometry) leaves to FinishEvaluate, which only the
    // hits that are shaded get: u, v, dPdu, dPdv and the interpolation stencils, from objectP
    // for a sphere (whose normals came from the point alone), from primID, hitU and hitV for a
    // mesh.
    enum class Pending : uint8_t { kNothing, kQuadric, kMesh };
    Pending pending = Pending::kNothing;
    Imath::V3f objectP;
};

}  // namespace gonio
