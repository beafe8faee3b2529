#include "shaderlang/shading_system.h"

#include <algorithm>
#include <cstring>

#include "base/search_path.h"
#include "shaderlang/compiler/codegen.h"
#include "shaderlang/compiler/optimizer.h"
#include "shaderlang/compiler/parser.h"
#include "shaderlang/compiler/preprocessor.h"
#include "shaderlang/compiler/typecheck.h"
#include "shaderlang/runtime/global_vars.h"
#include "shaderlang/runtime/interpreter.h"

namespace gonio::sl {

const char* ToString(ShaderType type) {
    switch (type) {
        case ShaderType::Surface:
            return "surface";
        case ShaderType::Light:
            return "light";
        case ShaderType::Displacement:
            return "displacement";
        case ShaderType::Volume:
            return "volume";
        case ShaderType::Imager:
            return "imager";
    }
    return "?";
}

const ShaderParam* Shader::FindParam(const std::string& name) const {
    for (const ShaderParam& p : params_) {
        if (p.name == name) return &p;
    }
    return nullptr;
}

std::string Shader::Disassemble() const { return sl::Disassemble(*program_); }

std::shared_ptr<const Shader> CompileShaderSource(const std::string& source,
                                                  const std::string& fileName,
                                                  const CompileOptions& options,
                                                  Diagnostics& diagnostics) {
    PreprocessOptions pp;
    pp.includeDirs = options.includeDirs;
    pp.defines = options.defines;
    std::string text;
    bool ok = Preprocess(source, fileName, pp, &text, diagnostics);
    SyntaxTree tree;
    ok = ParseShader(text, fileName, &tree, diagnostics) && ok;
    if (!ok) return nullptr;
    TypeChecker checker(tree, diagnostics, options.colorComponents);
    Node* definition = checker.Check();
    if (!definition || checker.Errors() > 0) return nullptr;
    auto program = std::make_shared<Program>();
    CodeGenerator generator(tree, checker, diagnostics, options.colorComponents);
    if (!generator.Generate(definition, program.get())) return nullptr;
    program->warnings = std::make_shared<RuntimeWarnings>();

    auto shader = std::make_shared<Shader>();
    shader->type_ = checker.Type();
    shader->name_ = definition->name;
    shader->file_ = fileName;
    shader->colorComponents_ = options.colorComponents;
    shader->ambientLight_ = shader->type_ == ShaderType::Light && program->ambientLight;
    for (Node* formal : definition->kids[0]->kids) {
        const Symbol* s = formal->symbol;
        if (!s) continue;
        ShaderParam param;
        param.name = s->name;
        param.type = s->type;
        param.detail = s->detail;
        param.output = s->output;
        param.loc = ToFileLoc(tree, formal->loc);
        param.defaultIsConstant = EvaluateDefault(*program, s->param, options.colorComponents,
                                                  &param.defaultFloats, &param.defaultStrings);
        shader->params_.push_back(param);
    }
    shader->program_ = program;
    return shader;
}

std::shared_ptr<const Shader> CompileShaderFile(const std::string& path,
                                                const CompileOptions& options,
                                                Diagnostics& diagnostics) {
    std::string source;
    if (!ReadTextFile(path, &source)) {
        diagnostics.Error(FileLoc{std::make_shared<const std::string>(path), 0, 0},
                          "cannot read the shader file");
        return nullptr;
    }
    return CompileShaderSource(source, path, options, diagnostics);
}

// ---------------------------------------------------------------------------------------------
// ShadingSystem

ShadingSystem::ShadingSystem(Diagnostics& diagnostics, int colorComponents)
    : diagnostics_(diagnostics), colorComponents_(colorComponents) {}

void ShadingSystem::SetSearchPath(const std::string& path) {
    std::lock_guard<std::mutex> lock(mutex_);
    searchPath_ = ExpandSearchPath(path, searchPath_, {});
}

void ShadingSystem::SetSearchPath(std::vector<std::string> folders) {
    std::lock_guard<std::mutex> lock(mutex_);
    searchPath_ = std::move(folders);
}

std::shared_ptr<const Shader> ShadingSystem::Load(const std::string& name, const FileLoc& where) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto cached = cache_.find(name);
    if (cached != cache_.end()) return cached->second;
    const bool hasSuffix = name.size() > 3 && name.compare(name.size() - 3, 3, ".sl") == 0;
    const std::string file = hasSuffix ? name : name + ".sl";
    std::string source;
    std::string found = FindOnSearchPath(file, searchPath_);
    if (!found.empty() && !ReadTextFile(found, &source)) found.clear();
    std::shared_ptr<const Shader> shader;
    if (found.empty()) {
        std::string dirs;
        for (const std::string& d : searchPath_) dirs += (dirs.empty() ? "" : ", ") + d;
        diagnostics_.Error(
            where, "cannot find shader '" + name + "' (looked for " + file + " in " + dirs + ")");
    } else {
        CompileOptions options;
        options.includeDirs = searchPath_;
        options.colorComponents = colorComponents_;
        shader = CompileShaderSource(source, found, options, diagnostics_);
        if (!shader) diagnostics_.Note(where, "shader '" + name + "' failed to compile");
    }
    cache_[name] = shader;
    return shader;
}

// ---------------------------------------------------------------------------------------------
// ShaderInstance

ShaderInstance::ShaderInstance(std::shared_ptr<const Shader> shader) : shader_(std::move(shader)) {}
ShaderInstance::~ShaderInstance() = default;

namespace {

int ValueCount(const ShaderParam& p, int ncomps) {
    const int elements = p.type.IsArray() ? p.type.arrayLength : 1;
    return p.type.base == BaseType::String ? elements : p.type.Width(ncomps) * elements;
}

}  // namespace

bool ShaderInstance::SetParameter(const std::string& name, const std::vector<float>& values,
                                  std::string* error) {
    const ShaderParam* p = shader_->FindParam(name);
    if (!p) {
        *error = "shader '" + shader_->Name() + "' has no parameter '" + name + "'";
        return false;
    }
    if (p->type.base == BaseType::String) {
        *error = "parameter '" + name + "' is a string, not numbers";
        return false;
    }
    const int want = ValueCount(*p, shader_->ColorComponents());
    if (int(values.size()) != want) {
        *error = "parameter '" + name + "' (" + ToString(p->type) + ") takes " +
                 std::to_string(want) + " numbers, not " + std::to_string(values.size());
        return false;
    }
    overrides_[name] = Override{values, {}};
    return true;
}

bool ShaderInstance::SetParameter(const std::string& name, const std::vector<std::string>& values,
                                  std::string* error) {
    const ShaderParam* p = shader_->FindParam(name);
    if (!p) {
        *error = "shader '" + shader_->Name() + "' has no parameter '" + name + "'";
        return false;
    }
    if (p->type.base != BaseType::String) {
        *error = "parameter '" + name + "' is a " + ToString(p->type) + ", not a string";
        return false;
    }
    if (int(values.size()) != ValueCount(*p, shader_->ColorComponents())) {
        *error = "parameter '" + name + "' takes " +
                 std::to_string(ValueCount(*p, shader_->ColorComponents())) + " strings";
        return false;
    }
    overrides_[name] = Override{{}, values};
    return true;
}

bool ShaderInstance::BindPrimvar(const std::string& name) {
    if (!shader_->FindParam(name)) return false;
    if (!IsBound(name)) bound_.push_back(name);
    return true;
}

bool ShaderInstance::IsBound(const std::string& name) const {
    return std::find(bound_.begin(), bound_.end(), name) != bound_.end();
}

std::string ShaderInstance::StringParameter(const std::string& name) const {
    auto it = overrides_.find(name);
    if (it != overrides_.end() && !it->second.strings.empty()) return it->second.strings[0];
    const ShaderParam* p = shader_->FindParam(name);
    if (p && !p->defaultStrings.empty()) return p->defaultStrings[0];
    return "";
}

void ShaderInstance::Specialize() {
    std::call_once(specialized_, [this] {
        auto program = std::make_shared<Program>(shader_->Code());
        const int ncomps = shader_->ColorComponents();
        OptimizeOptions options;
        options.colorComponents = ncomps;
        options.keepNamed = keepVariables_;
        const auto& params = shader_->Params();
        for (size_t i = 0; i < params.size() && i < program->params.size(); ++i) {
            const ShaderParam& param = params[i];
            const ParamCode code = program->params[i];
            Register& reg = program->regs[code.reg];
            auto override = overrides_.find(param.name);
            const bool bound = IsBound(param.name);
            if (param.output) options.pinned.push_back(code.reg);
            if (override == overrides_.end() && !bound) continue;
            // The default's code is skipped; the value comes from the instance.
            if (code.initEnd > code.initBegin) {
                Instr& first = program->code[code.initBegin];
                first = Instr{};
                first.op = uint16_t(Op::Jump);
                first.jump = code.initEnd;
            }
            Preset preset;
            preset.reg = code.reg;
            if (override != overrides_.end()) {
                preset.floats = override->second.floats;
                preset.strings = override->second.strings;
            } else {
                preset.floats = param.defaultFloats;
                preset.strings = param.defaultStrings;
            }
            const int count = ValueCount(param, ncomps);
            if (reg.isString) {
                preset.strings.resize(size_t(count));
            } else {
                preset.floats.resize(size_t(count), 0.0f);
            }
            if (bound) {
                preset.primvar = param.name;
                reg.varying = true;
                reg.fixedDetail = true;
                options.pinned.push_back(code.reg);
                program->presets.push_back(preset);
            } else if (!param.output &&
                       WritesOutside(*program, code.reg, code.initBegin, code.initEnd) == 0) {
                reg.constant = true;
                reg.varying = false;
                reg.fixedDetail = true;
                reg.constOffset = reg.isString ? program->AddStringConstant(preset.strings)
                                               : program->AddConstant(preset.floats, reg.type);
            } else {
                options.pinned.push_back(code.reg);
                program->presets.push_back(preset);
            }
        }
        Optimize(*program, options);
        program_ = program;
    });
}

const Program& ShaderInstance::Code() const { return program_ ? *program_ : shader_->Code(); }

// ---------------------------------------------------------------------------------------------
// ShaderExecutor

ShaderExecutor::ShaderExecutor() : state_(std::make_unique<ExecState>()) {}
ShaderExecutor::~ShaderExecutor() = default;

namespace {

// Copies `width` planes of n floats (or a default per component) into register r.
void LoadRegister(ExecState& x, int r, const float* source, const float* defaults) {
    RegRef reg = x.Reg(r);
    for (int c = 0; c < reg.width; ++c) {
        float* plane = reg.Plane(c);
        if (!reg.varying) {
            plane[0] = source ? source[size_t(c) * x.n] : defaults[c];
        } else if (source) {
            std::memcpy(plane, source + size_t(c) * x.n, sizeof(float) * size_t(x.n));
        } else {
            std::fill_n(plane, x.n, defaults[c]);
        }
    }
}

const float* GlobalSource(int id, const ShaderGlobals& g) {
    switch (id) {
        case kGlobalP:
            return g.P;
        case kGlobalN:
            return g.N;
        case kGlobalNg:
            return g.Ng;
        case kGlobalI:
            return g.I;
        case kGlobalDPdu:
            return g.dPdu;
        case kGlobalDPdv:
            return g.dPdv;
        case kGlobalDPdtime:
            return g.dPdtime;
        case kGlobalU:
            return g.u;
        case kGlobalV:
            return g.v;
        case kGlobalDu:
            return g.du;
        case kGlobalDv:
            return g.dv;
        case kGlobalS:
            return g.s;
        case kGlobalT:
            return g.t;
        case kGlobalCs:
            return g.Cs;
        case kGlobalOs:
            return g.Os;
        case kGlobalCi:
            return g.Ci;
        case kGlobalOi:
            return g.Oi ? g.Oi : g.Os;
        case kGlobalPs:
            return g.Ps;
        case kGlobalAlpha:
            return g.alphas;
        default:
            return nullptr;
    }
}

void LoadGlobals(ExecState& x, const ShaderGlobals& g) {
    const Program& p = *x.program;
    std::vector<float> ones(64, 1.0f), zeros(64, 0.0f);
    for (int id = 0; id < kGlobalCount; ++id) {
        const int r = p.globals[id];
        if (r < 0 || !p.regs[r].used) continue;
        float uniform[3] = {0, 0, 0};
        const float* defaults = zeros.data();
        switch (id) {
            case kGlobalE:
                defaults = g.E;
                break;
            case kGlobalNcomps:
                uniform[0] = float(x.colorComponents), defaults = uniform;
                break;
            case kGlobalTime:
                uniform[0] = g.time, defaults = uniform;
                break;
            case kGlobalDtime:
                uniform[0] = g.dtime, defaults = uniform;
                break;
            case kGlobalAlpha:
                uniform[0] = g.alpha, defaults = uniform;
                break;
            case kGlobalCs:
            case kGlobalOs:
            case kGlobalOi:
                defaults = ones.data();
                break;
            default:
                break;
        }
        LoadRegister(x, r, GlobalSource(id, g), defaults);
    }
}

void LoadPresets(ExecState& x, const ShaderGlobals& g) {
    for (const Preset& preset : x.program->presets) {
        const Register& reg = x.program->regs[preset.reg];
        if (reg.isString) {
            for (size_t k = 0; k < preset.strings.size(); ++k)
                x.Str(preset.reg, int(k)) = preset.strings[k];
            continue;
        }
        const ShaderGlobals::Primvar* primvar = nullptr;
        if (!preset.primvar.empty()) {
            for (const auto& pv : g.primvars) {
                if (pv.name == preset.primvar && pv.data) primvar = &pv;
            }
        }
        RegRef r = x.Reg(preset.reg);
        const int pvWidth = primvar ? primvar->type.Width(x.colorComponents) *
                                          std::max(1, primvar->type.arrayLength)
                                    : 0;
        for (int c = 0; c < r.width; ++c) {
            float* plane = r.Plane(c);
            const int count = r.varying ? x.n : 1;
            if (primvar && c < pvWidth && primvar->varying) {
                std::memcpy(plane, primvar->data + size_t(c) * x.n, sizeof(float) * size_t(count));
            } else {
                float v = primvar && c < pvWidth ? primvar->data[c] : preset.floats[size_t(c)];
                std::fill_n(plane, count, v);
            }
        }
    }
}

}  // namespace

bool ShaderExecutor::Run(ShaderInstance& instance, const ShaderGlobals& globals,
                         ShadingContext& context) {
    instance.Specialize();
    const Program& p = *instance.program_;
    ExecState& x = *state_;
    x.context = &context;
    x.warnings = p.warnings.get();
    x.Prepare(p, globals.n, instance.Master().ColorComponents());
    if (globals.active) {
        x.masks[0].all = false;
        std::memcpy(x.masks[0].bits.data(), globals.active, size_t(globals.n));
    }
    LoadGlobals(x, globals);
    LoadPresets(x, globals);
    x.Execute(0, int(p.code.size()));
    return true;
}

bool ShaderExecutor::RunLight(ShaderInstance& instance, const ShaderGlobals& globals,
                              ShadingContext& context, LightResult* result) {
    Run(instance, globals, context);
    ExecState& x = *state_;
    const int n = globals.n, ncomps = instance.Master().ColorComponents();
    auto planes = [&](const char* name, int width, float sign, float fallback) {
        std::vector<float> out(size_t(width) * n, fallback);
        FloatArg a = x.Get(name);
        if (!a.data) return out;
        for (int c = 0; c < width && c < a.width; ++c) {
            for (int i = 0; i < n; ++i) out[size_t(c) * n + i] = sign * a.At(c, i);
        }
        return out;
    };
    result->L = planes("L", 3, -1.0f, 0.0f);  // the surface's view: towards the light
    result->Cl = planes("Cl", ncomps, 1.0f, 0.0f);
    result->Ol = planes("Ol", ncomps, 1.0f, 0.0f);
    result->ambient = instance.Master().IsAmbientLight();
    result->atInfinity = x.solar;
    result->lit = result->ambient ? std::vector<uint8_t>(size_t(n), 1) : x.lit;
    result->fromAllDirections.clear();
    if (x.anyAllDirections && !result->ambient) result->fromAllDirections = x.allDirections;
    result->category = instance.StringParameter("__category");
    return true;
}

FloatArg ShaderExecutor::Output(const std::string& name) const { return state_->Get(name); }

const std::string* ShaderExecutor::OutputString(const std::string& name) const {
    const Program* p = state_->program;
    if (!p) return nullptr;
    auto it = p->named.find(name);
    if (it == p->named.end() || !p->regs[it->second].isString) return nullptr;
    return &state_->strings[it->second][0];
}

}  // namespace gonio::sl
