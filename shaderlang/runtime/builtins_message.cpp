// Information built-ins (RISpec §15.8): attribute, option and rendererinfo, answered by the
// ShadingContext. Each returns 1 and fills its output when the renderer knows the name with
// that type, else returns 0 and leaves the output unchanged. (surface(), lightsource() and the
// other message-passing calls read other shaders' instances: the interpreter implements them.)

#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

enum class InfoSource { Attribute, Option, RendererInfo };

template <InfoSource Source>
bool Query(const BuiltinCall& call, int p, std::vector<float>* floats, std::string* text) {
    const std::string& name = call.strings[0].data[0];
    const TypeSpec& type = call.argTypes[1];
    switch (Source) {
        case InfoSource::Attribute:
            return call.context->Attribute(name, type, p, floats, text);
        case InfoSource::Option:
            return call.context->Option(name, type, floats, text);
        default:
            return call.context->RendererInfo(name, type, floats, text);
    }
}

template <InfoSource Source>
void InfoKernel(const BuiltinCall& call) {
    const TypeSpec& type = call.argTypes[1];
    if (type.base == BaseType::String) {
        std::string text;
        bool found = call.context && Query<Source>(call, 0, nullptr, &text);
        if (found) call.strings[1].data[0] = text;
        ForEachPoint(call, [&](int p) { call.result.At(0, p) = found ? 1.0f : 0.0f; });
        return;
    }
    const FloatArg& out = call.args[1];
    // Attributes may differ per point (the context is asked per point for a varying output);
    // options and renderer facts are the same everywhere, so they are asked once.
    std::vector<float> values;
    std::string unused;
    bool found = false, asked = false;
    ForEachPoint(call, [&](int p) {
        if (!asked || (Source == InfoSource::Attribute && out.varying)) {
            values.clear();
            found = call.context && Query<Source>(call, p, &values, &unused) &&
                    static_cast<int>(values.size()) >= out.width;
            asked = true;
        }
        if (found) {
            for (int c = 0; c < out.width; ++c) out.At(c, p) = values[c];
        }
        call.result.At(0, p) = found ? 1.0f : 0.0f;
    });
}

template <InfoSource Source>
void AddInfoRows(BuiltinList* list, const char* name) {
    for (const char* out : {"F", "S", "C", "P", "V", "N", "M", "F[]"}) {
        list->Add(name, "f", std::string("s") + out, InfoKernel<Source>);
    }
}

}  // namespace

void AddMessageBuiltins(BuiltinList* list) {
    AddInfoRows<InfoSource::Attribute>(list, "attribute");
    AddInfoRows<InfoSource::Option>(list, "option");
    AddInfoRows<InfoSource::RendererInfo>(list, "rendererinfo");
}

}  // namespace gonio::sl::builtins
