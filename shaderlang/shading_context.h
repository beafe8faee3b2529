#pragma once
// What the shading language asks of the renderer while a batch of points is shaded (OSL's
// RendererServices in spirit): coordinate spaces, lights, textures, traced rays, attributes and
// options. The renderer implements it; `gonio shade` implements a simple one for testing.
// Every method works on the whole batch; per-point data is component-major as in batch.h.
// Spaces, neighbours and warnings are every context's own; the rest has a default (no lights,
// no attributes, and textures, shadows, traced rays and measured BRDFs that give 0 with a
// warning), so that a context overrides only what it has.

#include <Imath/ImathMatrix.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/file_loc.h"
#include "base/hash.h"
#include "base/texture_wrap.h"
#include "shaderlang/runtime/batch.h"
#include "shaderlang/types.h"

namespace gonio::sl {

struct RayBuiltinState;  // runtime/builtins_raytrace.cpp

// Message passing (RISpec §15.8): the shader whose parameters surface(), displacement(),
// atmosphere() and lightsource() read.
enum class MessageSource : uint8_t { Surface, Displacement, Atmosphere, Light };

// A parameter of another shader as message passing reads it: numbers (one element when the
// parameter is uniform, else planes of PointCount() floats, batch.h layout) or a string.
struct MessageValue {
    TypeSpec type;
    FloatArg floats;                    // data == nullptr for a string
    const std::string* text = nullptr;  // a string parameter's value
};

// One light as seen from a batch of surface points, after its light shader ran there.
struct LightResult {
    // Per point: L points from the surface point towards the light (the surface's view, as
    // inside illuminance), Cl and Ol the arriving colour and opacity (ncomps each).
    std::vector<float> L;      // 3 × n
    std::vector<float> Cl;     // ncomps × n
    std::vector<float> Ol;     // ncomps × n
    std::vector<uint8_t> lit;  // per point: 1 if the light's illuminate/solar reached it
    // Empty, or per point 1 where solar() without an axis lit it: light from all directions,
    // with no L of its own (L is 0); the surface side takes L along its axis (see OpIllumNext).
    std::vector<uint8_t> fromAllDirections;
    bool ambient = false;     // a light without illuminate or solar: only ambient() sees it
    bool atInfinity = false;  // lit by solar(): L is a direction, the light infinitely far
    std::string category;     // the light's __category parameter
    int shaderIndex = -1;     // which light shader instance, for lightsource() queries

    // The light shader's parameters as it left them, for lightsource(); the renderer fills
    // them only for batches whose shaders call lightsource().
    struct Parameter {
        std::string name;
        TypeSpec type;
        bool varying = false;
        int width = 0;              // floats per point
        std::vector<float> floats;  // width floats (uniform) or width planes of n
        std::string text;
    };
    std::vector<Parameter> parameters;

    // The parameter `name` as a MessageValue over n points; false if the light has none.
    bool FindParameter(const std::string& name, int n, MessageValue* value) const {
        for (const Parameter& p : parameters) {
            if (p.name != name) continue;
            value->type = p.type;
            value->text = p.type.base == BaseType::String ? &p.text : nullptr;
            value->floats = FloatArg{};
            if (!value->text)
                value->floats =
                    FloatArg{const_cast<float*>(p.floats.data()), p.width, p.varying, n};
            return true;
        }
        return false;
    }
};

// shadow()'s optional parameters (RISpec §15.7.3, with PRMan's and Pixie's names), uniform per
// call: "samples", "width"/"swidth"/"twidth" (scale the point's footprint in the map),
// "blur"/"sblur"/"tblur" (add to the filter region, as fractions of the map) and "bias" (depth
// offset; negative: the renderer's default).
struct ShadowOptions {
    float samples = 16;
    float swidth = 1, twidth = 1, sblur = 0, tblur = 0;
    float bias = -1;
};

// Rays that occlusion(), indirectdiffuse(), gather(), transmission() and visibility() sample
// (builtins_raytrace.cpp): `count` rays, each from org along dir, in current space.
struct SampledRays {
    enum class Kind : uint8_t {
        AnyHit,        // whether anything lies within [bias, maxdist]: hit only
        FirstHit,      // the nearest hit within [bias, maxdist]: hit, t, P, N
        Shaded,        // FirstHit, and the colour arriving along the ray, as trace() brings it
        Transmission,  // the product of (1 - Os) of every surface within [bias, maxdist]
    };
    Kind kind = Kind::FirstHit;
    int count = 0;
    const float* org = nullptr;      // 3 × count (component-major)
    const float* dir = nullptr;      // 3 × count, unit length
    const int* point = nullptr;      // count: the batch point each ray starts from
    const float* maxdist = nullptr;  // count: where each ray ends (current-space distance)
    // count: where each ray starts (current-space distance); a negative value asks for the
    // renderer's own self-hit offset (trace()'s).
    const float* bias = nullptr;
};

struct SampledHits {
    std::vector<uint8_t> hit;   // count: 1 where the ray hit something within its range
    std::vector<float> t;       // count: distance to the hit (current space)
    std::vector<float> P, N;    // 3 × count: the hit point and its normal (current space)
    std::vector<float> colour;  // ncomps × count: Shaded's colour, Transmission's product
};

// A named channel of per-point values, as bake3d() stores and texture3d() looks them up:
// `width` floats per point in `values` (batch.h layout; bake3d's may be uniform).
struct PointChannel {
    std::string name;
    int width = 0;
    FloatArg values;
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
    virtual const std::vector<LightResult>& Lights();

    // The lights evaluated at other positions `P` (3 × n, current space; light shaders see them
    // as Ps): illuminance(P', ...) with P' other than the surface's P (RISpec §13.3.1: the
    // position is where light is gathered). Only the `active` points (nullptr: all) matter.
    // Not cached: the interpreter calls it only when P' differs from P. The default suits
    // contexts whose lights do not depend on position (none at all, or fixed test lights).
    virtual const std::vector<LightResult>& LightsAt(const float* P, const uint8_t* active) {
        (void)P, (void)active;
        return Lights();
    }

    // Filtered texture lookup of `channels` channels starting at `firstChannel`, per point, at
    // (s, t) with the four-corner footprint when ds/dt are given (may be null), s and t outside
    // [0, 1] wrapped as the "swrap"/"twrap"/"wrap" parameters say (Default: as the file
    // records). Writes channels × n floats to out (component-major). False (and black) if the
    // texture cannot be read; the context then reports why through RuntimeWarning.
    virtual bool Texture(const std::string& name, int firstChannel, int channels,
                         const TextureWrapModes& wrap, const float* s, const float* t,
                         const float* dsdx, const float* dtdx, const float* dsdy, const float* dtdy,
                         const uint8_t* active, float* out);
    virtual bool Environment(const std::string& name, int firstChannel, int channels,
                             const float* directions /* 3 × n */, const uint8_t* active,
                             float* out);
    // shadow(): the fraction of each point in shadow in the shadow map `name` (0 lit, 1 in
    // shadow), filtered as `options` say.
    virtual bool Shadow(const std::string& name, const float* points /* 3 × n */,
                        const uint8_t* active, const ShadowOptions& options, float* out /* n */);

    // The file a texture-like name refers to (texture(), environment(), brdf()), looked up on
    // the renderer's texture search path; the name itself where there is no such path.
    virtual std::string FindTexture(const std::string& name) const { return name; }

    // brdf(): the measured BRDF in the file `name` (a .grd, found like a texture) for light
    // arriving from wIn and leaving towards wOut (3 × count each, unit, in the BRDF's local frame:
    // z the normal, x the direction of anisotropy), at each active point of `count`: ncomps ×
    // count floats into out. Directions at or below the surface give 0. False (and black) if
    // the file cannot be used; the context reports why through RuntimeError. The default
    // knows no BRDF files.
    virtual bool MeasuredBrdf(const std::string& name, int count, const float* wIn,
                              const float* wOut, const uint8_t* active, float* out);

    // bake3d() (PRMan's point clouds): stores each active point's P and N (3 × n, current
    // space) with the channels' values in the point cloud `file`, which the renderer writes
    // when the frame ends. False (with a warning) where nothing is stored; the default stores
    // nothing.
    virtual bool BakePoints(const std::string& file, const float* P, const float* N,
                            const uint8_t* active, const std::vector<PointChannel>& channels);
    // texture3d(): writes into each channel's values (varying) the values of the point of the
    // point cloud `file` nearest to each active P (current space). False (and 0) if the file
    // cannot be read or lacks a channel; the context reports why through RuntimeWarning.
    virtual bool LookupPoints(const std::string& file, const float* P, const float* N,
                              const uint8_t* active, const std::vector<PointChannel>& channels);

    // trace(P, R): colour arriving at each P from direction R (ncomps × n), by a traced ray.
    virtual void Trace(const float* P, const float* R, const uint8_t* active, float* out);

    // The ray-traced built-ins' rays (see SampledRays): fills `hits` and returns true, or
    // returns false where there is no scene to trace (`gonio shade`, imagers); the default
    // warns once that `what` gives 0 here.
    virtual bool TraceSampledRays(const std::string& what, const SampledRays& rays,
                                  SampledHits* hits);
    // Whether the hits of Kind::Shaded rays would be shaded here: false past the ray depth the
    // renderer allows (Attribute "trace" "maxdiffusedepth"), where indirectdiffuse() then
    // gives 0 without tracing its rays.
    virtual bool ShadesSampledRays() const { return true; }
    // The points whose ray-traced results are computed: a point i >= MainPointCount() shares
    // the result of point i % MainPointCount() (a ray tracer's neighbour points, which lie a
    // pixel away, share their hit's rays as they share its lights).
    virtual int MainPointCount() const { return n_; }
    // The width of a pixel at current-space point P (the size "samplebase" jitters ray
    // origins over); 0 where there are no pixels.
    virtual float PixelWidth(const Imath::V3f& P) const {
        (void)P;
        return 0;
    }

    // Scratch that the ray-traced built-ins keep between calls in one shader run (each gather
    // loop's samples, runtime/builtins_gather.cpp); theirs to define.
    std::shared_ptr<RayBuiltinState>& RayState() { return rayState_; }

    // attribute(), option(), rendererinfo(): the value named `name` as `type` (floats or a
    // string); false if there is none of that type.
    // The defaults know none, but rendererinfo("renderer") is "gonio".
    virtual bool Attribute(const std::string& name, const TypeSpec& type, int point,
                           std::vector<float>* floats, std::string* text) const;
    virtual bool Option(const std::string& name, const TypeSpec& type, std::vector<float>* floats,
                        std::string* text) const;
    virtual bool RendererInfo(const std::string& name, const TypeSpec& type,
                              std::vector<float>* floats, std::string* text) const;

    // surface(), displacement(), atmosphere(): the parameter `name` of the batch's shader of
    // that kind as that shader left it at these points (or as it stands while it runs). The
    // shaders run displacement, surface, atmosphere: a shader that has not run yet, or is
    // absent, gives false.
    virtual bool ShaderParameter(MessageSource, const std::string&, MessageValue*) const {
        return false;
    }

    // textureinfo(): the fact `dataname` ("resolution", "channels", "type", "viewingmatrix",
    // "projectionmatrix") of the texture file `name`; false if the file cannot be read or has
    // no such fact.
    virtual bool TextureInfo(const std::string&, const std::string&, std::vector<float>*,
                             std::string*) {
        return false;
    }

    // random(): the next 64 random bits of point i's own stream. The renderer seeds each
    // point's stream from its pixel, sample and the render's seed (SeedRandom), so an image
    // is the same whatever the thread count; unseeded points use their index.
    uint64_t NextRandomBits(int point) {
        if (randomState_.size() < size_t(n_)) SeedRandom(nullptr);
        uint64_t& state = randomState_[size_t(point)];
        return SplitMix64(state);
    }
    // A uniform random() (one value for all points of a run): the next 64 bits of the run's
    // own stream, seeded from all its points' seeds, so it too is the same whatever the thread
    // count.
    uint64_t NextUniformRandomBits() {
        if (randomState_.size() < size_t(n_)) SeedRandom(nullptr);
        return SplitMix64(uniformRandomState_);
    }

    // Reports a run-time problem (division by zero, NaN, a missing texture) once per `key` and
    // shader statement; `message` without location: the context adds Statement().
    virtual void RuntimeWarning(const std::string& key, const std::string& message) = 0;
    // Seconds one run of a shader may take before it is stopped (an endless loop); 0: no limit.
    virtual double ShaderTimeout() const { return 0; }
    // A run was stopped after `budget` seconds: a RuntimeError at the current statement.
    virtual void ShaderTimedOut(double budget);
    // True once a run has timed out and the picture has failed: later runs stop at their first
    // budget check instead of running out their own budget.
    virtual bool ShadersStopped() const { return false; }

    // The same as RuntimeWarning for a problem that makes the picture wrong (a brdf() file that
    // cannot be used): a renderer fails the frame. By default a warning, for contexts that make no
    // picture.
    virtual void RuntimeError(const std::string& key, const std::string& message) {
        RuntimeWarning(key, message);
    }

    // The shader statement being run ("file.sl:12"), set by the interpreter before each
    // built-in call and warning, so that run-time warnings name the shader's line; empty
    // outside shader code.
    void SetStatement(const std::string* where) { statement_ = where; }
    const std::string& Statement() const {
        static const std::string kNone;
        return statement_ ? *statement_ : kNone;
    }

    // printf output; the default writes to stdout, one whole text at a time.
    virtual void Print(const std::string& text);

    // Derivatives are differences over neighbouring points of the batch: for point i, the index
    // of a neighbouring point in each of two independent directions, or -1 when there is none
    // (then the kernels use the point whose neighbour it is, or 0).
    virtual const int* UNeighbours() const = 0;
    virtual const int* VNeighbours() const = 0;
    // How far the neighbours lie in (u, v): 4 planes of n floats, the change of (u, v) from
    // point i to UNeighbours()[i] (planes 0, 1) and to VNeighbours()[i] (planes 2, 3); Du and Dv
    // then solve for the parametric derivatives. nullptr: the neighbours are one step along u
    // and one along v, as on a grid, and the globals du and dv hold the steps. A ray tracer's
    // neighbours lie a pixel away along x and y, in any direction of (u, v).
    virtual const float* NeighbourSteps() const { return nullptr; }

  protected:
    // Zeroes `channels` × n floats of `out` and warns that `what` gives 0 in this context.
    bool Unavailable(const std::string& what, int channels, float* out);
    // One seed per point (PointCount() of them), or nullptr: each point's index.
    void SeedRandom(const uint64_t* seeds) {
        randomState_.resize(size_t(n_));
        // The run's stream starts apart from every point's (whose state is MixBits(seed)).
        uniformRandomState_ = kSplitMix64Step;
        for (int i = 0; i < n_; ++i) {
            randomState_[i] = MixBits(seeds ? seeds[i] : uint64_t(i) + 1);
            uniformRandomState_ = MixBits(uniformRandomState_ ^ randomState_[i]);
        }
    }
    int n_ = 0;
    int colorComponents_ = 3;
    std::vector<uint64_t> randomState_;
    uint64_t uniformRandomState_ = 0;

  private:
    std::shared_ptr<RayBuiltinState> rayState_;
    const std::string* statement_ = nullptr;
};

// The location a statement string ("file.sl:12") names, for diagnostics; `fallbackFile` when
// there is no statement.
FileLoc StatementLoc(const std::string& statement, const std::string& fallbackFile);

}  // namespace gonio::sl
