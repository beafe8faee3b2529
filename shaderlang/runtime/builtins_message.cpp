// Message passing and information built-ins (RISpec §15.8). surface(), displacement() and
// atmosphere() read a parameter of the batch's shader of that kind (ShadingContext::
// ShaderParameter); lightsource() reads one of the light that the enclosing illuminance loop
// runs for; incident() and opposite() find no volume shader (none runs). attribute, option and
// rendererinfo are answered by the ShadingContext. Each returns 1 and fills its output when the
// name exists with that type, else returns 0 and leaves the output unchanged.

#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/runtime/globals_view.h"
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

// A parameter of type `source` fills an output of type `out`: the same type (point, vector and
// normal are interchangeable: all are current-space triples) and array length.
bool TypesMatch(const TypeSpec& source, const TypeSpec& out) {
    if (source.arrayLength != out.arrayLength) return false;
    return source.base == out.base || (source.IsPointLike() && out.IsPointLike());
}

bool FindMessage(const BuiltinCall& call, MessageSource source, MessageValue* value) {
    const std::string& name = call.strings[0].data[0];
    if (source == MessageSource::Light) {
        const LightResult* light = call.globals ? call.globals->CurrentLight() : nullptr;
        return light && light->FindParameter(name, call.n, value);
    }
    return call.context && call.context->ShaderParameter(source, name, value);
}

template <MessageSource Source>
void MessageKernel(const BuiltinCall& call) {
    const TypeSpec& type = call.argTypes[1];
    MessageValue value;
    bool found = FindMessage(call, Source, &value) && TypesMatch(value.type, type);
    if (type.base == BaseType::String) {
        found = found && value.text;
        if (found) call.strings[1].data[0] = *value.text;
        ForEachPoint(call, [&](int p) { call.result.At(0, p) = found ? 1.0f : 0.0f; });
        return;
    }
    const FloatArg& out = call.args[1];
    const FloatArg& in = value.floats;
    // A varying value cannot fill a uniform variable (RISpec §15.8).
    found = found && in.data && in.width == out.width && (out.varying || !in.varying);
    ForEachPoint(call, [&](int p) {
        if (found) {
            for (int c = 0; c < out.width; ++c) out.At(c, p) = in.At(c, p);
        }
        call.result.At(0, p) = found ? 1.0f : 0.0f;
    });
}

// incident() and opposite() read the interior or exterior volume shader on either side of the
// surface (RISpec §15.8). gonio records Interior and Exterior requests but runs no such shaders,
// so there is never one to ask: 0, and the output is left unchanged.
void NoVolumeShaderKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) { call.result.At(0, p) = 0.0f; });
}

const char* const kMessageOutputs[] = {"F", "S",   "C",   "P",   "V",   "N",
                                       "M", "F[]", "C[]", "P[]", "V[]", "N[]"};

template <MessageSource Source>
void AddMessageRows(BuiltinList* list, const char* name) {
    // The values differ per point: the result is varying even for uniform arguments, and a
    // variable the message fills is inferred varying unless declared uniform.
    for (const char* out : kMessageOutputs) {
        list->Add(name, "f", std::string("s") + out, MessageKernel<Source>, kVaryingResult);
    }
}

void AddVolumeMessageRows(BuiltinList* list, const char* name) {
    for (const char* out : kMessageOutputs) {
        list->Add(name, "f", std::string("s") + out, NoVolumeShaderKernel, kVaryingResult);
    }
}

}  // namespace

void AddMessageBuiltins(BuiltinList* list) {
    AddMessageRows<MessageSource::Surface>(list, "surface");
    AddMessageRows<MessageSource::Displacement>(list, "displacement");
    AddMessageRows<MessageSource::Atmosphere>(list, "atmosphere");
    AddMessageRows<MessageSource::Light>(list, "lightsource");
    AddVolumeMessageRows(list, "incident");
    AddVolumeMessageRows(list, "opposite");
    AddInfoRows<InfoSource::Attribute>(list, "attribute");
    AddInfoRows<InfoSource::Option>(list, "option");
    AddInfoRows<InfoSource::RendererInfo>(list, "rendererinfo");
}

}  // namespace gonio::sl::builtins
