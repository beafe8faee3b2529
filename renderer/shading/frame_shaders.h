#pragma once
// The shading-language side of one frame: the shading system with the frame's search path, one
// shader instance per distinct Surface/Displacement/Atmosphere request (shared by every
// primitive that uses it), and the light shaders. Built once per frame before rendering, then
// read-only, so that all threads share it.

#include <atomic>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "renderer/raytrace/area_light_geometry.h"
#include "renderer/raytrace/camera.h"
#include "renderer/scene/frame.h"
#include "renderer/shading/shader_needs.h"
#include "shaderlang/shading_system.h"

namespace gonio {

// The shaders one attribute state shades with.
struct ShaderGroup {
    std::shared_ptr<sl::ShaderInstance> surface;       // null: the default surface
    std::shared_ptr<sl::ShaderInstance> displacement;  // may be null
    std::shared_ptr<sl::ShaderInstance> atmosphere;    // may be null
    const ShaderInstance* surfaceRequest = nullptr;    // for "shader" space
    // Names of primitive variables bound to surface-shader parameters.
    std::vector<std::string> boundPrimvars;
    sl::ShaderNeeds needs;  // of the surface, displacement and atmosphere together
};

struct FrameLight {
    std::shared_ptr<sl::ShaderInstance> instance;  // null when the shader failed to load
    M44f currentFromShader;
    bool castsShadows = false;
    // An AreaLightSource's surface (null: a LightSource, or an area light without geometry,
    // which lights from the origin of its shader space) and its samples per shaded point.
    std::shared_ptr<const AreaLightGeometry> area;
    int samples = 1;
};

class FrameShaders {
  public:
    FrameShaders(const Frame& frame, Diagnostics& diagnostics);

    // The group of an attribute state seen in the frame (null if the frame never used it).
    const ShaderGroup* Group(const Attributes* attributes) const;
    const std::vector<FrameLight>& Lights() const { return lights_; }
    // Whether points of this group are shaded together with neighbour points (derivatives):
    // when its shaders take derivatives, or trace rays while some shader of the frame takes
    // them (the neighbours' traced rays are the ray differentials of the traced rays).
    bool WantsNeighbours(const ShaderGroup& group) const {
        return group.needs.derivatives || (group.needs.trace && anyTakesDerivatives_);
    }
    int TraceMaxDepth() const { return traceMaxDepth_; }  // shader_needs.h
    // Option "limits" "shadertimeout": seconds one shader run may take (0: no limit).
    double ShaderTimeout() const { return shaderTimeout_; }
    // Whether a shader run of this frame has run out of time (RenderContext::ShaderTimedOut).
    bool TimedOut() const { return timedOut_.load(std::memory_order_relaxed); }
    void NoteTimedOut() const { timedOut_.store(true, std::memory_order_relaxed); }
    const Frame& GetFrame() const { return frame_; }
    Diagnostics& GetDiagnostics() const { return diagnostics_; }
    // Camera ("current") space from world space.
    const M44f& CurrentFromWorld() const { return frame_.options.cameraFromWorld; }
    // Where texture(), environment() and brdf() look for relative file names.
    const std::vector<std::string>& TextureSearchPath() const { return texturePath_; }
    // Whether every primitive blocks shadow rays completely (shadow_transmission.h).
    bool AllShadowsOpaque() const { return allShadowsOpaque_; }

  private:
    std::shared_ptr<sl::ShaderInstance> Instance(const ShaderInstance& request,
                                                 sl::ShaderType expected);
    // Records the shaders of `shadedWith` and binds the shape's primitive variables to them.
    void AddShapeGroup(const SceneShape& shape, const Attributes& shadedWith);
    void AddAreaGeometry(const SceneLight& light, FrameLight* frameLight) const;

    const Frame& frame_;
    Diagnostics& diagnostics_;
    std::unique_ptr<sl::ShadingSystem> system_;
    Declarations declarations_;
    std::map<std::string, std::shared_ptr<sl::ShaderInstance>> instances_;  // by request text
    std::map<const Attributes*, ShaderGroup> groups_;
    std::vector<FrameLight> lights_;
    bool anyTakesDerivatives_ = false;
    bool allShadowsOpaque_ = true;
    int traceMaxDepth_ = kDefaultTraceMaxDepth;
    double shaderTimeout_ = 0;
    mutable std::atomic<bool> timedOut_{false};
    std::vector<std::string> texturePath_;
};

// The folder of the standard shaders that ship with gonio (the source tree's shaders/).
std::string DefaultShaderFolder();

// Where shaders are looked for: next to the scene, then among those that ship with gonio
// (Option "searchpath" "shader" changes it).
std::vector<std::string> ShaderSearchPath(const Frame& frame);

// Where textures and .grd files are looked for: the working folder, then the scene's folder
// (Option "searchpath" "texture" changes it).
std::vector<std::string> FrameTextureSearchPath(const Frame& frame);

// The instance a shader request names: the shader from `system`'s search path, checked to be of
// the `expected` type, with the request's parameters (point-like values move from shader space
// with `currentFromShader`). A missing shader, a wrong type and a parameter that does not match
// its declaration are reported at the request's RIB location; a bad parameter keeps its
// default, the other errors give null, as does an unset request.
std::shared_ptr<sl::ShaderInstance> LoadShaderInstance(
    sl::ShadingSystem& system, const ShaderInstance& request, sl::ShaderType expected,
    const M44f& currentFromShader, const Declarations& declarations, const Options& options,
    Diagnostics& diagnostics);

}  // namespace gonio
