// gonio shader FILE.sl [-I DIR]... [-D NAME[=VALUE]]... [--ncomps N] [--code]
// Checks a shader and prints its type, name and parameters (like sloinfo).

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "shader_compile_args.h"
#include "shaderlang/shading_system.h"

namespace gonio {
namespace {

struct ShaderOptions {
    std::string file;
    ShaderCompileArgs compile;
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
    auto shader =
        sl::CompileShaderFile(options.file, MakeCompileOptions(options.compile), diagnostics);
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
    AddShaderCompileOptions(cmd, &options->compile);
    cmd->add_flag("--code", options->code, "Print the compiled bytecode too");
    cmd->callback([options, exitCode] { *exitCode = RunShader(*options); });
}

}  // namespace gonio
