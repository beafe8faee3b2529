#pragma once
// The renderer's entry to the shading language: find and compile NAME.sl once per run, describe
// its parameters, make instances with RIB overrides, and run them over batches of points.
//
//   ShadingSystem system(diagnostics);
//   system.SetSearchPath("shaders:&");                       // '&' = the previous path
//   auto plastic = system.Load("plastic", ribLocation);      // cached; nullptr after errors
//   ShaderInstance instance(plastic);
//   instance.SetParameter("Kd", {0.5f}, &error);             // false: error says why
//   instance.Specialize();                                   // folds the instance's constants
//   ShaderExecutor exec;                                     // one per thread
//   ShaderGlobals globals;  globals.n = 256; globals.P = ...; // component-major, see batch.h
//   exec.Run(instance, globals, context);                    // context: shading_context.h
//   FloatArg Ci = exec.Output("Ci");                         // valid until the next Run
//
// Lights: exec.RunLight(lightInstance, globals /* Ps = surface points */, context, &result)
// fills a LightResult (L as the surface sees it, Cl, Ol, the lit mask, ambient or not).

#include <Imath/ImathMatrix.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "shaderlang/runtime/batch.h"
#include "shaderlang/shading_context.h"
#include "shaderlang/types.h"

namespace gonio::sl {

enum class ShaderType : uint8_t { Surface, Light, Displacement, Volume, Imager };
const char* ToString(ShaderType type);

struct Program;  // runtime/program.h: the compiled bytecode

// One shader parameter as declared (what `gonio shader` prints).
struct ShaderParam {
    std::string name;
    TypeSpec type;
    Detail detail = Detail::Uniform;
    bool output = false;
    // The default, when it is a constant: width × max(1, arrayLength) floats (colours have
    // ColorComponents() floats), or max(1, arrayLength) strings. A default computed at run time
    // (from a global or another parameter) has defaultIsConstant == false and empty values.
    bool defaultIsConstant = true;
    std::vector<float> defaultFloats;
    std::vector<std::string> defaultStrings;
    FileLoc loc;
};

struct CompileOptions {
    std::vector<std::string> includeDirs;                      // for #include "..." and <...>
    std::vector<std::pair<std::string, std::string>> defines;  // -D name=value
    int colorComponents = 3;                                   // ColorSamples
};

// A compiled shader: immutable and shared by all its instances.
class Shader {
  public:
    ShaderType Type() const { return type_; }
    const std::string& Name() const { return name_; }
    const std::string& File() const { return file_; }
    int ColorComponents() const { return colorComponents_; }
    const std::vector<ShaderParam>& Params() const { return params_; }
    const ShaderParam* FindParam(const std::string& name) const;
    // A light shader without illuminate or solar: only ambient() sees it.
    bool IsAmbientLight() const { return ambientLight_; }
    const Program& Code() const { return *program_; }
    // The bytecode as text, one instruction per line (for `gonio shader --code` and tests).
    std::string Disassemble() const;

  private:
    friend std::shared_ptr<const Shader> CompileShaderSource(const std::string&, const std::string&,
                                                             const CompileOptions&, Diagnostics&);
    ShaderType type_ = ShaderType::Surface;
    std::string name_, file_;
    int colorComponents_ = 3;
    std::vector<ShaderParam> params_;
    bool ambientLight_ = false;
    std::shared_ptr<Program> program_;
};

// Compiles shader source; reports every error through `diagnostics` and returns nullptr if
// there was any.
std::shared_ptr<const Shader> CompileShaderFile(const std::string& path,
                                                const CompileOptions& options,
                                                Diagnostics& diagnostics);
std::shared_ptr<const Shader> CompileShaderSource(const std::string& source,
                                                  const std::string& fileName,
                                                  const CompileOptions& options,
                                                  Diagnostics& diagnostics);

// Finds NAME.sl on the shader search path and compiles each file once per run.
class ShadingSystem {
  public:
    explicit ShadingSystem(Diagnostics& diagnostics, int colorComponents = 3);

    // Colon-separated folders; '&' stands for the previous path (initially "."). Also used as
    // the #include path of the shaders.
    void SetSearchPath(const std::string& path);
    void SetSearchPath(std::vector<std::string> folders);
    const std::vector<std::string>& SearchPath() const { return searchPath_; }

    // `name` is a shader name ("plastic") or a file name ("plastic.sl", "dir/x.sl"). Errors
    // (not found, compile errors) are reported once, at `where`; then nullptr.
    std::shared_ptr<const Shader> Load(const std::string& name, const FileLoc& where);

  private:
    Diagnostics& diagnostics_;
    int colorComponents_;
    std::vector<std::string> searchPath_{"."};
    std::mutex mutex_;
    std::map<std::string, std::shared_ptr<const Shader>> cache_;  // nullptr: failed before
};

// What a specialised instance asks of the renderer beyond running it (OSL's "globals_read"):
// read off its code, so that a derivative or a trace() in a branch the instance's constants
// remove costs nothing.
struct ShaderNeeds {
    bool derivatives = false;              // calls Du, Dv, Deriv, area, calculatenormal, texture,
                                           // filterstep, ... or reads the globals du, dv
    bool trace = false;                    // calls trace()
    std::vector<std::string> globalsRead;  // the predefined variables its code reads ("P", "N")
};

// A shader with parameter values: the master's code specialised to the instance's constants.
class ShaderInstance {
  public:
    explicit ShaderInstance(std::shared_ptr<const Shader> shader);
    ~ShaderInstance();

    const Shader& Master() const { return *shader_; }

    // Overrides a parameter's default. Floats: width × arrayLength numbers; strings: one per
    // element. False (with *error set) for an unknown name or a wrong type or count.
    bool SetParameter(const std::string& name, const std::vector<float>& values,
                      std::string* error);
    bool SetParameter(const std::string& name, const std::vector<std::string>& values,
                      std::string* error);
    // Makes the varying (or uniform) parameter `name` take its values per point from the
    // primitive variable of the same name, passed in ShaderGlobals::primvars. False if the
    // shader has no parameter of that name.
    bool BindPrimvar(const std::string& name);
    bool IsBound(const std::string& name) const;

    // The value of a string parameter after overrides ("" if none), e.g. a light's __category.
    std::string StringParameter(const std::string& name) const;
    // The values of a numeric parameter after overrides (else its constant default); empty if
    // the shader has no such parameter or computes its default at run time.
    std::vector<float> FloatParameter(const std::string& name) const;

    // Folds constants and removes dead code with the parameter values known. Called by the
    // first Run when not called before; call it before sharing the instance between threads.
    void Specialize();
    const Program& Code() const;  // the specialised code (after Specialize)
    ShaderNeeds Needs() const;    // of the specialised code (after Specialize)
    // Keeps variables of the shader body alive through dead-code removal, so that
    // ShaderExecutor::Output can read them (`gonio shade --print`). Call before Specialize.
    void KeepVariables() { keepVariables_ = true; }

  private:
    friend class ShaderExecutor;
    struct Override {
        std::vector<float> floats;
        std::vector<std::string> strings;
    };
    std::shared_ptr<const Shader> shader_;
    std::map<std::string, Override> overrides_;
    std::vector<std::string> bound_;
    std::once_flag specialized_;
    std::shared_ptr<Program> program_;
    bool keepVariables_ = false;
};

// The shading globals of one batch of n points, component-major (batch.h). Null pointers take
// defaults: zero, except Cs = Os = 1 (and Oi = 1, Ci = 0 as inputs of volume shaders).
struct ShaderGlobals {
    int n = 0;
    const uint8_t* active = nullptr;  // points to shade; nullptr: all
    const float *P = nullptr, *N = nullptr, *Ng = nullptr, *I = nullptr;
    const float *dPdu = nullptr, *dPdv = nullptr, *dPdtime = nullptr;
    const float *u = nullptr, *v = nullptr, *du = nullptr, *dv = nullptr;
    const float *s = nullptr, *t = nullptr;
    const float *Cs = nullptr, *Os = nullptr;  // ncomps planes
    const float *Ci = nullptr, *Oi = nullptr;  // inputs of volume and imager shaders
    const float* alphas = nullptr;             // imager shaders: each pixel's alpha (null: alpha)
    const float* Ps = nullptr;                 // light shaders: the surface points being lit
    const float* Ns = nullptr;                 // ... and their normals (null: 0)
    float E[3] = {0, 0, 0};                    // the eye (camera space: the origin)
    float time = 0, dtime = 0, alpha = 1;

    struct Primvar {
        std::string name;
        TypeSpec type;
        bool varying = true;          // per point (component-major) or one value
        const float* data = nullptr;  // numbers
        const std::string* strings = nullptr;
    };
    std::vector<Primvar> primvars;  // bound to parameters by ShaderInstance::BindPrimvar
};

struct ExecState;  // runtime/interpreter.h

// Runs instances over batches. One per thread: it keeps its register memory between runs.
class ShaderExecutor {
  public:
    ShaderExecutor();
    ~ShaderExecutor();

    // Runs a surface, displacement, volume or imager shader. The context's PointCount() must
    // be globals.n. False only if the shader could not run at all (then outputs are defaults).
    bool Run(ShaderInstance& instance, const ShaderGlobals& globals, ShadingContext& context);

    // Runs a light shader for the surface points globals.Ps (and the light's own P, N, ...),
    // and fills `result` as illuminance sees it: L from the surface point to the light.
    bool RunLight(ShaderInstance& instance, const ShaderGlobals& globals, ShadingContext& context,
                  LightResult* result);

    // After Run: a global ("Ci", "Oi", "P", "N", "Cl", "L", ...) or a parameter (output
    // parameters are the shader's AOVs) by name; data == nullptr if there is none. A uniform
    // value has varying == false (one element). Valid until the next Run.
    FloatArg Output(const std::string& name) const;
    const std::string* OutputString(const std::string& name) const;

  private:
    std::unique_ptr<ExecState> state_;
};

}  // namespace gonio::sl
