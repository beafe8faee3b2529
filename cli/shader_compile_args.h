#pragma once
// The compiler options `gonio shader` and `gonio shade` share: -I, -D and --ncomps.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "shaderlang/shading_system.h"

namespace gonio {

struct ShaderCompileArgs {
    std::vector<std::string> includeDirs;
    std::vector<std::string> defines;  // NAME or NAME=VALUE
    int colorComponents = 3;
};

void AddShaderCompileOptions(CLI::App* cmd, ShaderCompileArgs* args);
sl::CompileOptions MakeCompileOptions(const ShaderCompileArgs& args);

}  // namespace gonio
