// gonio shade FILE.sl [--res WxH] [-p NAME=VALUE]... [--light "L.sl NAME=VALUE ..."]...
//                     [-o OUT.exr] [--print NAME]... [--at X,Y] [-I DIR] [-D NAME[=VALUE]]
// Runs a shader over a grid of points with simple default globals (as OSL's testshade does);
// docs/shading-language.md lists the globals.

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "commands.h"
#include "renderer/image/image_writer.h"
#include "shaderlang/shading_system.h"
#include "shaderlang/simple_context.h"

namespace gonio {
namespace {

struct ShadeOptions {
    std::string file;
    std::string res = "1x1";
    std::vector<std::string> params;
    std::vector<std::string> lights;
    std::string output;
    std::vector<std::string> prints;
    std::string at;
    std::vector<std::string> includeDirs;
    std::vector<std::string> defines;
    int colorComponents = 3;
};

constexpr int kBatch = 1024;

std::vector<std::string> Split(const std::string& text, char separator) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, separator)) out.push_back(item);
    return out;
}

// Applies "name=value" to an instance: numbers separated by commas (one number fills a whole
// colour or point), or text for a string parameter.
bool ApplyAssignment(sl::ShaderInstance& instance, const std::string& assignment,
                     std::string* error) {
    size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        *error = "expected NAME=VALUE, got '" + assignment + "'";
        return false;
    }
    const std::string name = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    const sl::ShaderParam* p = instance.Master().FindParam(name);
    if (!p) {
        *error = "shader '" + instance.Master().Name() + "' has no parameter '" + name + "'";
        return false;
    }
    if (p->type.base == sl::BaseType::String) {
        return instance.SetParameter(
            name, p->type.IsArray() ? Split(value, ',') : std::vector<std::string>{value}, error);
    }
    std::vector<float> numbers;
    for (const std::string& item : Split(value, ',')) {
        char* end = nullptr;
        float v = std::strtof(item.c_str(), &end);
        if (item.empty() || *end != '\0') {
            *error = "parameter '" + name + "' (" + sl::ToString(p->type) + ") expects numbers, " +
                     "got '" + value + "'";
            return false;
        }
        numbers.push_back(v);
    }
    const int width = p->type.Width(instance.Master().ColorComponents());
    if (numbers.size() == 1 && width > 1 && !p->type.IsArray()) {
        numbers.assign(size_t(width), p->type.base == sl::BaseType::Matrix ? 0.0f : numbers[0]);
        if (p->type.base == sl::BaseType::Matrix) {
            float v = std::strtof(value.c_str(), nullptr);
            for (int k = 0; k < 16; k += 5) numbers[size_t(k)] = v;
        }
    }
    return instance.SetParameter(name, numbers, error);
}

// Per-point values of one printed name over the whole grid.
struct Collected {
    std::vector<float> values;  // width planes of n floats (varying) or width floats
    int width = 0;
    bool varying = false;
    bool found = false;
    std::string text;
};

void Collect(const sl::FloatArg& a, int start, int count, int total, Collected* c) {
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

void PrintValues(const std::string& name, const Collected& c, int width, int total, int atIndex) {
    if (!c.text.empty() || (!c.found && !c.text.empty())) {
        std::printf("%s = \"%s\"\n", name.c_str(), c.text.c_str());
        return;
    }
    auto line = [&](int point) {
        std::string text;
        for (int comp = 0; comp < c.width; ++comp) {
            char buffer[32];
            float v = c.varying ? c.values[size_t(comp) * total + point] : c.values[size_t(comp)];
            std::snprintf(buffer, sizeof(buffer), "%s%g", comp ? " " : "", double(v));
            text += buffer;
        }
        return text;
    };
    if (!c.varying) {
        std::printf("%s = %s\n", name.c_str(), line(0).c_str());
        return;
    }
    for (int i = 0; i < total; ++i) {
        if (atIndex >= 0 && i != atIndex) continue;
        std::printf("%s[%d,%d] = %s\n", name.c_str(), i % width, i / width, line(i).c_str());
    }
}

int RunShade(const ShadeOptions& options) {
    int width = 0, height = 0;
    if (std::sscanf(options.res.c_str(), "%dx%d", &width, &height) != 2 || width < 1 ||
        height < 1 || double(width) * height > 1e8) {
        std::fprintf(stderr, "gonio shade: --res expects WxH with positive sizes, got '%s'\n",
                     options.res.c_str());
        return 2;
    }
    int atIndex = -1;
    if (!options.at.empty()) {
        int ax, ay;
        if (std::sscanf(options.at.c_str(), "%d,%d", &ax, &ay) != 2 || ax < 0 || ay < 0 ||
            ax >= width || ay >= height) {
            std::fprintf(stderr, "gonio shade: --at expects X,Y inside the grid, got '%s'\n",
                         options.at.c_str());
            return 2;
        }
        atIndex = ay * width + ax;
    }
    if (!std::ifstream(options.file)) {
        std::fprintf(stderr, "gonio shade: cannot read '%s'\n", options.file.c_str());
        return 2;
    }
    Diagnostics diagnostics;
    sl::CompileOptions compile;
    compile.includeDirs = options.includeDirs;
    compile.colorComponents = options.colorComponents;
    for (const std::string& d : options.defines) {
        size_t eq = d.find('=');
        compile.defines.emplace_back(d.substr(0, eq),
                                     eq == std::string::npos ? "" : d.substr(eq + 1));
    }
    auto shader = sl::CompileShaderFile(options.file, compile, diagnostics);
    if (!shader) return 1;
    sl::ShaderInstance instance(shader);
    std::string error;
    for (const std::string& p : options.params) {
        if (!ApplyAssignment(instance, p, &error)) {
            std::fprintf(stderr, "gonio shade: %s\n", error.c_str());
            return 1;
        }
    }
    sl::SimpleShadingContext context(diagnostics);
    for (const std::string& spec : options.lights) {
        std::istringstream words(spec);
        std::string file, assignment;
        words >> file;
        auto light = sl::CompileShaderFile(file, compile, diagnostics);
        if (!light) return 1;
        if (light->Type() != sl::ShaderType::Light) {
            std::fprintf(stderr, "gonio shade: '%s' is a %s shader, not a light\n", file.c_str(),
                         sl::ToString(light->Type()));
            return 1;
        }
        auto lightInstance = std::make_shared<sl::ShaderInstance>(light);
        while (words >> assignment) {
            if (!ApplyAssignment(*lightInstance, assignment, &error)) {
                std::fprintf(stderr, "gonio shade: %s\n", error.c_str());
                return 1;
            }
        }
        context.AddLight(lightInstance);
    }
    if (!options.prints.empty()) instance.KeepVariables();

    const int total = width * height;
    const int ncomps = shader->ColorComponents();
    std::map<std::string, Collected> collected;
    std::vector<std::string> names = options.prints;
    if (!options.output.empty()) {
        names.push_back("Ci");
        names.push_back("Oi");
    }
    sl::ShaderExecutor exec;
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
        sl::ShaderGlobals g;
        g.n = n;
        g.P = P.data(), g.N = N.data(), g.Ng = N.data(), g.I = I.data();
        g.dPdu = dPdu.data(), g.dPdv = dPdv.data();
        g.u = u.data(), g.v = v.data(), g.s = u.data(), g.t = v.data();
        g.du = du.data(), g.dv = dv.data();
        g.E[2] = -1.0f;
        if (shader->Type() == sl::ShaderType::Light) g.Ps = P.data();
        context.BeginBatch(g, ncomps);
        for (int i = 0; i < n; ++i) {
            const int index = start + i, x = index % width;
            if (x + 1 < width && i + 1 < n) context.UNeighbourTable()[i] = i + 1;
            if (i + width < n) context.VNeighbourTable()[i] = i + width;
        }
        exec.Run(instance, g, context);
        for (const std::string& name : names) {
            Collected& c = collected[name];
            sl::FloatArg a = exec.Output(name);
            Collect(a, start, n, total, &c);
            if (!a.data) {
                if (const std::string* text = exec.OutputString(name)) c.text = *text;
            }
        }
    }
    int status = diagnostics.ErrorCount() > 0 ? 1 : 0;
    for (const std::string& name : options.prints) {
        const Collected& c = collected[name];
        if (!c.found && c.text.empty()) {
            std::fprintf(stderr,
                         "gonio shade: '%s' is not a global, parameter or top-level variable of "
                         "'%s'\n",
                         name.c_str(), shader->Name().c_str());
            status = 1;
            continue;
        }
        PrintValues(name, c, width, total, atIndex);
    }
    if (!options.output.empty()) {
        Image image;
        image.width = image.fullWidth = width;
        image.height = image.fullHeight = height;
        image.channels = 4;
        image.pixels.assign(size_t(total) * 4, 0.0f);
        const Collected& ci = collected["Ci"];
        const Collected& oi = collected["Oi"];
        auto at = [&](const Collected& c, int comp, int i) {
            if (!c.found) return 0.0f;
            comp = std::min(comp, c.width - 1);
            return c.varying ? c.values[size_t(comp) * total + i] : c.values[size_t(comp)];
        };
        for (int i = 0; i < total; ++i) {
            float* px = &image.pixels[size_t(i) * 4];
            for (int c = 0; c < 3; ++c) px[c] = at(ci, c, i);
            float alpha = 0.0f;
            for (int c = 0; c < ncomps; ++c) alpha += oi.found ? at(oi, c, i) : 1.0f;
            px[3] = alpha / float(ncomps);
        }
        DisplaySpec display;
        display.name = options.output;
        display.type = "file";
        display.mode = "rgba";
        display.loc.file = std::make_shared<const std::string>(options.output);
        bool isFloat = options.output.size() > 4 &&
                       options.output.compare(options.output.size() - 4, 4, ".exr") == 0;
        Quantization colour;
        if (isFloat) colour = Quantization{0, 0, 0, 0.0f};
        if (!WriteDisplay(display, image, {"r", "g", "b", "a"}, Exposure{}, colour,
                          DefaultDepthQuantization(), diagnostics)) {
            return 2;
        }
    }
    return status;
}

}  // namespace

void AddShadeCommand(CLI::App& app, int* exitCode) {
    auto options = std::make_shared<ShadeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "shade", "Run a shader over a grid of points (see docs/shading-language.md)");
    cmd->add_option("file", options->file, "Shader source (.sl)")->required();
    cmd->add_option("--res", options->res, "Grid size WxH (default 1x1)");
    cmd->add_option("-p,--param", options->params, "Parameter value NAME=VALUE");
    cmd->add_option("--light", options->lights, "Light shader and its values: \"L.sl N=V ...\"");
    cmd->add_option("-o,--output", options->output, "Write Ci (and Oi as alpha) to an image");
    cmd->add_option("--print", options->prints, "Print a global, parameter or variable");
    cmd->add_option("--at", options->at, "Print only the point X,Y");
    cmd->add_option("-I", options->includeDirs, "Folder searched by #include");
    cmd->add_option("-D", options->defines, "Preprocessor definition NAME[=VALUE]");
    cmd->add_option("--ncomps", options->colorComponents, "Colour components (ColorSamples)")
        ->check(CLI::Range(1, 64));
    cmd->callback([options, exitCode] { *exitCode = RunShade(*options); });
}

}  // namespace gonio
