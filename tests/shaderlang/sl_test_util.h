#pragma once
// Compiles shader source in memory and runs it over a small grid of points, as `gonio shade`
// does (u = s = (x + 0.5) / W, v = t = (y + 0.5) / H, P = (u, v, 0), N = Ng = (0, 0, -1),
// I = (0, 0, 1)), collecting diagnostics as text.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "shaderlang/shading_system.h"
#include "shaderlang/simple_context.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio::sl::testing {

using gonio::test::CapturedDiagnostics;

inline std::shared_ptr<const Shader> Compile(const std::string& source, CapturedDiagnostics& d,
                                             int ncomps = 3) {
    CompileOptions options;
    options.colorComponents = ncomps;
    return CompileShaderSource(source, "test.sl", options, d.Get());
}

// The errors of compiling `source`, as printed.
inline std::string Errors(const std::string& source) {
    CapturedDiagnostics d;
    Compile(source, d);
    return d.Text();
}

struct Grid {
    int width = 1, height = 1;
    std::vector<float> P, N, I, u, v, du, dv;
    ShaderGlobals globals;

    Grid(int w, int h) : width(w), height(h) {
        const int n = w * h;
        P.resize(3 * n), N.resize(3 * n), I.resize(3 * n), u.resize(n), v.resize(n);
        du.assign(n, 1.0f / w), dv.assign(n, 1.0f / h);
        for (int i = 0; i < n; ++i) {
            u[i] = (i % w + 0.5f) / w;
            v[i] = (i / w + 0.5f) / h;
            P[i] = u[i], P[n + i] = v[i], P[2 * n + i] = 0;
            N[i] = 0, N[n + i] = 0, N[2 * n + i] = -1;
            I[i] = 0, I[n + i] = 0, I[2 * n + i] = 1;
        }
        globals.n = n;
        globals.P = P.data(), globals.N = N.data(), globals.Ng = N.data(), globals.I = I.data();
        globals.u = globals.s = u.data();
        globals.v = globals.t = v.data();
        globals.du = du.data(), globals.dv = dv.data();
        globals.E[2] = -1;
    }
};

// Runs `instance` over a w × h grid; returns the values of `name` per point (component-major,
// a uniform value repeated), with lights if any.
struct RunResult {
    std::vector<float> values;  // width planes of n
    int width = 0;
    bool varying = false;
    std::string diagnostics;
    float At(int component, int point) const {
        return values[size_t(component) * (values.size() / width) + point];
    }
};

inline RunResult Run(ShaderInstance& instance, int w, int h, const std::string& name,
                     const std::vector<std::shared_ptr<ShaderInstance>>& lights = {}) {
    CapturedDiagnostics d;
    SimpleShadingContext context(d.Get());
    for (const auto& l : lights) context.AddLight(l);
    Grid grid(w, h);
    context.BeginBatch(grid.globals, instance.Master().ColorComponents());
    ShaderExecutor exec;
    exec.Run(instance, grid.globals, context);
    FloatArg a = exec.Output(name);
    RunResult r;
    r.width = a.width;
    r.varying = a.varying;
    const int n = w * h;
    if (a.data) {
        r.values.resize(size_t(a.width) * n);
        for (int c = 0; c < a.width; ++c) {
            for (int i = 0; i < n; ++i) r.values[size_t(c) * n + i] = a.At(c, i);
        }
    }
    r.diagnostics = d.Text();
    return r;
}

// Compiles and runs `source` (which must compile) with its defaults.
inline RunResult Shade(const std::string& source, int w, int h, const std::string& name) {
    CapturedDiagnostics d;
    auto shader = Compile(source, d);
    if (!shader) {
        RunResult r;
        r.diagnostics = d.Text();
        return r;
    }
    ShaderInstance instance(shader);
    instance.KeepVariables();
    return Run(instance, w, h, name);
}

}  // namespace gonio::sl::testing
