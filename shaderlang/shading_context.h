#pragma once
// What the shading language asks of the renderer while a batch of points is shaded (OSL's
// RendererServices in spirit): coordinate spaces, lights, textures, traced rays, attributes and
// options. The renderer implements it; `gonio shade` implements a simple one for testing.
// Every method works on the whole batch; per-point data is component-major as in batch.h.

#include <Imath/ImathMatrix.h>

#include <string>
#include <vector>

#include "shaderlang/types.h"

namespace gonio::sl {

// One light as seen from a batch of surface points, after its light shader ran there.
struct LightResult {
    // Per point: L points from the surface point towards the light (the surface's view, as
    // inside illuminance), Cl and Ol the arriving colour and opacity (ncomps each).
    std::vector<float> L;      // 3 × n
    std::vector<float> Cl;     // ncomps × n
    std::vector<float> Ol;     // ncomps × n
    std::vector<uint8_t> lit;  // per point: 1 if the light's illuminate/solar reached it
    bool ambient = false;      // a light without illuminate or solar: only ambient() sees it
    std::string category;      // the light's __category parameter
    int shaderIndex = -1;      // which light shader instance, for lightsource() queries
};

class ShadingContext {
  public:
    virtual ~ShadingContext() = default;

    int PointCount() const { return n_; }
    int ColorComponents() const { return colorComponents_; }

    // The matrix that takes points from `space` to "current" space (RenderMan's camera space) at
    // point i. Spaces: "current", "camera", "world", "object", "shader", "screen", "raster",
    // "NDC", and CoordinateSystem names. False if the space is unknown.
    virtual bool CurrentFromSpace(const std::string& space, int point, Imath::M44f* m) const = 0;

    // The lights that illuminate the batch, evaluated at the current surface points with the
    // given (surface shader's) P; cached by the renderer so that several diffuse()/specular()/
    // illuminance uses in one shader run evaluate each light once.
    virtual const std::vector<LightResult>& Lights() = 0;

    // Filtered texture lookup of `channels` channels starting at `firstChannel`, per point, at
    // (s, t) with the four-corner footprint when ds/dt are given (may be null). Options are the
    // RSL texture parameters ("blur", "width", "filter", "fill", ...). Writes channels × n
    // floats to out (component-major). False (and black) if the texture cannot be read.
    virtual bool Texture(const std::string& name, int firstChannel, int channels, const float* s,
                         const float* t, const float* dsdx, const float* dtdx, const float* dsdy,
                         const float* dtdy, const uint8_t* active, float* out) = 0;
    virtual bool Environment(const std::string& name, int firstChannel, int channels,
                             const float* directions /* 3 × n */, const uint8_t* active,
                             float* out) = 0;
    virtual bool Shadow(const std::string& name, const float* points /* 3 × n */,
                        const uint8_t* active, float* out /* n */) = 0;

    // trace(P, R): colour arriving at each P from direction R (ncomps × n), by a traced ray.
    virtual void Trace(const float* P, const float* R, const uint8_t* active, float* out) = 0;

    // attribute(), option(), rendererinfo(): the value named `name` as `type` (floats or a
    // string); false if there is none of that type.
    virtual bool Attribute(const std::string& name, const TypeSpec& type, int point,
                           std::vector<float>* floats, std::string* text) const = 0;
    virtual bool Option(const std::string& name, const TypeSpec& type, std::vector<float>* floats,
                        std::string* text) const = 0;
    virtual bool RendererInfo(const std::string& name, const TypeSpec& type,
                              std::vector<float>* floats, std::string* text) const = 0;

    // Reports a run-time problem (division by zero, NaN, a missing texture) once per shader
    // source line; `message` without location, the context adds the shader's file:line.
    virtual void RuntimeWarning(const std::string& key, const std::string& message) = 0;

    // printf output.
    virtual void Print(const std::string& text) = 0;

    // Derivatives are differences over neighbouring points of the batch: for point i, the index
    // of the point one step along u (along v), or -1 when there is none (then the kernel uses
    // the opposite neighbour, or 0). The globals du and dv hold the steps.
    virtual const int* UNeighbours() const = 0;
    virtual const int* VNeighbours() const = 0;

  protected:
    int n_ = 0;
    int colorComponents_ = 3;
};

}  // namespace gonio::sl
