// Shader: compiling a source file (preprocess, parse, type-check, generate, optimize) into the
// immutable master that every instance shares.

#include "shaderlang/compiler/codegen.h"
#include "shaderlang/compiler/optimizer.h"
#include "shaderlang/compiler/parser.h"
#include "shaderlang/compiler/preprocessor.h"
#include "shaderlang/compiler/tree_depth.h"
#include "shaderlang/compiler/typecheck.h"
#include "shaderlang/runtime/global_vars.h"
#include "shaderlang/runtime/interpreter.h"
#include "shaderlang/shading_system.h"

namespace gonio::sl {

const char* ToString(ShaderType type) {
    switch (type) {
        case ShaderType::Surface:
            return "surface";
        case ShaderType::Light:
            return "light";
        case ShaderType::Displacement:
            return "displacement";
        case ShaderType::Volume:
            return "volume";
        case ShaderType::Imager:
            return "imager";
    }
    return "?";
}

const ShaderParam* Shader::FindParam(const std::string& name) const {
    for (const ShaderParam& p : params_) {
        if (p.name == name) return &p;
    }
    return nullptr;
}

std::string Shader::Disassemble() const { return sl::Disassemble(*program_); }

std::shared_ptr<const Shader> CompileShaderSource(const std::string& source,
                                                  const std::string& fileName,
                                                  const CompileOptions& options,
                                                  Diagnostics& diagnostics) {
    PreprocessOptions pp;
    pp.includeDirs = options.includeDirs;
    pp.defines = options.defines;
    std::string text;
    bool ok = Preprocess(source, fileName, pp, &text, diagnostics);
    SyntaxTree tree;
    ok = ParseShader(text, fileName, &tree, diagnostics) && ok;
    if (!ok || !CheckTreeDepth(tree, diagnostics)) return nullptr;
    TypeChecker checker(tree, diagnostics, options.colorComponents);
    Node* definition = checker.Check();
    if (!definition || checker.Errors() > 0) return nullptr;
    auto program = std::make_shared<Program>();
    CodeGenerator generator(tree, checker, diagnostics, options.colorComponents);
    if (!generator.Generate(definition, program.get())) return nullptr;
    program->warnings = std::make_shared<RuntimeWarnings>();

    auto shader = std::make_shared<Shader>();
    shader->type_ = checker.Type();
    shader->name_ = definition->name;
    shader->file_ = fileName;
    shader->colorComponents_ = options.colorComponents;
    shader->ambientLight_ = shader->type_ == ShaderType::Light && program->ambientLight;
    for (Node* formal : definition->Formals()) {
        const Symbol* s = formal->symbol;
        if (!s) continue;
        ShaderParam param;
        param.name = s->name;
        param.type = s->type;
        param.detail = s->detail;
        param.output = s->output;
        param.loc = ToFileLoc(tree, formal->loc);
        param.defaultIsConstant = EvaluateDefault(*program, s->param, options.colorComponents,
                                                  &param.defaultFloats, &param.defaultStrings);
        shader->params_.push_back(param);
    }
    shader->program_ = program;
    return shader;
}

std::shared_ptr<const Shader> CompileShaderFile(const std::string& path,
                                                const CompileOptions& options,
                                                Diagnostics& diagnostics) {
    std::string source, why;
    if (!ReadTextFile(path, &source, &why)) {
        diagnostics.Error(FileLoc{std::make_shared<const std::string>(path), 0, 0},
                          "cannot read the shader file: " + why);
        return nullptr;
    }
    return CompileShaderSource(source, path, options, diagnostics);
}

}  // namespace gonio::sl
