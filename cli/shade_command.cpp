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
#include "shader_compile_args.h"
#include "shaderlang/grid_shading.h"
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
    ShaderCompileArgs compile;
};

void PrintValues(const std::string& name, const sl::GridOutput& c, int width, int total,
                 int atIndex) {
    if (!c.text.empty() || (!c.found && !c.text.empty())) {
        std::printf("%s = \"%s\"\n", name.c_str(), c.text.c_str());
        return;
    }
    auto line = [&](int point) {
        std::string text;
        for (int comp = 0; comp < c.width; ++comp) {
            char buffer[32];
            const float v = c.At(comp, point, total);
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
    const sl::CompileOptions compile = MakeCompileOptions(options.compile);
    auto shader = sl::CompileShaderFile(options.file, compile, diagnostics);
    if (!shader) return 1;
    sl::ShaderInstance instance(shader);
    std::string error;
    for (const std::string& p : options.params) {
        if (!sl::SetParameterFromText(instance, p, &error)) {
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
            if (!sl::SetParameterFromText(*lightInstance, assignment, &error)) {
                std::fprintf(stderr, "gonio shade: %s\n", error.c_str());
                return 1;
            }
        }
        context.AddLight(lightInstance);
    }
    if (!options.prints.empty()) instance.KeepVariables();
    std::vector<std::string> names = options.prints;
    if (!options.output.empty()) {
        names.push_back("Ci");
        names.push_back("Oi");
    }
    const int total = width * height;
    const int ncomps = shader->ColorComponents();
    std::map<std::string, sl::GridOutput> collected =
        sl::ShadeGrid(instance, width, height, names, context);
    int status = diagnostics.ErrorCount() > 0 ? 1 : 0;
    for (const std::string& name : options.prints) {
        const sl::GridOutput& c = collected[name];
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
        const sl::GridOutput& ci = collected["Ci"];
        const sl::GridOutput& oi = collected["Oi"];
        for (int i = 0; i < total; ++i) {
            float* px = &image.pixels[size_t(i) * 4];
            for (int c = 0; c < 3; ++c) px[c] = ci.At(c, i, total);
            float alpha = 0.0f;
            for (int c = 0; c < ncomps; ++c) alpha += oi.found ? oi.At(c, i, total) : 1.0f;
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
    AddShaderCompileOptions(cmd, &options->compile);
    cmd->callback([options, exitCode] { *exitCode = RunShade(*options); });
}

}  // namespace gonio
