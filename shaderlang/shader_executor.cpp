// ShaderExecutor: loading globals, parameters and presets into registers and running a batch.

#include <algorithm>
#include <cstring>

#include "shaderlang/runtime/global_vars.h"
#include "shaderlang/runtime/interpreter.h"
#include "shaderlang/shading_system.h"

namespace gonio::sl {

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
        case kGlobalNs:
            return g.Ns;
        case kGlobalAlpha:
            return g.alphas;
        default:
            return nullptr;
    }
}

void LoadGlobals(ExecState& x, const ShaderGlobals& g) {
    const Program& p = *x.program;
    // Defaults for a global the caller did not give, one value per component: a colour has
    // ncomps of them (81 for a sampled spectrum), a matrix 16.
    const size_t width = std::max<size_t>(16, size_t(x.colorComponents));
    std::vector<float> ones(width, 1.0f), zeros(width, 0.0f);
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
    const auto now = std::chrono::steady_clock::now();
    if (context.ShadersStopped())
        x.deadline = now;
    else if (const double budget = context.ShaderTimeout(); budget > 0)
        x.deadline = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                               std::chrono::duration<double>(budget));
    if (globals.active) {
        x.masks[0].all = false;
        std::memcpy(x.masks[0].bits.data(), globals.active, size_t(globals.n));
    }
    x.inputP = globals.P;
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
