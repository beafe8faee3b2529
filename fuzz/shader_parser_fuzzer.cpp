// libFuzzer target for the shading-language front end and compiler: arbitrary bytes through
// the preprocessor, parser, type checker, code generator and instance specialisation must give
// diagnostics, never a crash or a hang.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "shaderlang/shading_system.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    gonio::Diagnostics diagnostics(nullptr);
    gonio::sl::CompileOptions options;
    std::string source(reinterpret_cast<const char*>(data), size);
    auto shader = gonio::sl::CompileShaderSource(source, "fuzz.sl", options, diagnostics);
    if (shader) {
        gonio::sl::ShaderInstance instance(shader);
        instance.Specialize();
    }
    return 0;
}
