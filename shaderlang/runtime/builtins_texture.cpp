// Texture built-ins (RISpec §15.7): texture, environment, shadow and textureinfo, through
// ShadingContext (the renderer uses OpenImageIO's TextureSystem).
//
// RSL's name[chan] selects the first channel (the compiler turns it into a trailing
// ("firstchannel", chan) option). The coordinates
// are the numeric arguments after the name: texture takes (s, t) or the four corners
// (s1, t1, ..., s4, t4); texture("name") reads the globals s and t.
// environment takes D or D1..D4, shadow P or P1..P4 (four are averaged). Then come optional
// ("name", value) pairs: "width"/"swidth"/"twidth" scale the filter footprint, "blur"/"sblur"/
// "tblur" widen it by a fraction of the texture; "swrap"/"twrap"/"wrap" (PRMan's names) say how
// texture() reads s and t outside [0, 1] ("black", "clamp", "periodic"; by default as the file
// records); "filter" and "fill" are accepted and left to the renderer's defaults. shadow()
// passes "samples", the widths, the blurs and "bias" to the renderer's percentage-closer
// filter (ShadowOptions).

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "shaderlang/runtime/builtins_derivatives.h"
#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/runtime/globals_view.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

struct TextureName {
    std::string file;
    int firstChannel = 0;
};

// The file name and the first channel, which the compiler passes as a trailing
// ("firstchannel", k) option for RSL's name[k] syntax.
TextureName ReadTextureName(const BuiltinCall& call) {
    TextureName out{call.strings[0].data[0], 0};
    for (int a = 1; a + 1 < call.argCount; ++a) {
        if (call.argTypes[a].base == BaseType::String && call.strings[a].data &&
            call.strings[a].data[0] == "firstchannel" &&
            call.argTypes[a + 1].base == BaseType::Float) {
            out.firstChannel = std::max(0, static_cast<int>(Float(call.args[a + 1], 0)));
        }
    }
    return out;
}

// The numeric arguments after the name, up to the first string (the options).
int CoordinateArgCount(const BuiltinCall& call) {
    int count = 0;
    while (1 + count < call.argCount && call.argTypes[1 + count].base != BaseType::String) ++count;
    return count;
}

struct TextureOptions {
    float swidth = 1.0f, twidth = 1.0f, sblur = 0.0f, tblur = 0.0f;
};

TextureOptions ParseOptions(const BuiltinCall& call, int first) {
    TextureOptions o;
    for (int a = first; a + 1 < call.argCount; a += 2) {
        if (call.argTypes[a].base != BaseType::String || !call.strings[a].data) continue;
        if (call.argTypes[a + 1].base != BaseType::Float) continue;
        const std::string& name = call.strings[a].data[0];
        float v = Float(call.args[a + 1], 0);
        if (name == "width")
            o.swidth = o.twidth = v;
        else if (name == "swidth")
            o.swidth = v;
        else if (name == "twidth")
            o.twidth = v;
        else if (name == "blur")
            o.sblur = o.tblur = v;
        else if (name == "sblur")
            o.sblur = v;
        else if (name == "tblur")
            o.tblur = v;
    }
    return o;
}

// The "swrap", "twrap" and "wrap" options; an unknown mode is warned about and left to the file.
TextureWrapModes ParseWrapOptions(const BuiltinCall& call, int first) {
    TextureWrapModes wrap;
    for (int a = first; a + 1 < call.argCount; a += 2) {
        if (call.argTypes[a].base != BaseType::String || !call.strings[a].data) continue;
        if (call.argTypes[a + 1].base != BaseType::String || !call.strings[a + 1].data) continue;
        const std::string& name = call.strings[a].data[0];
        if (name != "swrap" && name != "twrap" && name != "wrap") continue;
        const std::string& value = call.strings[a + 1].data[0];
        const std::optional<TextureWrap> mode = TextureWrapFromName(value);
        if (!mode) {
            if (call.context)
                call.context->RuntimeWarning("texture:wrap " + value,
                                             "texture(): \"" + name + "\" \"" + value +
                                                 "\" is not \"black\", \"clamp\" or "
                                                 "\"periodic\"; the file's mode is used");
            continue;
        }
        if (name != "twrap") wrap.s = *mode;
        if (name != "swrap") wrap.t = *mode;
    }
    return wrap;
}

// Copies component c of a value into a plane of n floats (uniform values broadcast).
void Plane(const BuiltinCall& call, const FloatArg& value, int c, std::vector<float>* out) {
    out->assign(call.n, 0.0f);
    if (!value.data) return;
    for (int p = 0; p < call.n; ++p) (*out)[p] = value.At(c, p);
}
void Plane(const BuiltinCall& call, int a, int c, std::vector<float>* out) {
    Plane(call, call.args[a], c, out);
}

// Differences of a plane across one grid step (batch neighbours, derivatives.h).
std::vector<float> StepDifference(const BuiltinCall& call, const std::vector<float>& v,
                                  const Stencil& stencil) {
    FloatArg plane{const_cast<float*>(v.data()), 1, true, call.n};
    std::vector<float> d(v.size());
    for (int p = 0; p < call.n; ++p) d[p] = Delta(stencil, plane, 0, p);
    return d;
}

void CopyOut(const BuiltinCall& call, const std::vector<float>& out) {
    const int n = call.n, w = call.result.width;
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < w; ++c) call.result.At(c, p) = out[c * n + p];
    });
}

void TextureKernel(const BuiltinCall& call) {
    const int n = call.n, w = call.result.width;
    const TextureName name = ReadTextureName(call);
    const int coords = CoordinateArgCount(call);
    const TextureOptions options = ParseOptions(call, 1 + coords);
    const TextureWrapModes wrap = ParseWrapOptions(call, 1 + coords);
    std::vector<float> s, t, dsdx, dtdx, dsdy, dtdy;
    if (coords >= 8) {  // four corners: (s1,t1) (s2,t2) along u, (s3,t3) along v
        std::vector<float> s2, t2, s3, t3;
        Plane(call, 1, 0, &s);
        Plane(call, 2, 0, &t);
        Plane(call, 3, 0, &s2);
        Plane(call, 4, 0, &t2);
        Plane(call, 5, 0, &s3);
        Plane(call, 6, 0, &t3);
        dsdx.resize(n), dtdx.resize(n), dsdy.resize(n), dtdy.resize(n);
        for (int p = 0; p < n; ++p) {
            dsdx[p] = s2[p] - s[p], dtdx[p] = t2[p] - t[p];
            dsdy[p] = s3[p] - s[p], dtdy[p] = t3[p] - t[p];
        }
    } else {
        if (coords >= 2) {
            Plane(call, 1, 0, &s);
            Plane(call, 2, 0, &t);
        } else {  // texture("name"): the globals s and t
            if (!call.globals || !call.globals->Get("s").data) {
                if (call.context) {
                    call.context->RuntimeWarning("texture:coordinates",
                                                 "texture() has no s and t to look up");
                }
            }
            if (call.globals) {
                Plane(call, call.globals->Get("s"), 0, &s);
                Plane(call, call.globals->Get("t"), 0, &t);
            } else {
                s.assign(n, 0.0f), t.assign(n, 0.0f);
            }
        }
        const Stencil su = UStencil(call), sv = VStencil(call);
        dsdx = StepDifference(call, s, su), dtdx = StepDifference(call, t, su);
        dsdy = StepDifference(call, s, sv), dtdy = StepDifference(call, t, sv);
    }
    for (int p = 0; p < n; ++p) {
        dsdx[p] = dsdx[p] * options.swidth + std::copysign(options.sblur, dsdx[p]);
        dsdy[p] *= options.swidth;
        dtdx[p] *= options.twidth;
        dtdy[p] = dtdy[p] * options.twidth + std::copysign(options.tblur, dtdy[p]);
    }
    std::vector<float> out(static_cast<size_t>(w) * n, 0.0f);
    // A file that cannot be read gives black; the context says why.
    if (call.context)
        call.context->Texture(name.file, name.firstChannel, w, wrap, s.data(), t.data(),
                              dsdx.data(), dtdx.data(), dsdy.data(), dtdy.data(), call.active,
                              out.data());
    CopyOut(call, out);
}

// The mean of the coordinate triples after the name, as 3 planes of n floats.
std::vector<float> MeanTriple(const BuiltinCall& call, int count) {
    const int n = call.n;
    std::vector<float> v(3 * static_cast<size_t>(n), 0.0f);
    for (int a = 1; a <= count; ++a) {
        for (int c = 0; c < 3; ++c) {
            for (int p = 0; p < n; ++p) v[c * n + p] += call.args[a].At(c, p) / count;
        }
    }
    return v;
}

void EnvironmentKernel(const BuiltinCall& call) {
    const int n = call.n, w = call.result.width;
    const TextureName name = ReadTextureName(call);
    const int coords = CoordinateArgCount(call);
    std::vector<float> directions = MeanTriple(call, coords >= 4 ? 4 : 1);
    std::vector<float> out(static_cast<size_t>(w) * n, 0.0f);
    if (call.context)
        call.context->Environment(name.file, name.firstChannel, w, directions.data(), call.active,
                                  out.data());
    CopyOut(call, out);
}

ShadowOptions ParseShadowOptions(const BuiltinCall& call, int first) {
    const TextureOptions footprint = ParseOptions(call, first);
    ShadowOptions o;
    o.swidth = footprint.swidth, o.twidth = footprint.twidth;
    o.sblur = footprint.sblur, o.tblur = footprint.tblur;
    for (int a = first; a + 1 < call.argCount; a += 2) {
        if (call.argTypes[a].base != BaseType::String || !call.strings[a].data) continue;
        if (call.argTypes[a + 1].base != BaseType::Float) continue;
        const std::string& name = call.strings[a].data[0];
        if (name == "samples") o.samples = Float(call.args[a + 1], 0);
        if (name == "bias") o.bias = Float(call.args[a + 1], 0);
    }
    return o;
}

void ShadowKernel(const BuiltinCall& call) {
    const int n = call.n;
    const TextureName name = ReadTextureName(call);
    const int coords = CoordinateArgCount(call);
    std::vector<float> points = MeanTriple(call, coords >= 4 ? 4 : 1);
    const ShadowOptions options = ParseShadowOptions(call, 1 + coords);
    std::vector<float> out(n, 0.0f);
    if (call.context)
        call.context->Shadow(name.file, points.data(), call.active, options, out.data());
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < call.result.width; ++c) call.result.At(c, p) = out[p];
    });
}

// textureinfo(name, dataname, output v) (RISpec Table 15.3): 1 and v filled when the texture
// has the fact with v's type ("resolution" float[2], "channels" float, "type" string,
// "viewingmatrix" and "projectionmatrix" matrix), else 0 and v unchanged.
void TextureInfoKernel(const BuiltinCall& call) {
    std::vector<float> floats;
    std::string text;
    bool found = call.context && call.context->TextureInfo(call.strings[0].data[0],
                                                           call.strings[1].data[0], &floats, &text);
    if (call.argTypes[2].base == BaseType::String) {
        found = found && floats.empty();
        if (found) call.strings[2].data[0] = text;
    } else {
        const FloatArg& out = call.args[2];
        found = found && static_cast<int>(floats.size()) == out.width;
        if (found) {
            ForEachPoint(call, [&](int p) {
                for (int c = 0; c < out.width; ++c) out.At(c, p) = floats[c];
            });
        }
    }
    ForEachPoint(call, [&](int p) { call.result.At(0, p) = found ? 1.0f : 0.0f; });
}

}  // namespace

void AddTextureBuiltins(BuiltinList* list) {
    for (const char* out : {"F", "S", "M", "F[]"})
        list->Add("textureinfo", "f", std::string("ss") + out, TextureInfoKernel);
    const unsigned flags = kVaryingResult | kNeedsDerivatives | kReadsGlobals;
    list->Add("texture", "f", "s*", TextureKernel, flags);
    list->Add("texture", "c", "s*", TextureKernel, flags);
    list->Add("environment", "f", "s*", EnvironmentKernel, kVaryingResult);
    list->Add("environment", "c", "s*", EnvironmentKernel, kVaryingResult);
    list->Add("shadow", "f", "s*", ShadowKernel, kVaryingResult);
    list->Add("shadow", "c", "s*", ShadowKernel, kVaryingResult);
}

}  // namespace gonio::sl::builtins
