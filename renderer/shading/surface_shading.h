#pragma once
// How the render loop asks for the colour of surface points: in batches of points that share
// one attribute state (so one surface shader instance and one light list). The default surface
// and the shading language both implement it.

#include <Imath/ImathVec.h>

#include <memory>
#include <vector>

#include "render/surface_point.h"

namespace gonio {

struct ShadingBatch {
    const Attributes* attributes = nullptr;
    std::vector<const SurfacePoint*> points;
    std::vector<Imath::V3f> incident;  // I: from the eye to each point (world space)
    std::vector<float> depth;          // camera-space z of each point
};

// Per-thread shading state (shader registers, light caches); not shared between threads.
class ShadingWorker {
  public:
    virtual ~ShadingWorker() = default;
    // Writes ncomps floats of Ci and of Oi per point, point-major: Ci[i * ncomps + c]. Ci is
    // premultiplied by Oi, as RenderMan surface shaders leave it.
    virtual void Shade(const ShadingBatch& batch, float* Ci, float* Oi) = 0;
};

class SurfaceShading {
  public:
    virtual ~SurfaceShading() = default;
    virtual std::unique_ptr<ShadingWorker> MakeWorker() const = 0;
};

// The default surface of primitives without a Surface shader: a squared facing ratio,
// Ci = Os·Cs·(Ka + Kd·(N·I)²) with Ka = 0.2, Kd = 0.8 and N, I unit vectors, as Aqsis's
// defaultsurface (RISpec leaves the default surface to the implementation).
std::unique_ptr<SurfaceShading> MakeDefaultSurfaceShading(int colorComponents);

}  // namespace gonio

namespace gonio {

class RayScene;
class Camera;
class Diagnostics;

// Shading by the frame's shading-language shaders (Surface, Displacement, Atmosphere and the
// light shaders); attribute states without a Surface use the default surface.
std::unique_ptr<SurfaceShading> MakeShaderShading(const Frame& frame, const RayScene& scene,
                                                  const Camera& camera, Diagnostics& diagnostics);

}  // namespace gonio
