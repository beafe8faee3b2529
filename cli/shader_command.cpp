// gonio shader FILE.sl [-I DIR]... [-D NAME[=VALUE]]... [--ncomps N] [--code]
// Checks a shader and prints its type, name and parameters (like sloinfo).

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "base/limits.h"
#include "commands.h"
#include "shaderlang/shading_system.h"

namespace gonio {
namespace {

struct ShaderOptions {
    std::string file;
    std::vector<std::string> includeDirs;
    std::vector<std::string> defines;
    int colorComponents = 3;
    bool code = false;
};

std::string FormatDefault(const sl::ShaderParam& p) {
    if (!p.defaultIsConstant) return "<computed at run time>";
    std::ostringstream out;
    if (p.type.base == sl::BaseType::String) {
        if (p.type.IsArray()) out << "{";
        for (size_t k = 0; k < p.defaultStrings.size(); ++k) {
            out << (k ? " " : "") << "\"" << p.defaultStrings[k] << "\"";
        }
        if (p.type.IsArray()) out << "}";
        return out.str();
    }
    bool single = p.defaultFloats.size() == 1;
    if (!single) out << (p.type.IsArray() ? "{" : "[");
    for (size_t k = 0; k < p.defaultFloats.size(); ++k) {
        out << (k ? " " : "") << p.defaultFloats[k];
    }
    if (!single) out << (p.type.IsArray() ? "}" : "]");
    return out.str();
}

int RunShader(const ShaderOptions& options) {
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
    if (!shader) return diagnostics.ErrorCount() > 0 && !std::ifstream(options.file) ? 2 : 1;
    std::printf("%s \"%s\"\n", sl::ToString(shader->Type()), shader->Name().c_str());
    for (const sl::ShaderParam& p : shader->Params()) {
        std::printf("    %s%s %s %s = %s\n", p.output ? "output " : "",
                    p.detail == sl::Detail::Uniform ? "uniform" : "varying",
                    sl::ToString(p.type).c_str(), p.name.c_str(), FormatDefault(p).c_str());
    }
    if (options.code) std::printf("\n%s", shader->Disassemble().c_str());
    return 0;
}

}  // namespace

void AddShaderCommand(CLI::App& app, int* exitCode) {
    auto options = std::make_shared<ShaderOptions>();
    CLI::App* cmd = app.add_subcommand("shader", "Check a shader and print its parameters");
    cmd->add_option("file", options->file, "Shader source (.sl)")->required();
    cmd->add_option("-I", options->includeDirs, "Folder searched by #include");
    cmd->add_option("-D", options->defines, "Preprocessor definition NAME[=VALUE]");
    cmd->add_option("--ncomps", options->colorComponents, "Colour components (ColorSamples)")
        ->check(CLI::Range(1, kMaxColorComponents));
    cmd->add_flag("--code", options->code, "Print the compiled bytecode too");
    cmd->callback([options, exitCode] { *exitCode = RunShader(*options); });
}

}  // namespace gonio
