#include "shading/render_context.h"

#include <cmath>
#include <cstdio>

#include "image/texture_lookup.h"

namespace gonio {
namespace {

V3f ToV3(const float* data, int n, int i) { return V3f(data[i], data[n + i], data[2 * n + i]); }

}  // namespace

RenderContext::RenderContext(const FrameShaders& shaders, const RayScene& scene,
                             const Camera& camera, TextureLookup& textures,
                             sl::ShaderExecutor& lightExecutor)
    : shaders_(shaders),
      scene_(scene),
      camera_(camera),
      textures_(textures),
      lightExecutor_(lightExecutor),
      worldFromCurrent_(shaders.CurrentFromWorld().inverse()) {
    colorComponents_ = shaders.GetFrame().options.colorComponents;
}

void RenderContext::Begin(const ShadingBatch& batch, const float* currentP,
                          const ShaderInstance* shader) {
    batch_ = &batch;
    currentP_ = currentP;
    shader_ = shader;
    n_ = static_cast<int>(batch.points.size());
    lightsValid_ = false;
    noNeighbours_.assign(n_, -1);
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
    lights_.clear();
    const std::vector<FrameLight>& lights = shaders_.Lights();
    const std::vector<SceneLight>& sceneLights = shaders_.GetFrame().lights;
    const ShaderInstance* surfaceShader = shader_;
    for (int index : batch_->attributes->activeLights) {
        const FrameLight& light = lights[index];
        if (!light.instance) continue;
        sl::ShaderGlobals globals;
        globals.n = n_;
        globals.Ps = currentP_;
        sl::LightResult result;
        shader_ = &sceneLights[index].light.shader;  // "shader" space is the light's
        lightExecutor_.RunLight(*light.instance, globals, *this, &result);
        result.shaderIndex = index;
        if (light.castsShadows && !result.ambient) TraceShadows(&result);
        lights_.push_back(std::move(result));
    }
    shader_ = surfaceShader;
    return lights_;
}

// A point whose way to the light is blocked receives nothing from it. L runs from the surface
// point to the light, so the shadow ray ends just before L's tip.
void RenderContext::TraceShadows(sl::LightResult* light) const {
    for (int i = 0; i < n_; ++i) {
        if (!light->lit[i]) continue;
        V3f L = ToV3(light->L.data(), n_, i), P = ToV3(currentP_, n_, i);
        V3f org, dir;
        worldFromCurrent_.multVecMatrix(P, org);
        worldFromCurrent_.multDirMatrix(L, dir);
        const float eps = 1e-4f * std::max(1.f, org.length() / std::max(dir.length(), 1e-20f));
        // Shadows are traced at the shutter's opening: points of a batch have no common time.
        const float time = shaders_.GetFrame().options.shutterOpen;
        if (!scene_.Occluded(org, dir, eps, 1 - 1e-4f, time)) continue;
        for (int c = 0; c < colorComponents_; ++c) light->Cl[c * n_ + i] = 0;
    }
}

bool RenderContext::Texture(const std::string& name, int firstChannel, int channels, const float* s,
                            const float* t, const float* dsdx, const float* dtdx, const float* dsdy,
                            const float* dtdy, const uint8_t* active, float* out) {
    const bool ok = textures_.Texture(name, firstChannel, channels, n_, s, t, dsdx, dtdx, dsdy,
                                      dtdy, active, out);
    if (!ok)
        RuntimeWarning("texture " + name, "texture \"" + name + "\": " + textures_.LastError());
    return ok;
}

bool RenderContext::Environment(const std::string& name, int firstChannel, int channels,
                                const float* directions, const uint8_t* active, float* out) {
    // The shader gives directions in current space; environment maps are indexed in world.
    std::vector<float> world(3 * size_t(n_));
    for (int i = 0; i < n_; ++i) {
        V3f d;
        worldFromCurrent_.multDirMatrix(ToV3(directions, n_, i), d);
        world[i] = d.x, world[n_ + i] = d.y, world[2 * n_ + i] = d.z;
    }
    const bool ok =
        textures_.Environment(name, firstChannel, channels, n_, world.data(), active, out);
    if (!ok)
        RuntimeWarning("environment " + name,
                       "environment \"" + name + "\": " + textures_.LastError());
    return ok;
}

bool RenderContext::Shadow(const std::string& name, const float*, const uint8_t*, float* out) {
    // Shadows are ray traced (Attribute "light" "shadows" "on"); shadow maps are not read.
    RuntimeWarning("shadow map", "shadow(\"" + name +
                                     "\"): shadow maps are not used; shadows are ray traced "
                                     "when a light has Attribute \"light\" \"shadows\" \"on\"");
    std::fill(out, out + n_, 0.f);
    return false;
}

void RenderContext::Trace(const float*, const float*, const uint8_t*, float* out) {
    RuntimeWarning("trace", "trace() returns black in this version");
    std::fill(out, out + size_t(colorComponents_) * n_, 0.f);
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
    const std::string param = name.substr(colon + 1);
    for (const Param& p : group->second) {
        const size_t space = p.token.rfind(' ');
        if (p.token.substr(space + 1) != param) continue;
        if (p.isString) {
            if (type.base != sl::BaseType::String || p.strings.empty()) return false;
            *text = p.strings[0];
            return true;
        }
        if (type.base == sl::BaseType::String) return false;
        floats->assign(p.numbers.begin(), p.numbers.end());
        return true;
    }
    return false;
}

bool RenderContext::Option(const std::string& name, const sl::TypeSpec& type,
                           std::vector<float>* floats, std::string*) const {
    if (type.base != sl::BaseType::Float) return false;
    const Options& o = shaders_.GetFrame().options;
    if (name == "Format") {
        floats->assign({float(o.xres), float(o.yres), o.pixelAspect});
    } else if (name == "FrameAspectRatio") {
        floats->assign({o.frameAspect > 0 ? o.frameAspect : o.xres * o.pixelAspect / o.yres});
    } else if (name == "CropWindow") {
        floats->assign(o.cropWindow, o.cropWindow + 4);
    } else if (name == "Clipping") {
        floats->assign({o.nearClip, o.farClip});
    } else if (name == "DepthOfField") {
        floats->assign({o.fstop, o.focalLength, o.focalDistance});
    } else if (name == "Shutter") {
        floats->assign({o.shutterOpen, o.shutterClose});
    } else {
        return false;
    }
    return true;
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
    const FileLoc loc = shader_ ? shader_->loc : FileLoc{};
    shaders_.GetDiagnostics().WarningOnce("runtime " + key, loc, message);
}

void RenderContext::Print(const std::string& text) {
    static std::mutex printMutex;
    std::lock_guard<std::mutex> lock(printMutex);
    std::fputs(text.c_str(), stdout);
}

}  // namespace gonio
