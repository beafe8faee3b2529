#include "renderer/shading/frame_shaders.h"

#include <algorithm>
#include <sstream>

#include "renderer/raytrace/shadow_transmission.h"
#include "renderer/scene/search_paths.h"
#include "renderer/shading/rib_shader_parameters.h"

namespace gonio {
namespace {

// Parameters named like shading globals are never bound from primitive variables: the
// renderer passes those as globals.
bool IsGlobalName(const std::string& name) {
    static const char* const kGlobals[] = {"P", "Pw", "Pz", "N", "Ng", "Cs",    "Os",
                                           "s", "t",  "st", "u", "v",  "width", "constantwidth"};
    for (const char* g : kGlobals)
        if (name == g) return true;
    return false;
}

// A shader request as text: equal requests share one instance.
std::string RequestKey(const ShaderInstance& request) {
    std::ostringstream key;
    key << request.name << '|';
    for (const Param& p : request.params) {
        key << p.token << '=';
        for (double d : p.numbers) key << d << ',';
        for (const std::string& s : p.strings) key << s << ',';
        key << ';';
    }
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) key << request.worldFromShader[r][c] << ',';
    return key.str();
}

// "a surface", "an imager".
std::string WithArticle(sl::ShaderType type) {
    const std::string name = sl::ToString(type);
    return (name[0] == 'i' ? "an " : "a ") + name;
}

}  // namespace

std::string DefaultShaderFolder() { return GONIO_SHADER_DIR; }

std::vector<std::string> FrameTextureSearchPath(const Frame& frame) {
    return TextureSearchPath(frame.options, frame.sceneFile);
}

std::vector<std::string> ShaderSearchPath(const Frame& frame) {
    return OptionSearchPath(frame.options, "shader",
                            {SceneFolder(frame.sceneFile), DefaultShaderFolder()});
}

std::shared_ptr<sl::ShaderInstance> LoadShaderInstance(
    sl::ShadingSystem& system, const ShaderInstance& request, sl::ShaderType expected,
    const M44f& currentFromShader, const Declarations& declarations, const Options& options,
    Diagnostics& diagnostics) {
    if (!request.IsSet()) return nullptr;
    std::shared_ptr<const sl::Shader> shader = system.Load(request.name, request.loc);
    if (!shader) return nullptr;
    if (shader->Type() != expected) {
        diagnostics.Error(request.loc, "\"" + request.name + "\" is " +
                                           WithArticle(shader->Type()) + " shader, not " +
                                           WithArticle(expected) + " shader");
        return nullptr;
    }
    auto instance = std::make_shared<sl::ShaderInstance>(shader);
    ApplyRibParameters(*instance, request.params, declarations, options, currentFromShader,
                       diagnostics);
    return instance;
}

// An area light runs its shader at points on its surface; one with no surface to sample (no
// primitives followed it, or none with area) lights from its origin, as a LightSource does.
void FrameShaders::AddAreaGeometry(const SceneLight& light, FrameLight* frameLight) const {
    auto geometry =
        std::make_shared<const AreaLightGeometry>(AreaLightGeometry::Build(frame_, light));
    if (geometry->Empty()) {
        diagnostics_.WarningOnce("area light without geometry", light.light.shader.loc,
                                 "AreaLightSource \"" + light.light.shader.name +
                                     "\" has no geometry with area (no polygon, patch, quadric "
                                     "or subdivision mesh followed it in its attribute block); "
                                     "it lights from its origin, as a LightSource would");
        return;
    }
    frameLight->area = std::move(geometry);
    frameLight->samples = light.samples;
}

FrameShaders::FrameShaders(const Frame& frame, Diagnostics& diagnostics)
    : frame_(frame),
      diagnostics_(diagnostics),
      system_(std::make_unique<sl::ShadingSystem>(diagnostics, frame.options.colorComponents)) {
    system_->SetSearchPath(ShaderSearchPath(frame));
    texturePath_ = FrameTextureSearchPath(frame);
    for (const SceneShape& shape : frame.shapes) AddShapeGroup(shape, *shape.attributes);
    for (const ObjectInstanceUse& use : frame.instances)
        for (size_t i = 0; i < use.definition->shapes.size(); ++i)
            AddShapeGroup(use.definition->shapes[i], *use.shapeAttributes[i]);
    for (const SceneLight& light : frame.lights) {
        FrameLight frameLight;
        frameLight.instance = Instance(light.light.shader, sl::ShaderType::Light);
        frameLight.currentFromShader = light.light.shader.worldFromShader * CurrentFromWorld();
        frameLight.castsShadows = light.castsShadows;
        if (light.light.isArea) AddAreaGeometry(light, &frameLight);
        lights_.push_back(std::move(frameLight));
    }
    allShadowsOpaque_ = gonio::AllShadowsOpaque(frame);
    // Parameters are known and primitive variables bound: fold every instance's constants now,
    // before the threads share them.
    for (auto& [key, instance] : instances_)
        if (instance) instance->Specialize();
    for (auto& [attributes, group] : groups_) {
        for (const auto* instance :
             {group.surface.get(), group.displacement.get(), group.atmosphere.get()}) {
            if (!instance) continue;
            const sl::ShaderNeeds needs = instance->Needs();
            group.needs.derivatives |= needs.derivatives;
            group.needs.trace |= needs.trace;
        }
        anyTakesDerivatives_ |= group.needs.derivatives;
    }
    traceMaxDepth_ = gonio::TraceMaxDepth(frame);
    if (auto limits = frame.options.user.find("limits"); limits != frame.options.user.end())
        shaderTimeout_ = std::max(0.0, double(limits->second.GetFloat("shadertimeout", 0)));
}

std::shared_ptr<sl::ShaderInstance> FrameShaders::Instance(const ShaderInstance& request,
                                                           sl::ShaderType expected) {
    if (!request.IsSet()) return nullptr;
    const std::string key = RequestKey(request);
    auto found = instances_.find(key);
    if (found != instances_.end()) return found->second;
    // Failed requests are remembered too (as null), so that each is reported once.
    std::shared_ptr<sl::ShaderInstance>& instance = instances_[key];
    instance = LoadShaderInstance(*system_, request, expected,
                                  request.worldFromShader * CurrentFromWorld(), declarations_,
                                  frame_.options, diagnostics_);
    return instance;
}

void FrameShaders::AddShapeGroup(const SceneShape& shape, const Attributes& shadedWith) {
    const Attributes* attributes = &shadedWith;
    auto [it, isNew] = groups_.try_emplace(attributes);
    ShaderGroup& group = it->second;
    if (isNew) {
        group.surface = Instance(attributes->surface, sl::ShaderType::Surface);
        group.displacement = Instance(attributes->displacement, sl::ShaderType::Displacement);
        group.atmosphere = Instance(attributes->atmosphere, sl::ShaderType::Volume);
        group.surfaceRequest = &attributes->surface;
    }
    if (!group.surface) return;
    // Primitive variables reach the surface shader's parameters of the same name (RSL §14.1).
    // The instance is shared by every group with the same Surface request, so another group may
    // have bound the parameter already: this group still needs it in its own list.
    auto bind = [&](const PrimVar& var) {
        const std::string& name = var.decl.name;
        const auto& bound = group.boundPrimvars;
        if (IsGlobalName(name) || std::find(bound.begin(), bound.end(), name) != bound.end())
            return;
        if (!group.surface->Master().FindParam(name)) return;
        if (group.surface->IsBound(name) || group.surface->BindPrimvar(name))
            group.boundPrimvars.push_back(name);
    };
    std::visit(
        [&](const auto& geometry) {
            using T = std::decay_t<decltype(geometry)>;
            if constexpr (std::is_same_v<T, TriangleMesh>) {
                for (const MeshVar& mv : geometry.vars) bind(mv.var);
            } else {
                for (const PrimVar& var : geometry.vars.vars) bind(var);
            }
        },
        shape.geometry);
}

const ShaderGroup* FrameShaders::Group(const Attributes* attributes) const {
    auto it = groups_.find(attributes);
    return it == groups_.end() ? nullptr : &it->second;
}

}  // namespace gonio
