// Point-cloud built-ins (PRMan's and Pixie's baking, beyond RISpec 3.2), through ShadingContext
// (the renderer keeps the clouds, renderer/shading/point_cloud*):
//
//   float bake3d(string file; string displaychannels; point P; normal N; "name", value, ...)
//   float texture3d(string file; point P; normal N; "name", output value, ...)
//   float bake(string file; float s, t; value)
//
// bake3d stores P, N and each ("name", value) pair whose name `displaychannels` lists (comma-
// or space-separated; "" keeps them all); texture3d writes each variable with the value of the
// point nearest to P. bake is bake3d of one channel "value" at P = (s, t, 0). Each returns 1
// where it stored or found the values, else 0.

#include <sstream>
#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

// A point-like argument as 3 planes of n floats (a uniform one repeated).
std::vector<float> Planes(const BuiltinCall& call, const FloatArg& a) {
    std::vector<float> out(3 * size_t(call.n), 0.0f);
    if (!a.data) return out;
    for (int c = 0; c < 3; ++c)
        for (int p = 0; p < call.n; ++p) out[size_t(c) * call.n + p] = a.At(c, p);
    return out;
}

std::vector<std::string> ChannelList(const std::string& text) {
    std::vector<std::string> names;
    std::string name;
    std::istringstream in(text);
    while (in >> name) {
        std::stringstream parts(name);
        std::string part;
        while (std::getline(parts, part, ','))
            if (!part.empty()) names.push_back(part);
    }
    return names;
}

// The ("name", value) pairs from argument `first` on; `keep` (if not empty) selects names.
std::vector<PointChannel> Pairs(const BuiltinCall& call, int first,
                                const std::vector<std::string>& keep) {
    std::vector<PointChannel> channels;
    for (int a = first; a + 1 < call.argCount; a += 2) {
        if (call.argTypes[a].base != BaseType::String || !call.strings[a].data) continue;
        const TypeSpec& type = call.argTypes[a + 1];
        if (type.base == BaseType::String || type.IsArray() || !call.args[a + 1].data) continue;
        const std::string& name = call.strings[a].data[0];
        bool listed = keep.empty();
        for (const std::string& k : keep) listed = listed || k == name;
        if (listed) channels.push_back({name, call.args[a + 1].width, call.args[a + 1]});
    }
    return channels;
}

void SetResult(const BuiltinCall& call, bool ok) {
    ForEachPoint(call, [&](int p) { call.result.At(0, p) = ok ? 1.0f : 0.0f; });
}

void Bake3dKernel(const BuiltinCall& call) {
    const std::vector<float> P = Planes(call, call.args[2]), N = Planes(call, call.args[3]);
    const std::vector<PointChannel> channels = Pairs(call, 4, ChannelList(call.strings[1].data[0]));
    SetResult(call, call.context->BakePoints(call.strings[0].data[0], P.data(), N.data(),
                                             call.active, channels));
}

void BakeKernel(const BuiltinCall& call) {
    std::vector<float> P(3 * size_t(call.n), 0.0f), N(3 * size_t(call.n), 0.0f);
    for (int p = 0; p < call.n; ++p)
        P[p] = Float(call.args[1], p), P[call.n + p] = Float(call.args[2], p);
    const std::vector<PointChannel> channels = {{"value", call.args[3].width, call.args[3]}};
    SetResult(call, call.context->BakePoints(call.strings[0].data[0], P.data(), N.data(),
                                             call.active, channels));
}

void Texture3dKernel(const BuiltinCall& call) {
    const std::vector<float> P = Planes(call, call.args[1]), N = Planes(call, call.args[2]);
    const std::vector<PointChannel> channels = Pairs(call, 3, {});
    SetResult(call, call.context->LookupPoints(call.strings[0].data[0], P.data(), N.data(),
                                               call.active, channels));
}

}  // namespace

void AddPointCloudBuiltins(BuiltinList* list) {
    const unsigned bakes = kVaryingResult | kHasSideEffects;
    for (const char* normal : {"n", "v"}) {
        list->Add("bake3d", "f", std::string("ssp") + normal + "*", Bake3dKernel, bakes);
        list->Add("texture3d", "f", std::string("sp") + normal + "*", Texture3dKernel,
                  kVaryingResult | kReadsFiles | kOutputPairs);
    }
    for (const char* value : kNumericCodes)
        list->Add("bake", "f", std::string("sff") + value, BakeKernel, bakes);
}

}  // namespace gonio::sl::builtins
