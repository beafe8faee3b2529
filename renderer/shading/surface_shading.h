#pragma once
// How the render loop asks for the colour of surface points: in batches of points that share
// one attribute state (so one surface shader instance and one light list). The default surface
// and the shading language both implement it.

#include <Imath/ImathVec.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/raytrace/ray_counts.h"
#include "renderer/raytrace/surface_point.h"

namespace gonio {

class Diagnostics;

// The rays one pixel away from a point's ray along raster x and y (ray differentials as whole
// rays), in world space. Shaders that take derivatives (Du, area, texture footprints, ...) are
// run on the points these rays hit too, as the neighbours of the point (shader_shading.cpp).
struct NeighbourRays {
    Imath::V3f org[2], dir[2];
    float tnear = 0;  // where the point's own ray started looking (past transparent layers)
    float time = 0;
};

// An arbitrary output variable (AOV): a Display whose mode names a shader variable, an output
// parameter of the surface shader or a global ("N", "Cs", "Oi", ...), with its floats per point.
struct ShaderOutput {
    std::string name;
    int width = 1;
    bool isColor = false;  // channels name.r, name.g, ... rather than name.x, name.y, ...
};

struct ShadingBatch {
    const Attributes* attributes = nullptr;
    std::vector<const SurfacePoint*> points;
    std::vector<Imath::V3f> incident;  // I: from the ray's origin (the eye) to each point (world)
    std::vector<float> depth;          // camera-space z of each point
    // Empty, or one per point when the worker WantsNeighbourRays for these attributes.
    std::vector<NeighbourRays> neighbourRays;
    // Empty, or one per point: the seed of the point's random() stream, from its pixel, sample
    // and the render's seed, so that random() does not depend on threads.
    std::vector<uint64_t> randomSeeds;
    // The AOVs wanted (null: none) and where they go: per point the sum of their widths in
    // floats, point-major, in the order of `outputs`. A point whose shader lacks one keeps 0.
    const std::vector<ShaderOutput>* outputs = nullptr;
    float* outputValues = nullptr;
};

// Per-thread shading state (shader registers, light caches); not shared between threads.
class ShadingWorker {
  public:
    virtual ~ShadingWorker() = default;
    // Writes ncomps floats of Ci and of Oi per point, point-major: Ci[i * ncomps + c]. Ci is
    // premultiplied by Oi, as RenderMan surface shaders leave it.
    virtual void Shade(const ShadingBatch& batch, float* Ci, float* Oi) = 0;
    // Whether Shade wants ShadingBatch::neighbourRays for points with these attributes (their
    // shaders take derivatives, or trace rays to surfaces that do).
    virtual bool WantsNeighbourRays(const Attributes*) const { return false; }
    // The rays this worker's shading has traced so far (shadows, trace(), ...), for --stats.
    const RayCounts& Rays() const { return rays_; }

  protected:
    RayCounts rays_;
};

class SurfaceShading {
  public:
    virtual ~SurfaceShading() = default;
    virtual std::unique_ptr<ShadingWorker> MakeWorker() const = 0;
    // Fills the width and kind of the AOV output->name; false when no shader of the frame has
    // it.
    virtual bool DescribeOutput(ShaderOutput*) const { return false; }
    // After the last batch of the frame: writes what the shaders baked (bake3d()); false, with
    // the errors reported, if a file could not be written.
    virtual bool FinishFrame(Diagnostics&) { return true; }
};

// The default surface of primitives without a Surface shader: a squared facing ratio,
// Ci = Os·Cs·(Ka + Kd·(N·I)²) with Ka = 0.2, Kd = 0.8 and N, I unit vectors, as Aqsis's
// defaultsurface (RISpec leaves the default surface to the implementation).
std::unique_ptr<SurfaceShading> MakeDefaultSurfaceShading(int colorComponents);

}  // namespace gonio

namespace gonio {

class RayScene;
class Camera;

// Shading by the frame's shading-language shaders (Surface, Displacement, Atmosphere and the
// light shaders); attribute states without a Surface use the default surface.
std::unique_ptr<SurfaceShading> MakeShaderShading(const Frame& frame, const RayScene& scene,
                                                  const Camera& camera, Diagnostics& diagnostics);

}  // namespace gonio
