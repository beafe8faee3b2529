#include "shader_compile_args.h"

#include "base/limits.h"

namespace gonio {

void AddShaderCompileOptions(CLI::App* cmd, ShaderCompileArgs* args) {
    cmd->add_option("-I", args->includeDirs, "Folder searched by #include");
    cmd->add_option("-D", args->defines, "Preprocessor definition NAME[=VALUE]");
    cmd->add_option("--ncomps", args->colorComponents, "Colour components (ColorSamples)")
        ->check(CLI::Range(1, kMaxColorComponents));
}

sl::CompileOptions MakeCompileOptions(const ShaderCompileArgs& args) {
    sl::CompileOptions compile;
    compile.includeDirs = args.includeDirs;
    compile.colorComponents = args.colorComponents;
    for (const std::string& d : args.defines) {
        const size_t eq = d.find('=');
        compile.defines.emplace_back(d.substr(0, eq),
                                     eq == std::string::npos ? "" : d.substr(eq + 1));
    }
    return compile;
}

}  // namespace gonio
