// Control opcodes (masks, loops, light loops), space and colour casts, tuples and built-in
// calls (see opcodes.h for what each does).

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "shaderlang/runtime/builtin_table.h"
#include "shaderlang/runtime/global_vars.h"
#include "shaderlang/runtime/interpreter.h"
#include "shaderlang/runtime/ops.h"

namespace gonio::sl {

namespace {

int CountActive(const MaskEntry& e, int n) {
    if (e.all) return n;
    int count = 0;
    for (int i = 0; i < n; ++i) count += e.bits[i];
    return count;
}

void SetEmpty(MaskEntry& e, int n) {
    e.all = false;
    std::memset(e.bits.data(), 0, size_t(n));
}

// entry &= keep(i) for each point; returns the active count.
template <typename Keep>
int Restrict(ExecState& x, int entry, Keep keep) {
    MaskEntry& e = x.masks[entry];
    int count = 0;
    for (int i = 0; i < x.n; ++i) {
        uint8_t b = (e.all || e.bits[i]) && keep(i);
        e.bits[i] = b;
        count += b;
    }
    e.all = count == x.n;
    return count;
}

Imath::V3f Triple(const RegRef& r, int i) {
    return Imath::V3f(r.Plane(0)[r.varying ? i : 0], r.Plane(1)[r.varying ? i : 0],
                      r.Plane(2)[r.varying ? i : 0]);
}

float Value(const RegRef& r, int i) { return r.Plane(0)[r.varying ? i : 0]; }

// Whether direction `d` lies within `angle` of `axis` (the cone of illuminance/illuminate).
bool InCone(const Imath::V3f& d, const Imath::V3f& axis, float angle) {
    if (angle >= float(M_PI)) return true;
    float lengths = d.length() * axis.length();
    if (lengths == 0.0f) return true;
    return d.dot(axis) >= std::cos(angle) * lengths;
}

// A light's __category is a comma-separated list; "-name" selects the lights without it.
bool CategoryMatches(const std::string& wanted, const std::string& categories) {
    if (wanted.empty()) return true;
    bool negate = wanted[0] == '-';
    std::string name = negate ? wanted.substr(1) : wanted;
    bool has = false;
    std::stringstream list(categories);
    std::string item;
    while (std::getline(list, item, ',')) {
        size_t b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
        if (b != std::string::npos && item.substr(b, e - b + 1) == name) has = true;
    }
    return has != negate;
}

void CopyPlanes(ExecState& x, int reg, const std::vector<float>& from, int width) {
    if (reg < 0 || from.empty()) return;
    RegRef r = x.Reg(reg);
    int w = std::min(width, r.width);
    if (r.varying) {
        std::memcpy(r.data, from.data(), sizeof(float) * size_t(w) * size_t(x.n));
    } else {
        for (int c = 0; c < w; ++c) r.data[c] = from[size_t(c) * x.n];
    }
}

// Colour spaces of RISpec Table 11.1, converted to linear RGB (Rec. 709 primaries, D65).
Imath::V3f HsvToRgb(float h, float s, float v) {
    if (!std::isfinite(h)) h = 0.0f;
    h = (h - std::floor(h)) * 6.0f;
    int sector = int(h) % 6;
    float f = h - std::floor(h);
    float p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (sector) {
        case 0:
            return {v, t, p};
        case 1:
            return {q, v, p};
        case 2:
            return {p, v, t};
        case 3:
            return {p, q, v};
        case 4:
            return {t, p, v};
        default:
            return {v, p, q};
    }
}

float HueToRgb(float m1, float m2, float h) {
    h -= std::floor(h);
    if (h * 6 < 1) return m1 + (m2 - m1) * h * 6;
    if (h * 2 < 1) return m2;
    if (h * 3 < 2) return m1 + (m2 - m1) * (2.0f / 3.0f - h) * 6;
    return m1;
}

Imath::V3f HslToRgb(float h, float s, float l) {
    float m2 = l <= 0.5f ? l * (1 + s) : l + s - l * s;
    float m1 = 2 * l - m2;
    return {HueToRgb(m1, m2, h + 1.0f / 3.0f), HueToRgb(m1, m2, h),
            HueToRgb(m1, m2, h - 1.0f / 3.0f)};
}

Imath::V3f XyzToRgb(const Imath::V3f& c) {
    return {3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z,
            -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z,
            0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z};
}

bool ColorToRgb(const std::string& space, const Imath::V3f& c, Imath::V3f* rgb) {
    if (space == "rgb" || space == "RGB") {
        *rgb = c;
    } else if (space == "hsv") {
        *rgb = HsvToRgb(c.x, c.y, c.z);
    } else if (space == "hsl") {
        *rgb = HslToRgb(c.x, c.y, c.z);
    } else if (space == "xyz" || space == "XYZ") {
        *rgb = XyzToRgb(c);
    } else if (space == "xyY") {
        float Y = c.z;
        Imath::V3f xyz = c.y == 0.0f ? Imath::V3f(0.0f)
                                     : Imath::V3f(c.x * Y / c.y, Y, (1 - c.x - c.y) * Y / c.y);
        *rgb = XyzToRgb(xyz);
    } else if (space == "YIQ") {
        *rgb = {c.x + 0.956f * c.y + 0.621f * c.z, c.x - 0.272f * c.y - 0.647f * c.z,
                c.x - 1.106f * c.y + 1.703f * c.z};
    } else {
        *rgb = c;
        return false;
    }
    return true;
}

// Whether an illuminance position register holds the P the run was given at every active
// point: then the context's cached lights serve (RISpec §13.3.1 gathers light at the given
// position). The P register itself need not: a surface shader may have written it.
bool IsSurfaceP(const ExecState& x, int positionReg, int entry) {
    if (positionReg < 0) return true;
    const int Preg = x.program->globals[kGlobalP];
    if (!x.inputP) return positionReg == Preg;
    const RegRef at = x.Reg(positionReg);
    const MaskEntry& e = x.masks[entry];
    for (int i = 0; i < x.n; ++i) {
        if (!e.all && !e.bits[i]) continue;
        for (int c = 0; c < 3; ++c)
            if (at.Plane(c)[at.varying ? i : 0] != x.inputP[size_t(c) * x.n + i]) return false;
    }
    return true;
}

// The position as 3 planes of n floats (a uniform point is replicated).
const float* PositionPlanes(ExecState& x, int positionReg) {
    const RegRef at = x.Reg(positionReg);
    if (at.varying) return at.data;
    x.illuminancePosition.resize(3 * size_t(x.n));
    for (int c = 0; c < 3; ++c)
        std::fill_n(x.illuminancePosition.begin() + size_t(c) * x.n, x.n, at.data[c]);
    return x.illuminancePosition.data();
}

// L for the points a light from all directions (solar() without an axis) reached: along the
// loop's axis, else along the surface's N, so that it counts fully wherever it is gathered.
void AimAllDirectionsLight(ExecState& x, const LightResult& light, const RegRef* axis) {
    const int Lreg = x.program->globals[kGlobalL];
    const int Nreg = x.program->globals[kGlobalN];
    if (light.fromAllDirections.empty() || Lreg < 0 || (!axis && Nreg < 0)) return;
    const RegRef L = x.Reg(Lreg), along = axis ? *axis : x.Reg(Nreg);
    for (int i = 0; i < x.n; ++i) {
        if (!light.fromAllDirections[i]) continue;
        const Imath::V3f d = Triple(along, i);
        for (int c = 0; c < 3; ++c) L.Plane(c)[i] = d[c];
    }
}

}  // namespace

int SetMask(ExecState& x, int to, int from, const RegRef* cond, bool negate) {
    MaskEntry& t = x.masks[to];
    const MaskEntry& f = x.masks[from];
    if (!cond || !cond->varying) {
        bool keep = !cond || ((cond->data[0] != 0.0f) != negate);
        if (!keep) {
            SetEmpty(t, x.n);
            return 0;
        }
        if (to != from) {
            t.all = f.all;
            if (!f.all) std::memcpy(t.bits.data(), f.bits.data(), size_t(x.n));
        }
        return CountActive(t, x.n);
    }
    const float* c = cond->data;
    int count = 0;
    for (int i = 0; i < x.n; ++i) {
        uint8_t b = (f.all || f.bits[i]) && ((c[i] != 0.0f) != negate);
        t.bits[i] = b;
        count += b;
    }
    t.all = count == x.n;
    return count;
}

void OpJump(ExecState& x, const Instr& in) {
    if (in.jump < x.pc) x.CheckBudget(in);  // a loop's back edge
    x.pc = in.jump;
}

void OpIf(ExecState& x, const Instr& in) {
    RegRef c = x.Reg(in.args[0]);
    if (SetMask(x, in.extra, in.extra - 1, &c, false) == 0) x.pc = in.jump;
}

void OpElse(ExecState& x, const Instr& in) {
    RegRef c = x.Reg(in.args[0]);
    if (SetMask(x, in.extra, in.extra - 1, &c, true) == 0) x.pc = in.jump;
}

void OpLoopInit(ExecState& x, const Instr& in) {
    SetMask(x, in.extra, in.extra - 1, nullptr, false);
}

void OpLoopTest(ExecState& x, const Instr& in) {
    RegRef c = x.Reg(in.args[0]);
    if (SetMask(x, in.extra, in.extra, &c, false) == 0) {
        x.pc = in.jump;
        return;
    }
    SetMask(x, in.extra + 1, in.extra, nullptr, false);
}

void OpLoopNext(ExecState& x, const Instr& in) {
    SetMask(x, in.extra + 1, in.extra, nullptr, false);
}

void OpEnter(ExecState& x, const Instr& in) { SetMask(x, in.extra, in.extra - 1, nullptr, false); }

void OpExit(ExecState& x, const Instr& in) {
    const MaskEntry& current = x.masks[in.depth];
    if (current.all) {
        for (int e = in.extra; e <= in.depth; ++e) SetEmpty(x.masks[e], x.n);
        return;
    }
    std::vector<uint8_t> leaving = current.bits;
    for (int e = in.extra; e <= in.depth; ++e) {
        Restrict(x, e, [&](int i) { return !leaving[i]; });
    }
}

void OpIllumBegin(ExecState& x, const Instr& in) {
    SetMask(x, in.extra, in.extra - 1, nullptr, false);
    x.lightIndex = -1;
    x.lights = nullptr;
    if (!x.context) return;
    const int position = in.argCount > 3 ? in.args[3] : -1;
    if (IsSurfaceP(x, position, in.extra)) {
        x.lights = &x.context->Lights();
        return;
    }
    const MaskEntry& e = x.masks[in.extra];
    x.lights = &x.context->LightsAt(PositionPlanes(x, position), e.all ? nullptr : e.bits.data());
}

void OpIllumNext(ExecState& x, const Instr& in) {
    const int body = in.extra + 1;
    const std::string* category = in.args[0] >= 0 ? &x.Str(in.args[0]) : nullptr;
    const int count = x.lights ? int(x.lights->size()) : 0;
    const Program& p = *x.program;
    while (++x.lightIndex < count) {
        const LightResult& light = (*x.lights)[x.lightIndex];
        if (light.ambient) continue;
        if (category && !CategoryMatches(*category, light.category)) continue;
        SetMask(x, body, in.extra, nullptr, false);
        const bool cone = in.args[1] >= 0;
        RegRef axis, angle;
        if (cone) {
            axis = x.Reg(in.args[1]);
            angle = x.Reg(in.args[2]);
        }
        const int n = x.n;
        const uint8_t* all =
            light.fromAllDirections.empty() ? nullptr : light.fromAllDirections.data();
        int active = Restrict(x, body, [&](int i) {
            if (!light.lit.empty() && !light.lit[i]) return false;
            if (!cone || (all && all[i])) return true;
            Imath::V3f L(light.L[i], light.L[n + i], light.L[2 * n + i]);
            return InCone(L, Triple(axis, i), Value(angle, i));
        });
        if (active == 0) continue;
        CopyPlanes(x, p.globals[kGlobalL], light.L, 3);
        CopyPlanes(x, p.globals[kGlobalCl], light.Cl, x.colorComponents);
        CopyPlanes(x, p.globals[kGlobalOl], light.Ol, x.colorComponents);
        AimAllDirectionsLight(x, light, cone ? &axis : nullptr);
        return;
    }
    x.pc = in.jump;
}

void OpIlluminate(ExecState& x, const Instr& in) {
    const Program& p = *x.program;
    x.illuminated = true;
    SetMask(x, in.extra, in.extra - 1, nullptr, false);
    const int Lreg = p.globals[kGlobalL], PsReg = p.globals[kGlobalPs];
    if (Lreg < 0 || PsReg < 0) return;
    RegRef L = x.Reg(Lreg), Ps = x.Reg(PsReg), from = x.Reg(in.args[0]);
    const bool cone = in.args[1] >= 0;
    RegRef axis = cone ? x.Reg(in.args[1]) : RegRef{}, angle = cone ? x.Reg(in.args[2]) : RegRef{};
    int active = Restrict(x, in.extra, [&](int i) {
        Imath::V3f d = Triple(Ps, i) - Triple(from, i);
        for (int c = 0; c < 3; ++c) L.Plane(c)[i] = d[c];
        return !cone || InCone(d, Triple(axis, i), Value(angle, i));
    });
    const MaskEntry& lit = x.masks[in.extra];
    for (int i = 0; i < x.n; ++i) x.lit[i] |= lit.all || lit.bits[i];
    if (active == 0) x.pc = in.jump;
}

void OpSolar(ExecState& x, const Instr& in) {
    const Program& p = *x.program;
    x.illuminated = true;
    x.solar = true;
    SetMask(x, in.extra, in.extra - 1, nullptr, false);
    const MaskEntry& lit = x.masks[in.extra];
    const int Lreg = p.globals[kGlobalL];
    RegRef L = Lreg >= 0 ? x.Reg(Lreg) : RegRef{};
    const RegRef axisReg = in.args[0] >= 0 ? x.Reg(in.args[0]) : RegRef{};
    for (int i = 0; i < x.n; ++i) {
        if (!(lit.all || lit.bits[i])) continue;
        x.lit[i] = 1;
        // L = axis: the light arrives along it everywhere. solar() without an axis is light
        // from all directions (RISpec §13.3.2): it has no L of its own; the surface side aims
        // it (OpIllumNext, the lighting built-ins).
        if (!axisReg.data) x.allDirections[i] = 1, x.anyAllDirections = true;
        if (!L.data) continue;
        Imath::V3f axis = axisReg.data ? Triple(axisReg, i) : Imath::V3f(0.0f);
        for (int c = 0; c < 3; ++c) L.Plane(c)[i] = axis[c];
    }
}

namespace {

// Component c of d = the float v, at the active points (once for a uniform d).
void SetComponent(ExecState& x, const Instr& in, const RegRef& d, int c, const RegRef& v) {
    float* out = d.Plane(c);
    const float* pv = v.Plane(0);
    if (!d.varying) {
        out[0] = pv[0];
        return;
    }
    const uint8_t* mask = x.Mask(in);
    const int sv = v.Stride();
    for (int i = 0; i < x.n; ++i) {
        if (!mask || mask[i]) out[i] = pv[i * sv];
    }
}

}  // namespace

void OpSetComp(ExecState& x, const Instr& in) {
    SetComponent(x, in, x.Reg(in.args[0]), in.extra, x.Reg(in.args[1]));
}

void OpTriple(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]);
    for (int c = 0; c < 3; ++c) SetComponent(x, in, d, c, x.Reg(in.args[1 + c]));
}

void OpSpaceCast(ExecState& x, const Instr& in) {
    // extra: 0 point, 1 vector, 2 normal, 3 matrix. The value is in `space`; the result in
    // current space.
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]);
    const std::string& space = x.Str(in.args[2]);
    const uint8_t* mask = d.varying ? x.Mask(in) : nullptr;
    const int count = d.varying ? x.n : 1;
    bool unknown = false;
    for (int i = 0; i < count; ++i) {
        if (mask && !mask[i]) continue;
        Imath::M44f m;
        if (space != "current" && (!x.context || !x.context->CurrentFromSpace(space, i, &m))) {
            unknown = true;
        }
        auto at = [&](int c) { return a.Plane(c)[a.varying ? i : 0]; };
        auto out = [&](int c) -> float& { return d.Plane(c)[d.varying ? i : 0]; };
        if (in.extra == 3) {
            Imath::M44f v;
            for (int k = 0; k < 16; ++k) v[k / 4][k % 4] = at(k);
            Imath::M44f r = v * m;
            for (int k = 0; k < 16; ++k) out(k) = r[k / 4][k % 4];
            continue;
        }
        Imath::V3f v(at(0), at(1), at(2)), r;
        if (in.extra == 0) {
            m.multVecMatrix(v, r);
        } else if (in.extra == 1) {
            m.multDirMatrix(v, r);
        } else {
            m.inverse().transposed().multDirMatrix(v, r);
        }
        for (int c = 0; c < 3; ++c) out(c) = r[c];
    }
    if (unknown) x.Warn(in, "unknown coordinate system '" + space + "' (taken as current)");
}

void OpColorCast(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]);
    const std::string& space = x.Str(in.args[2]);
    const uint8_t* mask = d.varying ? x.Mask(in) : nullptr;
    const int count = d.varying ? x.n : 1;
    bool unknown = false;
    for (int i = 0; i < count; ++i) {
        if (mask && !mask[i]) continue;
        auto at = [&](int c) { return a.Plane(c)[a.varying ? i : 0]; };
        if (d.width != 3) {
            for (int c = 0; c < d.width; ++c) d.Plane(c)[d.varying ? i : 0] = at(c);
            continue;
        }
        Imath::V3f rgb;
        if (!ColorToRgb(space, Imath::V3f(at(0), at(1), at(2)), &rgb)) unknown = true;
        for (int c = 0; c < 3; ++c) d.Plane(c)[d.varying ? i : 0] = rgb[c];
    }
    if (unknown) x.Warn(in, "unknown color space '" + space + "' (taken as rgb)");
}

namespace {

// Results almost never hold a NaN: a scan of the bit patterns, which the compiler vectorises,
// first, the per-point mask only when it found one. A float is a NaN when its magnitude bits,
// as a signed integer, exceed those of infinity, 0x7f800000. A register's floats are contiguous
// (all its planes, or its one element).
bool MayHoldNaN(const FloatArg& r) {
    const size_t count = size_t(r.width) * (r.varying ? size_t(r.n) : 1);
    int found = 0;
    for (size_t i = 0; i < count; ++i) {
        int32_t bits;
        std::memcpy(&bits, &r.data[i], sizeof bits);
        found |= (bits & 0x7fffffff) > 0x7f800000;
    }
    return found != 0;
}

}  // namespace

void OpCall(ExecState& x, const Instr& in) {
    const Program& p = *x.program;
    const int* list = &p.callArgs[in.extra];
    const BuiltinInfo& info = BuiltinTable()[list[0]];
    const int argCount = list[1];
    const int result = list[2];
    BuiltinCall call;
    call.n = x.n;
    call.active = x.Mask(in);
    call.argCount = argCount;
    call.context = x.context;
    if (x.context) x.context->SetStatement(&p.locations[in.loc]);
    call.colorComponents = x.colorComponents;
    call.globals = &x;
    for (int k = 0; k < argCount; ++k) {
        int r = list[3 + k];
        const Register& reg = p.regs[r];
        call.argTypes[k] = reg.type;
        if (reg.isString) {
            call.strings[k].data = x.strings[r].data();
        } else {
            call.args[k] = FloatArg{x.Reg(r).data, reg.width, reg.varying, x.n};
        }
    }
    if (result >= 0) {
        const Register& reg = p.regs[result];
        call.resultType = reg.type;
        if (reg.isString) {
            call.stringResult.data = x.strings[result].data();
        } else {
            call.result = FloatArg{x.Reg(result).data, reg.width, reg.varying, x.n};
        }
    }
    info.kernel(call);
    // NaNs (sqrt(-1), acos(2), ...) are reported once per line, not per point.
    if (result >= 0 && !p.regs[result].isString && MayHoldNaN(call.result)) {
        const FloatArg& r = call.result;
        const int points = r.varying ? x.n : 1;
        for (int c = 0; c < r.width; ++c) {
            for (int i = 0; i < points; ++i) {
                if (std::isnan(r.At(c, i)) && (!r.varying || x.Active(call.active, i))) {
                    x.Warn(in, std::string("NaN from ") + info.name + "()");
                    return;
                }
            }
        }
    }
}

}  // namespace gonio::sl
