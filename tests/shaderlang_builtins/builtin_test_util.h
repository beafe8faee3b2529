#pragma once
// Test scaffolding for built-in kernels: a BuiltinCall builder with hand-made uniform and varying
// arguments and masks, a fake ShadingContext (spaces, lights, neighbours, options), a fake
// GlobalsView, and a checker that runs a kernel under every uniform/varying combination of its
// arguments with a mask and compares each active point to a reference function.

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "shaderlang/runtime/batch.h"
#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/globals_view.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::testing {

inline constexpr float kSentinel = -12345.0f;

TypeSpec TypeFromCode(const std::string& code);  // "f", "c", "P", "f[]" (length 0), ...
int WidthOfCode(char code, int colorComponents);

// The kernel of the table row with exactly this name, return code and argument codes.
BuiltinKernel FindKernel(const std::string& name, const std::string& returnType,
                         const std::string& arguments);
const BuiltinInfo* FindRow(const std::string& name, const std::string& returnType,
                           const std::string& arguments);

// Builds one BuiltinCall. Values are given per point, each a vector of the type's width.
class TestCall {
  public:
    explicit TestCall(int n, int colorComponents = 3);

    TestCall& Uniform(const TypeSpec& type, const std::vector<float>& value);
    TestCall& Varying(const TypeSpec& type, const std::vector<std::vector<float>>& perPoint);
    TestCall& Float(float v) { return Uniform(TypeSpec{BaseType::Float}, {v}); }
    TestCall& String(const std::string& s);
    TestCall& Mask(const std::vector<uint8_t>& active);
    TestCall& Result(const TypeSpec& type, bool varying);
    TestCall& StringResult();
    TestCall& Context(ShadingContext* context);
    TestCall& Globals(const GlobalsView* globals);

    // Runs the kernel; the result (and any outputs) keep their values for inspection.
    void Run(BuiltinKernel kernel);
    const BuiltinCall& Call() const { return call_; }

    float R(int component, int point = 0) const { return call_.result.At(component, point); }
    float Arg(int index, int component, int point = 0) const {
        return call_.args[index].At(component, point);
    }
    const std::string& StringOut() const { return *stringResult_; }
    const std::string& StringArgValue(int index) const { return *strings_.at(index); }

  private:
    int Width(const TypeSpec& type) const;
    std::vector<float>& NewStorage(size_t size);

    int n_, colorComponents_;
    BuiltinCall call_;
    std::vector<std::unique_ptr<std::vector<float>>> storage_;
    std::map<int, std::unique_ptr<std::string>> strings_;
    std::unique_ptr<std::string> stringResult_;
    std::vector<uint8_t> mask_;
};

// Per point, per argument: the argument's components at that point.
using PointArgs = std::vector<std::vector<float>>;
using Reference = std::function<std::vector<float>(const PointArgs&)>;

// Runs row (name, ret, args) -- numeric arguments only -- under every uniform/varying
// combination of the arguments. inputs[a][p] is argument a's value at point p (a uniform
// argument takes point 0's value). rowArguments names the table row when it differs from the
// argument codes (a "*" row). Varying calls run with every third point masked off and
// must leave those points untouched; each computed point must match `reference` within tol.
void ExpectAllVariants(const std::string& name, const std::string& returnType,
                       const std::string& arguments,
                       const std::vector<std::vector<std::vector<float>>>& inputs,
                       const Reference& reference, float tol = 1e-5f, int colorComponents = 3,
                       const std::string& rowArguments = "");

// A ShadingContext with settable spaces, lights, neighbours and options.
class FakeContext : public ShadingContext {
  public:
    explicit FakeContext(int n, int colorComponents = 3) {
        n_ = n;
        colorComponents_ = colorComponents;
    }

    bool CurrentFromSpace(const std::string& space, int point, Imath::M44f* m) const override;
    const std::vector<LightResult>& Lights() override {
        ++lightQueries;
        return lights;
    }
    bool Texture(const std::string& name, int firstChannel, int channels,
                 const TextureWrapModes& wrap, const float* s, const float* t, const float* dsdx,
                 const float* dtdx, const float* dsdy, const float* dtdy, const uint8_t* active,
                 float* out) override;
    bool Environment(const std::string& name, int firstChannel, int channels,
                     const float* directions, const uint8_t* active, float* out) override;
    bool Shadow(const std::string& name, const float* points, const uint8_t* active,
                const ShadowOptions& options, float* out) override;
    ShadowOptions lastShadowOptions;
    void Trace(const float* P, const float* R, const uint8_t* active, float* out) override;
    bool Attribute(const std::string& name, const TypeSpec& type, int point,
                   std::vector<float>* floats, std::string* text) const override;
    bool Option(const std::string& name, const TypeSpec& type, std::vector<float>* floats,
                std::string* text) const override;
    bool RendererInfo(const std::string& name, const TypeSpec& type, std::vector<float>* floats,
                      std::string* text) const override;
    void RuntimeWarning(const std::string& key, const std::string& message) override {
        warnings[key] = message;
    }
    void Print(const std::string& text) override { printed.push_back(text); }
    const int* UNeighbours() const override {
        return uNeighbours.empty() ? nullptr : uNeighbours.data();
    }
    const int* VNeighbours() const override {
        return vNeighbours.empty() ? nullptr : vNeighbours.data();
    }
    const float* NeighbourSteps() const override {
        return neighbourSteps.empty() ? nullptr : neighbourSteps.data();
    }

    std::map<std::string, Imath::M44f> currentFromSpace;
    std::vector<LightResult> lights;
    int lightQueries = 0;
    std::vector<int> uNeighbours, vNeighbours;
    std::vector<float> neighbourSteps;  // 4 × n (ShadingContext::NeighbourSteps); empty: none
    std::map<std::string, std::vector<float>> floatInfo;  // attributes, options, renderer
    std::map<std::string, std::string> stringInfo;
    std::map<std::string, std::string> warnings;
    std::vector<std::string> printed;
    // Texture records: the last lookup's arguments; the texture is s + 10·t + 100·channel.
    std::string lastTexture;
    int lastFirstChannel = -1;
    TextureWrapModes lastWrap;
    std::vector<float> lastDsdx, lastDtdy;
};

// A GlobalsView over named planes (varying) or single values (uniform).
class FakeGlobals : public GlobalsView {
  public:
    explicit FakeGlobals(int n) : n_(n) {}
    void SetVarying(const std::string& name, int width, std::vector<float> planes);
    void SetUniform(const std::string& name, std::vector<float> value);
    FloatArg Get(const std::string& name) const override;

  private:
    struct Value {
        std::vector<float> data;
        int width;
        bool varying;
    };
    int n_;
    std::map<std::string, Value> values_;
};

}  // namespace gonio::sl::testing
