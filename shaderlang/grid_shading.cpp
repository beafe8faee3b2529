#include "shaderlang/grid_shading.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace gonio::sl {
namespace {

constexpr int kBatch = 1024;

std::vector<std::string> Split(const std::string& text, char separator) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, separator)) out.push_back(item);
    return out;
}

void Collect(const sl::FloatArg& a, int start, int count, int total, GridOutput* c) {
    if (!a.data) return;
    if (!c->found) {
        c->found = true;
        c->width = a.width;
        c->varying = a.varying;
        c->values.assign(size_t(a.width) * (a.varying ? total : 1), 0.0f);
    }
    for (int comp = 0; comp < a.width; ++comp) {
        if (!a.varying) {
            c->values[size_t(comp)] = a.data[comp];
            continue;
        }
        for (int i = 0; i < count; ++i) {
            c->values[size_t(comp) * total + start + i] = a.data[size_t(comp) * count + i];
        }
    }
}

}  // namespace

float GridOutput::At(int comp, int i, int total) const {
    if (!found) return 0.0f;
    comp = std::min(comp, width - 1);
    return varying ? values[size_t(comp) * total + i] : values[size_t(comp)];
}

std::map<std::string, GridOutput> ShadeGrid(ShaderInstance& instance, int width, int height,
                                            const std::vector<std::string>& names,
                                            SimpleShadingContext& context) {
    const int total = width * height;
    const int ncomps = instance.Master().ColorComponents();
    std::map<std::string, GridOutput> outputs;
    ShaderExecutor exec;
    for (int start = 0; start < total; start += kBatch) {
        const int n = std::min(kBatch, total - start);
        std::vector<float> P(3 * n), N(3 * n), I(3 * n), dPdu(3 * n), dPdv(3 * n);
        std::vector<float> u(n), v(n), du(n, 1.0f / width), dv(n, 1.0f / height);
        for (int i = 0; i < n; ++i) {
            const int index = start + i, x = index % width, y = index / width;
            u[i] = (x + 0.5f) / width;
            v[i] = (y + 0.5f) / height;
            P[i] = u[i], P[n + i] = v[i], P[2 * n + i] = 0.0f;
            N[i] = 0.0f, N[n + i] = 0.0f, N[2 * n + i] = -1.0f;
            I[i] = 0.0f, I[n + i] = 0.0f, I[2 * n + i] = 1.0f;
            dPdu[i] = 1.0f, dPdu[n + i] = 0.0f, dPdu[2 * n + i] = 0.0f;
            dPdv[i] = 0.0f, dPdv[n + i] = 1.0f, dPdv[2 * n + i] = 0.0f;
        }
        ShaderGlobals g;
        g.n = n;
        g.P = P.data(), g.N = N.data(), g.Ng = N.data(), g.I = I.data();
        g.dPdu = dPdu.data(), g.dPdv = dPdv.data();
        g.u = u.data(), g.v = v.data(), g.s = u.data(), g.t = v.data();
        g.du = du.data(), g.dv = dv.data();
        g.E[2] = -1.0f;
        if (instance.Master().Type() == ShaderType::Light) g.Ps = P.data(), g.Ns = N.data();
        context.BeginBatch(g, ncomps);
        for (int i = 0; i < n; ++i) {
            const int index = start + i, x = index % width;
            if (x + 1 < width && i + 1 < n) context.UNeighbourTable()[i] = i + 1;
            if (i + width < n) context.VNeighbourTable()[i] = i + width;
        }
        exec.Run(instance, g, context);
        for (const std::string& name : names) {
            GridOutput& c = outputs[name];
            FloatArg a = exec.Output(name);
            Collect(a, start, n, total, &c);
            if (!a.data) {
                if (const std::string* text = exec.OutputString(name)) c.text = *text;
            }
        }
    }
    return outputs;
}

bool SetParameterFromText(ShaderInstance& instance, const std::string& assignment,
                          std::string* error) {
    size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        *error = "expected NAME=VALUE, got '" + assignment + "'";
        return false;
    }
    const std::string name = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    const ShaderParam* p = instance.Master().FindParam(name);
    if (!p) {
        *error = "shader '" + instance.Master().Name() + "' has no parameter '" + name + "'";
        return false;
    }
    if (p->type.base == BaseType::String) {
        return instance.SetParameter(
            name, p->type.IsArray() ? Split(value, ',') : std::vector<std::string>{value}, error);
    }
    std::vector<float> numbers;
    for (const std::string& item : Split(value, ',')) {
        char* end = nullptr;
        float v = std::strtof(item.c_str(), &end);
        if (item.empty() || *end != '\0') {
            *error = "parameter '" + name + "' (" + ToString(p->type) + ") expects numbers, " +
                     "got '" + value + "'";
            return false;
        }
        numbers.push_back(v);
    }
    const int width = p->type.Width(instance.Master().ColorComponents());
    if (numbers.size() == 1 && width > 1 && !p->type.IsArray()) {
        numbers.assign(size_t(width), p->type.base == BaseType::Matrix ? 0.0f : numbers[0]);
        if (p->type.base == BaseType::Matrix) {
            float v = std::strtof(value.c_str(), nullptr);
            for (int k = 0; k < 16; k += 5) numbers[size_t(k)] = v;
        }
    }
    return instance.SetParameter(name, numbers, error);
}

}  // namespace gonio::sl
