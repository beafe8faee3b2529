#include "renderer/shading/render_context.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "base/hash.h"
#include "renderer/raytrace/shadow_transmission.h"
#include "renderer/shading/option_query.h"
#include "renderer/shading/shading_files.h"

namespace gonio {
namespace {

V3f ToV3(const float* data, int n, int i) { return V3f(data[i], data[n + i], data[2 * n + i]); }

}  // namespace

RenderContext::RenderContext(const FrameShaders& shaders, const RayScene& scene,
                             const Camera& camera, ShadingFiles& textures,
                             sl::ShaderExecutor& lightExecutor, RayTracer& tracer, int depth,
                             RayCounts& rays)
    : shaders_(shaders),
      scene_(scene),
      camera_(camera),
      textures_(textures, shaders.TextureSearchPath()),
      shadowMaps_(textures.shadowMaps),
      pointClouds_(textures.pointClouds),
      lightExecutor_(lightExecutor),
      tracer_(tracer),
      depth_(depth),
      rays_(rays),
      worldFromCurrent_(shaders.CurrentFromWorld().inverse()) {
    colorComponents_ = shaders.GetFrame().options.colorComponents;
}

void RenderContext::Begin(const ShadingBatch& batch, const float* currentP,
                          const ShaderInstance* shader, const BatchNeighbours* neighbours) {
    batch_ = &batch;
    currentP_ = currentP;
    shader_ = shader;
    n_ = static_cast<int>(batch.points.size());
    neighbours_ = neighbours && neighbours->mainCount * 3 == n_ ? neighbours : nullptr;
    lightsValid_ = false;
    noNeighbours_.assign(n_, -1);
    messageShaders_.Clear();
    SeedRandom(batch.randomSeeds.size() == size_t(n_) ? batch.randomSeeds.data() : nullptr);
}

template <typename T>
void RenderContext::ShareWithNeighbours(std::vector<T>* values, int planes) const {
    const int main = MainCount();
    if (main == n_ || values->size() != size_t(planes) * main) return;
    std::vector<T> all(size_t(planes) * n_);
    for (int c = 0; c < planes; ++c)
        for (int i = 0; i < main; ++i)
            for (int k = 0; k < 3; ++k)
                all[size_t(c) * n_ + k * main + i] = (*values)[c * main + i];
    values->swap(all);
}

bool RenderContext::CurrentFromSpace(const std::string& space, int point, M44f* m) const {
    const M44f& currentFromWorld = shaders_.CurrentFromWorld();
    if (space == "current" || space == "camera") {
        *m = M44f();
    } else if (space == "world") {
        *m = currentFromWorld;
    } else if (space == "object") {
        *m = batch_->points[point]->worldFromObject * currentFromWorld;
    } else if (space == "shader") {
        *m = (shader_ ? shader_->worldFromShader : M44f()) * currentFromWorld;
    } else if (space == "screen") {
        *m = camera_.ScreenFromCamera().inverse();
    } else if (space == "NDC") {
        *m = (camera_.ScreenFromCamera() * camera_.NdcFromScreen()).inverse();
    } else if (space == "raster") {
        *m = (camera_.ScreenFromCamera() * camera_.NdcFromScreen() * camera_.RasterFromNdc())
                 .inverse();
    } else {
        const auto& named = shaders_.GetFrame().namedSpaces;
        auto it = named.find(space);
        if (it == named.end()) return false;
        *m = it->second * currentFromWorld;
    }
    return true;
}

const std::vector<sl::LightResult>& RenderContext::Lights() {
    if (lightsValid_) return lights_;
    lightsValid_ = true;
    EvaluateLights(currentP_, nullptr, &lights_);
    return lights_;
}

// illuminance(P', ...) away from the surface's P: the lights run again with P' as their Ps
// (RISpec §13.3.1), for the batch's active points only; the cached lights_ stay as they are.
const std::vector<sl::LightResult>& RenderContext::LightsAt(const float* P, const uint8_t* active) {
    EvaluateLights(P, active, &movedLights_);
    return movedLights_;
}

// The main points' copies of `P` (3 × MainCount()) and which of them to light: a main point
// whose neighbour point is active counts, so that derivatives see its lights.
const float* RenderContext::MainPoints(const float* P, const uint8_t* active) {
    const int all = n_, main = MainCount();
    mainActive_.assign(size_t(main), 1);
    if (active)
        for (int i = 0; i < main; ++i)
            mainActive_[i] =
                active[i] || (main < all && (active[main + i] || active[2 * main + i]));
    if (main == all) return P;
    mainP_.resize(3 * size_t(main));
    for (int c = 0; c < 3; ++c)
        std::copy(P + size_t(c) * all, P + size_t(c) * all + main,
                  mainP_.begin() + size_t(c) * main);
    return mainP_.data();
}

void RenderContext::EvaluateLights(const float* P, const uint8_t* active,
                                   std::vector<sl::LightResult>* results) {
    results->clear();
    const std::vector<FrameLight>& lights = shaders_.Lights();
    const std::vector<SceneLight>& sceneLights = shaders_.GetFrame().lights;
    const ShaderInstance* surfaceShader = shader_;
    // Neighbour points share their main point's lights: they lie a pixel away, and running the
    // lights and their shadow rays for them would triple the cost.
    const int all = n_;
    lightP_ = MainPoints(P, active);
    n_ = MainCount();
    // The surface's P, N and I: the globals of an ambient light (which runs at the surface)
    // and every light's Ns.
    sl::ShaderGlobals surface;
    ambientGlobals_.Set(*batch_, worldFromCurrent_, n_, lightP_, &surface);
    for (int index : batch_->attributes->activeLights) {
        const FrameLight& light = lights[index];
        if (!light.instance) continue;
        shader_ = &sceneLights[index].light.shader;  // "shader" space is the light's
        // An area light runs once per sample point on its surface; each run is one light to
        // illuminance, its Cl weighted by 1/(pdf · samples) (docs/shading-language.md).
        const int runs = light.area ? light.samples : 1;
        for (int k = 0; k < runs; ++k) {
            sl::ShaderGlobals globals;
            globals.n = n_;
            globals.Ps = lightP_;
            globals.Ns = surface.N;
            if (light.instance->Master().IsAmbientLight())
                globals.P = surface.P, globals.N = surface.N, globals.I = surface.I;
            if (light.area) {
                const uint64_t* seeds = batch_->randomSeeds.size() == size_t(all)
                                            ? batch_->randomSeeds.data()
                                            : nullptr;
                AreaLightSamplePoints(*light.area, k, runs, seeds, n_, shaders_.CurrentFromWorld(),
                                      &areaPoints_);
                globals.P = areaPoints_.P.data();
                globals.N = globals.Ng = areaPoints_.N.data();
            }
            results->push_back(RunLight(index, light, globals, active));
        }
    }
    n_ = all;
    for (sl::LightResult& result : *results) ShareLightWithNeighbours(&result);
    shader_ = surfaceShader;
}

sl::LightResult RenderContext::RunLight(int index, const FrameLight& light,
                                        const sl::ShaderGlobals& globals, const uint8_t* active) {
    sl::LightResult result;
    shadowMapMissing_ = false;
    runningLight_ = true;
    lightExecutor_.RunLight(*light.instance, globals, *this, &result);
    runningLight_ = false;
    result.shaderIndex = index;
    if (captureLights_) sl::CaptureLightParameters(*light.instance, lightExecutor_, n_, &result);
    if (active)
        for (int i = 0; i < n_; ++i) result.lit[i] &= mainActive_[i];
    if (light.area)
        for (int c = 0; c < colorComponents_; ++c)
            for (int i = 0; i < n_; ++i) result.Cl[c * size_t(n_) + i] *= areaPoints_.weight[i];
    // A light whose shadow map cannot be read is shadowed by rays instead (see Shadow).
    if ((light.castsShadows || shadowMapMissing_) && !result.ambient) TraceShadows(&result);
    return result;
}

void RenderContext::ShareLightWithNeighbours(sl::LightResult* result) const {
    ShareWithNeighbours(&result->L, 3);
    ShareWithNeighbours(&result->Cl, colorComponents_);
    ShareWithNeighbours(&result->Ol, colorComponents_);
    ShareWithNeighbours(&result->lit, 1);
    ShareWithNeighbours(&result->fromAllDirections, 1);
    for (sl::LightResult::Parameter& p : result->parameters)
        if (p.varying) ShareWithNeighbours(&p.floats, p.width);
}

// A point whose way to the light is blocked receives nothing from it. L runs from the surface
// point to the light, so the shadow ray ends just before L's tip; for a solar light L is only a
// direction, and the ray goes on for ever. Light from all directions (solar() without an axis)
// is not shadowed: no one ray stands for it.
void RenderContext::TraceShadows(sl::LightResult* light) {
    // Shadows are traced at the shutter's opening: points of a batch have no common time.
    const float time = shaders_.GetFrame().options.shutterOpen;
    const float end = light->atInfinity ? std::numeric_limits<float>::infinity() : 1 - 1e-4f;
    const uint8_t* all =
        light->fromAllDirections.empty() ? nullptr : light->fromAllDirections.data();
    const bool opaque = shaders_.AllShadowsOpaque();
    std::vector<float> passed(colorComponents_, 1.f);
    for (int i = 0; i < n_; ++i) {
        // Light from all directions has no one direction to test (see the docs).
        if (!light->lit[i] || (all && all[i])) continue;
        V3f L = ToV3(light->L.data(), n_, i), P = ToV3(lightP_, n_, i);
        V3f org, dir;
        worldFromCurrent_.multVecMatrix(P, org);
        worldFromCurrent_.multDirMatrix(L, dir);
        const float eps = 1e-4f * std::max(1.f, org.length() / std::max(dir.length(), 1e-20f));
        if (opaque) {
            ++rays_.shadow;
            if (!scene_.Occluded(org, dir, eps, end, time)) continue;
            std::fill(passed.begin(), passed.end(), 0.f);
        } else {
            // Partly transparent shadow casters let 1 − Os through (shadow_transmission.h).
            rays_.shadow += uint64_t(ShadowTransmission(scene_, org, dir, eps, end, time,
                                                        colorComponents_, passed.data()));
        }
        for (int c = 0; c < colorComponents_; ++c) light->Cl[c * n_ + i] *= passed[c];
    }
}

bool RenderContext::Texture(const std::string& name, int firstChannel, int channels,
                            const TextureWrapModes& wrap, const float* s, const float* t,
                            const float* dsdx, const float* dtdx, const float* dsdy,
                            const float* dtdy, const uint8_t* active, float* out) {
    return textures_.Texture(*this, n_, name, firstChannel, channels, wrap, s, t, dsdx, dtdx, dsdy,
                             dtdy, active, out);
}

// The direction is used as the shader gives it: RISpec §15.7.2 leaves the map's coordinate
// system to the shader, whose job it is to transform D into the space the map was made in
// (the standard shinymetal does D = vtransform("world", D)). Transforming here as well would
// turn the reflection with the camera.
bool RenderContext::Environment(const std::string& name, int firstChannel, int channels,
                                const float* directions, const uint8_t* active, float* out) {
    return textures_.Environment(*this, n_, name, firstChannel, channels, directions, active, out);
}

std::string RenderContext::FindTexture(const std::string& name) const {
    return textures_.Find(name);
}

// The matrices a texture was made with take world space to its camera and screen; the
// shader works in current space.
bool RenderContext::TextureInfo(const std::string& name, const std::string& dataname,
                                std::vector<float>* floats, std::string* text) {
    if (!textures_.Info(name, dataname, floats, text)) return false;
    if ((dataname == "viewingmatrix" || dataname == "projectionmatrix") && floats->size() == 16) {
        M44f fromWorld;
        for (int i = 0; i < 16; ++i) fromWorld[i / 4][i % 4] = (*floats)[i];
        const M44f fromCurrent = worldFromCurrent_ * fromWorld;
        for (int i = 0; i < 16; ++i) (*floats)[i] = fromCurrent[i / 4][i % 4];
    }
    return true;
}

// shadow("map", P): percentage-closer filtering of the map (renderer/image/shadow_map.h) over
// the point's footprint, a camera pixel's width at P (the light runs for the main points only,
// so no derivative of Ps is at hand). A map that cannot be read gives 0 (nothing in the way)
// with a warning once; inside a light shader the light's Cl is then shadowed by rays towards L
// instead, which is what 1 − shadow() multiplies it by in shadowspot, shadowpoint and
// shadowdistant (docs/shading-language.md, Shadow maps).
bool RenderContext::Shadow(const std::string& name, const float* points, const uint8_t* active,
                           const sl::ShadowOptions& options, float* out) {
    std::fill(out, out + n_, 0.f);
    if (name.empty()) return true;
    std::string why;
    const std::shared_ptr<const ShadowMap> map = shadowMaps_.Get(textures_.Find(name), &why);
    if (!map) {
        shadowMapMissing_ |= runningLight_;
        RuntimeWarning("shadow map " + name,
                       "shadow(\"" + name + "\"): " + why +
                           (runningLight_ ? "; the light is shadowed by traced rays instead"
                                          : "; outside a light shader nothing is shadowed"));
        return false;
    }
    ShadowFilter filter;
    filter.samples = int(std::clamp(options.samples, 1.f, 4096.f));
    filter.swidth = options.swidth, filter.twidth = options.twidth;
    filter.sblur = options.sblur, filter.tblur = options.tblur;
    filter.bias = options.bias;
    V3f unitStep;
    worldFromCurrent_.multDirMatrix(V3f(1, 0, 0), unitStep);
    const float worldUnit = unitStep.length();
    for (int i = 0; i < n_; ++i) {
        if (active && !active[i]) continue;
        const V3f P = ToV3(points, n_, i);
        V3f world;
        worldFromCurrent_.multVecMatrix(P, world);
        // A camera pixel's width, in world units as the map measures them.
        const float footprint = PixelWidth(P) * worldUnit;
        out[i] = map->Occlusion(world, footprint, filter, ShadowSeed(i, P));
    }
    return true;
}

uint64_t RenderContext::ShadowSeed(int i, const V3f& P) const {
    if (batch_->randomSeeds.size() >= size_t(n_)) return MixBits(batch_->randomSeeds[i] ^ 0x5ad0);
    uint32_t bits[3];
    std::memcpy(bits, &P, sizeof bits);
    return HashCombine(HashCombine(MixBits(bits[0]), bits[1]), bits[2]);
}

bool RenderContext::WorldRay(const float* P, const float* R, int i, V3f* org, V3f* dir) const {
    worldFromCurrent_.multVecMatrix(ToV3(P, n_, i), *org);
    worldFromCurrent_.multDirMatrix(ToV3(R, n_, i), *dir);
    const float length = dir->length();
    if (!(length > 0) || !std::isfinite(length)) return false;
    *dir /= length;
    return true;
}

// trace(P, R): the rays of the batch's active points go one depth deeper together; beyond
// Option "trace" "maxdepth" they bring black. A point's neighbour points share its colour, and
// their rays travel with it as its ray differentials.
void RenderContext::Trace(const float* P, const float* R, const uint8_t* active, float* out) {
    const int nc = colorComponents_;
    std::fill(out, out + size_t(nc) * n_, 0.f);
    if (depth_ + 1 > shaders_.TraceMaxDepth()) return;
    const int main = MainCount();
    auto isActive = [&](int i) { return !active || active[i]; };
    TracedRays rays;
    // Traced at the shutter's opening, as shadows are: points of a batch have no common time.
    rays.time = shaders_.GetFrame().options.shutterOpen;
    std::vector<int> traced;
    for (int i = 0; i < main; ++i) {
        V3f org, dir;
        if (!isActive(i) || !WorldRay(P, R, i, &org, &dir)) continue;
        // Leave the surface: an offset along the ray that grows with the coordinates' size, as
        // float precision does.
        const float tnear = 1e-4f * std::max(1.f, org.length());
        rays.org.push_back(org), rays.dir.push_back(dir), rays.tnear.push_back(tnear);
        traced.push_back(i);
        if (batch_->randomSeeds.size() == size_t(n_))
            rays.randomSeeds.push_back(MixBits(batch_->randomSeeds[i] ^ uint64_t(depth_ + 1)));
        if (!neighbours_) continue;
        NeighbourRays differential;
        for (int axis = 0; axis < 2; ++axis) {
            const int j = (axis + 1) * main + i;
            differential.org[axis] = org, differential.dir[axis] = dir;
            if (isActive(j)) WorldRay(P, R, j, &differential.org[axis], &differential.dir[axis]);
        }
        differential.tnear = tnear;
        differential.time = rays.time;
        rays.neighbours.push_back(differential);
    }
    if (traced.empty()) return;
    std::vector<float> colours(traced.size() * nc, 0.f);
    tracer_.TraceRays(depth_ + 1, rays, colours.data());
    for (size_t k = 0; k < traced.size(); ++k)
        for (int c = 0; c < nc; ++c)
            for (int copy = 0; copy < n_ / main; ++copy)
                out[size_t(c) * n_ + copy * main + traced[k]] = colours[k * nc + c];
}

bool RenderContext::Attribute(const std::string& name, const sl::TypeSpec& type, int,
                              std::vector<float>* floats, std::string* text) const {
    const Attributes& a = *batch_->attributes;
    auto numbers = [&](std::initializer_list<float> values) {
        if (type.base != sl::BaseType::Float) return false;
        floats->assign(values);
        return true;
    };
    if (name == "Sides") return numbers({a.twoSided ? 2.f : 1.f});
    if (name == "Matte") return numbers({a.matte ? 1.f : 0.f});
    if (name == "identifier:name" && type.base == sl::BaseType::String) {
        *text = a.identifier;
        return true;
    }
    const size_t colon = name.find(':');
    if (colon == std::string::npos) return false;
    auto group = a.user.find(name.substr(0, colon));
    if (group == a.user.end()) return false;
    const TypedParam* p = group->second.Find(name.substr(colon + 1));
    if (!p) return false;
    if (p->decl.type == ParamType::String) {
        if (type.base != sl::BaseType::String || p->strings.empty()) return false;
        *text = p->strings[0];
        return true;
    }
    if (type.base == sl::BaseType::String) return false;
    floats->assign(p->numbers.begin(), p->numbers.end());
    return true;
}

bool RenderContext::Option(const std::string& name, const sl::TypeSpec& type,
                           std::vector<float>* floats, std::string*) const {
    return QueryOption(shaders_.GetFrame().options, name, type, floats);
}

bool RenderContext::RendererInfo(const std::string& name, const sl::TypeSpec& type,
                                 std::vector<float>* floats, std::string* text) const {
    if (name == "renderer" && type.base == sl::BaseType::String) {
        *text = "gonio";
        return true;
    }
    if (name == "versionstring" && type.base == sl::BaseType::String) {
        *text = "0.1.0";
        return true;
    }
    if (name == "version" && type.base == sl::BaseType::Float) {
        floats->assign({0, 1, 0, 0});
        return true;
    }
    return false;
}

void RenderContext::RuntimeWarning(const std::string& key, const std::string& message) {
    ReportRuntime(Severity::Warning, key, message);
}

void RenderContext::ShaderTimedOut(double budget) {
    const bool first = !shaders_.TimedOut();
    shaders_.NoteTimedOut();
    if (first) sl::ShadingContext::ShaderTimedOut(budget);
}

void RenderContext::RuntimeError(const std::string& key, const std::string& message) {
    ReportRuntime(Severity::Error, key, message);
}

void RenderContext::ReportRuntime(Severity severity, const std::string& key,
                                  const std::string& message) {
    // At the shader statement, naming the RIB request that bound the shader.
    const std::string& where = Statement();
    const FileLoc request = shader_ ? shader_->loc : FileLoc{};
    const FileLoc loc = where.empty() ? request : sl::StatementLoc(where, "");
    const std::string bound = where.empty() || !shader_ ? std::string()
                                                        : " (shader \"" + shader_->name + "\" of " +
                                                              request.ToString() + ")";
    shaders_.GetDiagnostics().ReportOnce(severity, "runtime " + where + key, loc, message + bound);
}

void RenderContext::Print(const std::string& text) {
    static std::mutex printMutex;
    std::lock_guard<std::mutex> lock(printMutex);
    std::fputs(text.c_str(), stdout);
}

}  // namespace gonio
