#include "builtin_test_util.h"

#include <cmath>

namespace gonio::sl::testing {

TypeSpec TypeFromCode(const std::string& code) { return TypeOfCode(code[0]); }

int WidthOfCode(char code, int colorComponents) { return TypeOfCode(code).Width(colorComponents); }

const BuiltinInfo* FindRow(const std::string& name, const std::string& returnType,
                           const std::string& arguments) {
    for (const BuiltinInfo& row : BuiltinTable()) {
        if (name == row.name && returnType == row.returnType && arguments == row.arguments) {
            return &row;
        }
    }
    return nullptr;
}

BuiltinKernel FindKernel(const std::string& name, const std::string& returnType,
                         const std::string& arguments) {
    const BuiltinInfo* row = FindRow(name, returnType, arguments);
    EXPECT_NE(row, nullptr) << "no built-in " << returnType << " " << name << "(" << arguments
                            << ")";
    return row ? row->kernel : nullptr;
}

TestCall::TestCall(int n, int colorComponents) : n_(n), colorComponents_(colorComponents) {
    call_.n = n;
    call_.colorComponents = colorComponents;
}

int TestCall::Width(const TypeSpec& type) const {
    return type.Width(colorComponents_) * std::max(1, type.arrayLength);
}

std::vector<float>& TestCall::NewStorage(size_t size) {
    storage_.push_back(std::make_unique<std::vector<float>>(size, 0.0f));
    return *storage_.back();
}

TestCall& TestCall::Uniform(const TypeSpec& type, const std::vector<float>& value) {
    int a = call_.argCount++;
    std::vector<float>& data = NewStorage(Width(type));
    for (size_t i = 0; i < value.size() && i < data.size(); ++i) data[i] = value[i];
    call_.argTypes[a] = type;
    call_.args[a] = FloatArg{data.data(), Width(type), false, n_};
    return *this;
}

TestCall& TestCall::Varying(const TypeSpec& type, const std::vector<std::vector<float>>& perPoint) {
    int a = call_.argCount++;
    const int w = Width(type);
    std::vector<float>& data = NewStorage(static_cast<size_t>(w) * n_);
    for (int p = 0; p < n_ && p < static_cast<int>(perPoint.size()); ++p) {
        for (int c = 0; c < w && c < static_cast<int>(perPoint[p].size()); ++c) {
            data[c * n_ + p] = perPoint[p][c];
        }
    }
    call_.argTypes[a] = type;
    call_.args[a] = FloatArg{data.data(), w, true, n_};
    return *this;
}

TestCall& TestCall::String(const std::string& s) {
    int a = call_.argCount++;
    strings_[a] = std::make_unique<std::string>(s);
    call_.argTypes[a] = TypeSpec{BaseType::String};
    call_.strings[a] = StringArg{strings_[a].get()};
    return *this;
}

TestCall& TestCall::Mask(const std::vector<uint8_t>& active) {
    mask_ = active;
    call_.active = mask_.data();
    return *this;
}

TestCall& TestCall::Result(const TypeSpec& type, bool varying) {
    const int w = Width(type);
    std::vector<float>& data = NewStorage(static_cast<size_t>(w) * (varying ? n_ : 1));
    std::fill(data.begin(), data.end(), kSentinel);
    call_.resultType = type;
    call_.result = FloatArg{data.data(), w, varying, n_};
    return *this;
}

TestCall& TestCall::StringResult() {
    stringResult_ = std::make_unique<std::string>();
    call_.resultType = TypeSpec{BaseType::String};
    call_.stringResult = StringArg{stringResult_.get()};
    return *this;
}

TestCall& TestCall::Context(ShadingContext* context) {
    call_.context = context;
    return *this;
}

TestCall& TestCall::Globals(const GlobalsView* globals) {
    call_.globals = globals;
    return *this;
}

void TestCall::Run(BuiltinKernel kernel) {
    ASSERT_NE(kernel, nullptr);
    kernel(call_);
}

void ExpectAllVariants(const std::string& name, const std::string& returnType,
                       const std::string& arguments,
                       const std::vector<std::vector<std::vector<float>>>& inputs,
                       const Reference& reference, float tol, int colorComponents,
                       const std::string& rowArguments) {
    BuiltinKernel kernel =
        FindKernel(name, returnType, rowArguments.empty() ? arguments : rowArguments);
    ASSERT_NE(kernel, nullptr);
    const int argCount = static_cast<int>(arguments.size());
    ASSERT_EQ(static_cast<int>(inputs.size()), argCount);
    const int n = static_cast<int>(inputs[0].size());
    const TypeSpec resultType = TypeFromCode(returnType);
    for (int variant = 0; variant < (1 << argCount); ++variant) {
        const bool anyVarying = variant != 0;
        TestCall call(n, colorComponents);
        std::vector<uint8_t> mask(n);
        for (int p = 0; p < n; ++p) mask[p] = p % 3 != 1;
        if (anyVarying) call.Mask(mask);
        for (int a = 0; a < argCount; ++a) {
            TypeSpec type = TypeOfCode(arguments[a]);
            if (variant & (1 << a))
                call.Varying(type, inputs[a]);
            else
                call.Uniform(type, inputs[a][0]);
        }
        call.Result(resultType, anyVarying);
        call.Run(kernel);
        const int points = anyVarying ? n : 1;
        for (int p = 0; p < points; ++p) {
            PointArgs at(argCount);
            for (int a = 0; a < argCount; ++a) at[a] = inputs[a][(variant & (1 << a)) ? p : 0];
            const std::vector<float> expected = reference(at);
            for (int c = 0; c < static_cast<int>(expected.size()); ++c) {
                if (anyVarying && !mask[p]) {
                    EXPECT_EQ(call.R(c, p), kSentinel)
                        << name << " wrote masked point " << p << " (variant " << variant << ")";
                } else {
                    EXPECT_NEAR(call.R(c, p), expected[c], tol)
                        << name << "(" << arguments << ") point " << p << " component " << c
                        << " variant " << variant;
                }
            }
        }
    }
}

bool FakeContext::CurrentFromSpace(const std::string& space, int, Imath::M44f* m) const {
    if (space == "current" || space == "camera") {
        *m = Imath::M44f();
        return true;
    }
    auto it = currentFromSpace.find(space);
    if (it == currentFromSpace.end()) return false;
    *m = it->second;
    return true;
}

bool FakeContext::Texture(const std::string& name, int firstChannel, int channels,
                          const TextureWrapModes& wrap, const float* s, const float* t,
                          const float* dsdx, const float*, const float*, const float* dtdy,
                          const uint8_t* active, float* out) {
    lastTexture = name;
    lastFirstChannel = firstChannel;
    lastWrap = wrap;
    lastDsdx.assign(dsdx, dsdx + n_);
    lastDtdy.assign(dtdy, dtdy + n_);
    if (name == "missing.tx") return false;
    for (int p = 0; p < n_; ++p) {
        if (active && !active[p]) continue;
        for (int c = 0; c < channels; ++c) {
            out[c * n_ + p] = s[p] + 10.0f * t[p] + 100.0f * (firstChannel + c);
        }
    }
    return true;
}

bool FakeContext::Environment(const std::string& name, int firstChannel, int channels,
                              const float* directions, const uint8_t* active, float* out) {
    lastTexture = name;
    lastFirstChannel = firstChannel;
    for (int p = 0; p < n_; ++p) {
        if (active && !active[p]) continue;
        for (int c = 0; c < channels; ++c) out[c * n_ + p] = directions[(c % 3) * n_ + p];
    }
    return true;
}

bool FakeContext::Shadow(const std::string& name, const float* points, const uint8_t* active,
                         const ShadowOptions& options, float* out) {
    lastTexture = name;
    lastShadowOptions = options;
    for (int p = 0; p < n_; ++p) {
        if (!active || active[p]) out[p] = points[p] > 0.0f ? 1.0f : 0.0f;  // x > 0: shadowed
    }
    return true;
}

void FakeContext::Trace(const float* P, const float* R, const uint8_t* active, float* out) {
    for (int p = 0; p < n_; ++p) {
        if (active && !active[p]) continue;
        for (int c = 0; c < colorComponents_; ++c) {
            out[c * n_ + p] = P[(c % 3) * n_ + p] + R[(c % 3) * n_ + p];
        }
    }
}

bool FakeContext::Attribute(const std::string& name, const TypeSpec& type, int point,
                            std::vector<float>* floats, std::string* text) const {
    if (name == "user:perpoint" && type.base == BaseType::Float) {
        floats->assign(1, static_cast<float>(point));
        return true;
    }
    return Option("attr:" + name, type, floats, text);
}

bool FakeContext::Option(const std::string& name, const TypeSpec& type, std::vector<float>* floats,
                         std::string* text) const {
    if (type.base == BaseType::String) {
        auto it = stringInfo.find(name);
        if (it == stringInfo.end()) return false;
        *text = it->second;
        return true;
    }
    auto it = floatInfo.find(name);
    if (it == floatInfo.end()) return false;
    if (static_cast<int>(it->second.size()) !=
        type.Width(colorComponents_) * std::max(1, type.arrayLength)) {
        return false;
    }
    *floats = it->second;
    return true;
}

bool FakeContext::RendererInfo(const std::string& name, const TypeSpec& type,
                               std::vector<float>* floats, std::string* text) const {
    return Option("renderer:" + name, type, floats, text);
}

void FakeGlobals::SetVarying(const std::string& name, int width, std::vector<float> planes) {
    values_[name] = Value{std::move(planes), width, true};
}

void FakeGlobals::SetUniform(const std::string& name, std::vector<float> value) {
    int width = static_cast<int>(value.size());
    values_[name] = Value{std::move(value), width, false};
}

FloatArg FakeGlobals::Get(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) return FloatArg{};
    const Value& v = it->second;
    return FloatArg{const_cast<float*>(v.data.data()), v.width, v.varying, n_};
}

}  // namespace gonio::sl::testing
