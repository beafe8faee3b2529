// Colour built-ins (RISpec §15.3): comp, setcomp, ctransform between colour spaces, and
// luminance (EXT). mix lives with the math built-ins (one kernel for every type).
//
// Colour spaces: "rgb" (linear, Rec. 709 primaries, D65 white), "hsv", "hsl" (hue in [0, 1)),
// "xyz"/"XYZ" (CIE 1931 XYZ from those primaries), "xyY" (chromaticity and luminance) and
// "YIQ" (NTSC). Only 3-component colours convert; with ColorSamples other than 3 ctransform
// warns and returns its input.

#include <algorithm>
#include <cmath>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

void CompKernel(const BuiltinCall& call) {
    const int w = call.args[0].width;
    ForEachPoint(call, [&](int p) {
        int i = static_cast<int>(Float(call.args[1], p));
        call.result.At(0, p) = (i >= 0 && i < w) ? call.args[0].At(i, p) : 0.0f;
    });
}

// setcomp(output c, index, value); an index out of range leaves c unchanged.
void SetCompKernel(const BuiltinCall& call) {
    const int w = call.args[0].width;
    ForEachPoint(call, [&](int p) {
        int i = static_cast<int>(Float(call.args[1], p));
        if (i >= 0 && i < w) call.args[0].At(i, p) = Float(call.args[2], p);
    });
}

// sRGB/Rec. 709 primaries with a D65 white (IEC 61966-2-1).
const M44 kXyzFromRgbRows(0.412453f, 0.357580f, 0.180423f, 0.0f,  //
                          0.212671f, 0.715160f, 0.072169f, 0.0f,  //
                          0.019334f, 0.119193f, 0.950227f, 0.0f,  //
                          0.0f, 0.0f, 0.0f, 1.0f);
// NTSC YIQ (FCC 1953).
const M44 kYiqFromRgbRows(0.299f, 0.587f, 0.114f, 0.0f,    //
                          0.596f, -0.274f, -0.322f, 0.0f,  //
                          0.211f, -0.523f, 0.312f, 0.0f,   //
                          0.0f, 0.0f, 0.0f, 1.0f);

// The matrices above are written as rows acting on column vectors: y = M·x.
V3 Apply(const M44& rows, const V3& x) {
    V3 y;
    rows.transposed().multDirMatrix(x, y);
    return y;
}

V3 HsvFromRgb(const V3& c) {
    float mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z});
    float d = mx - mn;
    float h = 0.0f;
    if (d > 0.0f) {
        if (mx == c.x)
            h = (c.y - c.z) / d;
        else if (mx == c.y)
            h = 2.0f + (c.z - c.x) / d;
        else
            h = 4.0f + (c.x - c.y) / d;
        h /= 6.0f;
        if (h < 0.0f) h += 1.0f;
    }
    return V3(h, mx > 0.0f ? d / mx : 0.0f, mx);
}

V3 RgbFromHsv(const V3& c) {
    float h = (c.x - std::floor(c.x)) * 6.0f, s = c.y, v = c.z;
    int sector = static_cast<int>(h) % 6;
    float f = h - std::floor(h);
    float p = v * (1.0f - s), q = v * (1.0f - s * f), t = v * (1.0f - s * (1.0f - f));
    switch (sector) {
        case 0:
            return V3(v, t, p);
        case 1:
            return V3(q, v, p);
        case 2:
            return V3(p, v, t);
        case 3:
            return V3(p, q, v);
        case 4:
            return V3(t, p, v);
        default:
            return V3(v, p, q);
    }
}

V3 HslFromRgb(const V3& c) {
    float mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z});
    float l = 0.5f * (mx + mn), d = mx - mn;
    float s = 0.0f;
    if (d > 0.0f) s = l <= 0.5f ? d / (mx + mn) : d / (2.0f - mx - mn);
    return V3(HsvFromRgb(c).x, s, l);
}

V3 RgbFromHsl(const V3& c) {
    float h = c.x, s = c.y, l = c.z;
    float m2 = l <= 0.5f ? l * (1.0f + s) : l + s - l * s;
    float m1 = 2.0f * l - m2;
    auto channel = [&](float hue) {
        hue -= std::floor(hue);
        if (hue < 1.0f / 6.0f) return m1 + (m2 - m1) * hue * 6.0f;
        if (hue < 0.5f) return m2;
        if (hue < 2.0f / 3.0f) return m1 + (m2 - m1) * (2.0f / 3.0f - hue) * 6.0f;
        return m1;
    };
    return V3(channel(h + 1.0f / 3.0f), channel(h), channel(h - 1.0f / 3.0f));
}

V3 XyyFromRgb(const V3& c) {
    V3 xyz = Apply(kXyzFromRgbRows, c);
    float sum = xyz.x + xyz.y + xyz.z;
    if (sum <= 0.0f) return V3(0.0f, 0.0f, xyz.y);
    return V3(xyz.x / sum, xyz.y / sum, xyz.y);
}

V3 RgbFromXyy(const V3& c) {
    if (c.y <= 0.0f) return V3(0.0f);
    float Y = c.z;
    V3 xyz(c.x * Y / c.y, Y, (1.0f - c.x - c.y) * Y / c.y);
    return Apply(kXyzFromRgbRows.inverse(), xyz);
}

enum class Conversion { ToRgb, FromRgb };

// Converts between "rgb" and the named space; false for an unknown space name.
bool ConvertRgb(const std::string& space, Conversion direction, const V3& in, V3* out) {
    const bool toRgb = direction == Conversion::ToRgb;
    if (space == "rgb")
        *out = in;
    else if (space == "hsv")
        *out = toRgb ? RgbFromHsv(in) : HsvFromRgb(in);
    else if (space == "hsl")
        *out = toRgb ? RgbFromHsl(in) : HslFromRgb(in);
    else if (space == "xyz" || space == "XYZ")
        *out = Apply(toRgb ? kXyzFromRgbRows.inverse() : kXyzFromRgbRows, in);
    else if (space == "xyY")
        *out = toRgb ? RgbFromXyy(in) : XyyFromRgb(in);
    else if (space == "YIQ")
        *out = Apply(toRgb ? kYiqFromRgbRows.inverse() : kYiqFromRgbRows, in);
    else
        return false;
    return true;
}

// ctransform([from,] to, c): from defaults to "rgb".
void CtransformKernel(const BuiltinCall& call) {
    const bool hasFrom = call.argCount == 3;
    const std::string from = hasFrom ? call.strings[0].data[0] : "rgb";
    const std::string& to = call.strings[hasFrom ? 1 : 0].data[0];
    const FloatArg& c = call.args[call.argCount - 1];
    const int w = call.result.width;
    V3 probe;
    bool known = ConvertRgb(from, Conversion::ToRgb, V3(0.0f), &probe) &&
                 ConvertRgb(to, Conversion::FromRgb, V3(0.0f), &probe);
    if (call.context && !known) {
        call.context->RuntimeWarning(
            "ctransform:" + from + ":" + to,
            "ctransform: unknown colour space \"" + from + "\" or \"" + to + "\"");
    }
    if (call.context && known && w != 3) {
        call.context->RuntimeWarning("ctransform:ncomps", "ctransform needs 3-component colours");
    }
    ForEachPoint(call, [&](int p) {
        if (!known || w != 3) {
            for (int i = 0; i < w; ++i) call.result.At(i, p) = c.At(i, p);
            return;
        }
        V3 rgb, out;
        ConvertRgb(from, Conversion::ToRgb, Triple(c, p), &rgb);
        ConvertRgb(to, Conversion::FromRgb, rgb, &out);
        SetTriple(call.result, p, out);
    });
}

// luminance(c): CIE Y of a linear Rec. 709 colour (the mean for other component counts).
void LuminanceKernel(const BuiltinCall& call) {
    const int w = call.args[0].width;
    ForEachPoint(call, [&](int p) {
        float y = 0.0f;
        if (w == 3) {
            y = Apply(kXyzFromRgbRows, Triple(call.args[0], p)).y;
        } else {
            for (int i = 0; i < w; ++i) y += call.args[0].At(i, p);
            y /= static_cast<float>(std::max(w, 1));
        }
        call.result.At(0, p) = y;
    });
}

}  // namespace

void AddColorBuiltins(BuiltinList* list) {
    list->Add("comp", "f", "cf", CompKernel);
    list->Add("setcomp", "x", "Cff", SetCompKernel);
    list->Add("ctransform", "c", "sc", CtransformKernel);
    list->Add("ctransform", "c", "ssc", CtransformKernel);
    list->Add("luminance", "f", "c", LuminanceKernel);
}

}  // namespace gonio::sl::builtins
