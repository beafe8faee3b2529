// Arithmetic, comparison, logic, selection and array opcodes (see opcodes.h). Each runs over
// the batch with the loop innermost; an operand of width 1 (a float) is broadcast over the
// components of the other, and a uniform operand over the points.

#include <Imath/ImathMatrix.h>

#include <cmath>

#include "shaderlang/runtime/interpreter.h"
#include "shaderlang/runtime/ops.h"

namespace gonio::sl {

namespace {

// out = f(a, b) per component and point, for the active points of a varying destination.
template <typename F>
void Binary(ExecState& x, const Instr& in, F f) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), b = x.Reg(in.args[2]);
    const uint8_t* mask = d.varying ? x.Mask(in) : nullptr;
    const int count = d.varying ? x.n : 1;
    const int sa = a.Stride(), sb = b.Stride();
    for (int c = 0; c < d.width; ++c) {
        float* out = d.Plane(c);
        const float* pa = a.Plane(c);
        const float* pb = b.Plane(c);
        if (mask) {
            for (int i = 0; i < count; ++i) {
                if (mask[i]) out[i] = f(pa[i * sa], pb[i * sb]);
            }
        } else if (sa && sb) {
            for (int i = 0; i < count; ++i) out[i] = f(pa[i], pb[i]);
        } else if (sa) {
            const float vb = pb[0];
            for (int i = 0; i < count; ++i) out[i] = f(pa[i], vb);
        } else if (sb) {
            const float va = pa[0];
            for (int i = 0; i < count; ++i) out[i] = f(va, pb[i]);
        } else {
            const float v = f(pa[0], pb[0]);
            for (int i = 0; i < count; ++i) out[i] = v;
        }
    }
}

// out = f(a) per component and point.
template <typename F>
void Unary(ExecState& x, const Instr& in, F f) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]);
    const uint8_t* mask = d.varying ? x.Mask(in) : nullptr;
    const int count = d.varying ? x.n : 1;
    const int sa = a.Stride();
    for (int c = 0; c < d.width; ++c) {
        float* out = d.Plane(c);
        const float* pa = a.Plane(c);
        if (mask) {
            for (int i = 0; i < count; ++i) {
                if (mask[i]) out[i] = f(pa[i * sa]);
            }
        } else if (sa) {
            for (int i = 0; i < count; ++i) out[i] = f(pa[i]);
        } else {
            const float v = f(pa[0]);
            for (int i = 0; i < count; ++i) out[i] = v;
        }
    }
}

// A per-point operation over whole values (matrices, dot and cross products, comparisons of
// all components): fn(point) for each point the destination needs.
template <typename F>
void PerPoint(ExecState& x, const Instr& in, F fn) {
    const RegRef d = x.Reg(in.args[0]);
    if (!d.varying) return fn(0);
    const uint8_t* mask = x.Mask(in);
    for (int i = 0; i < x.n; ++i) {
        if (!mask || mask[i]) fn(i);
    }
}

float At(const RegRef& r, int c, int i) { return r.Plane(c)[r.varying ? i : 0]; }
float& Out(const RegRef& r, int c, int i) { return r.Plane(c)[r.varying ? i : 0]; }

Imath::M44f LoadMatrix(const RegRef& r, int i) {
    Imath::M44f m;
    if (r.width == 1) return m * At(r, 0, i);  // a float is that multiple of the identity
    for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = At(r, k, i);
    return m;
}

void StoreMatrix(const RegRef& r, int i, const Imath::M44f& m) {
    for (int k = 0; k < 16; ++k) Out(r, k, i) = m[k / 4][k % 4];
}

// Whether every component of a equals b's (a float compares with each component).
bool AllEqual(const RegRef& a, const RegRef& b, int i) {
    int width = std::max(a.width, b.width);
    for (int c = 0; c < width; ++c) {
        if (At(a, c, i) != At(b, c, i)) return false;
    }
    return true;
}

}  // namespace

void OpAssign(ExecState& x, const Instr& in) {
    const Register& info = x.program->regs[in.args[0]];
    if (info.isString) {
        for (int k = 0; k < info.width; ++k) x.Str(in.args[0], k) = x.Str(in.args[1], k);
        return;
    }
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]);
    if (info.type.base == BaseType::Matrix && a.width == 1) {
        // float -> matrix: the float times the identity (RISpec §11.2).
        PerPoint(x, in, [&](int i) {
            float v = At(a, 0, i);
            for (int k = 0; k < 16; ++k) Out(d, k, i) = k % 5 == 0 ? v : 0.0f;
        });
        return;
    }
    Unary(x, in, [](float v) { return v; });
}

void OpNeg(ExecState& x, const Instr& in) {
    Unary(x, in, [](float v) { return -v; });
}
void OpAdd(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return a + b; });
}
void OpSub(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return a - b; });
}
void OpMul(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return a * b; });
}

void OpDiv(ExecState& x, const Instr& in) {
    bool byZero = false;
    Binary(x, in, [&byZero](float a, float b) {
        if (b == 0.0f) {
            byZero = true;
            return 0.0f;  // a defined result instead of inf/NaN spreading through the image
        }
        return a / b;
    });
    if (byZero) x.Warn(in, "division by zero (the result is 0)");
}

void OpMatMul(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), b = x.Reg(in.args[2]);
    PerPoint(x, in, [&](int i) { StoreMatrix(d, i, LoadMatrix(a, i) * LoadMatrix(b, i)); });
}

void OpMatDiv(ExecState& x, const Instr& in) {
    // m1 / m2 = m1 * inverse(m2) (RISpec §11.2, so 1/m is the inverse).
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), b = x.Reg(in.args[2]);
    bool singular = false;
    PerPoint(x, in, [&](int i) {
        Imath::M44f m = LoadMatrix(b, i);
        if (m.determinant() == 0.0f) {
            singular = true;
            StoreMatrix(d, i, Imath::M44f(0.0f));
            return;
        }
        StoreMatrix(d, i, LoadMatrix(a, i) * m.inverse());
    });
    if (singular) x.Warn(in, "division by a singular matrix (the result is 0)");
}

void OpDot(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), b = x.Reg(in.args[2]);
    const uint8_t* mask = d.varying ? x.Mask(in) : nullptr;
    const int count = d.varying ? x.n : 1;
    float* out = d.data;
    for (int i = 0; i < count; ++i) {
        if (mask && !mask[i]) continue;
        float sum = 0;
        for (int c = 0; c < a.width; ++c) sum += At(a, c, i) * At(b, c, i);
        out[i] = sum;
    }
}

void OpCross(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), b = x.Reg(in.args[2]);
    PerPoint(x, in, [&](int i) {
        float ax = At(a, 0, i), ay = At(a, 1, i), az = At(a, 2, i);
        float bx = At(b, 0, i), by = At(b, 1, i), bz = At(b, 2, i);
        Out(d, 0, i) = ay * bz - az * by;
        Out(d, 1, i) = az * bx - ax * bz;
        Out(d, 2, i) = ax * by - ay * bx;
    });
}

void OpLt(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return float(a < b); });
}
void OpLe(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return float(a <= b); });
}
void OpGt(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return float(a > b); });
}
void OpGe(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return float(a >= b); });
}

void OpEq(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), b = x.Reg(in.args[2]);
    PerPoint(x, in, [&](int i) { Out(d, 0, i) = float(AllEqual(a, b, i)); });
}

void OpNe(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), b = x.Reg(in.args[2]);
    PerPoint(x, in, [&](int i) { Out(d, 0, i) = float(!AllEqual(a, b, i)); });
}

// Strings are uniform, so a comparison has one answer; the result register may still be varying
// (a string written by a built-in's output argument inherits the call's detail): every active
// point gets the answer.
void SetStringComparison(ExecState& x, const Instr& in, bool value) {
    const RegRef d = x.Reg(in.args[0]);
    PerPoint(x, in, [&](int i) { Out(d, 0, i) = float(value); });
}

void OpStrEq(ExecState& x, const Instr& in) {
    SetStringComparison(x, in, x.Str(in.args[1]) == x.Str(in.args[2]));
}

void OpStrNe(ExecState& x, const Instr& in) {
    SetStringComparison(x, in, x.Str(in.args[1]) != x.Str(in.args[2]));
}

void OpAnd(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return float(a != 0.0f && b != 0.0f); });
}
void OpOr(ExecState& x, const Instr& in) {
    Binary(x, in, [](float a, float b) { return float(a != 0.0f || b != 0.0f); });
}
void OpNot(ExecState& x, const Instr& in) {
    Unary(x, in, [](float a) { return float(a == 0.0f); });
}

void OpSelect(ExecState& x, const Instr& in) {
    const RegRef d = x.Reg(in.args[0]), c = x.Reg(in.args[1]), a = x.Reg(in.args[2]),
                 b = x.Reg(in.args[3]);
    if (x.program->regs[in.args[0]].isString) {
        x.Str(in.args[0]) = At(c, 0, 0) != 0.0f ? x.Str(in.args[2]) : x.Str(in.args[3]);
        return;
    }
    PerPoint(x, in, [&](int i) {
        const RegRef& from = At(c, 0, i) != 0.0f ? a : b;
        for (int k = 0; k < d.width; ++k) Out(d, k, i) = At(from, k, i);
    });
}

// Clamps an array index into range; false (and a warning) when it was outside.
static int ClampIndex(float index, int length, bool* outside) {
    if (!(index >= 0.0f)) {  // also NaN
        *outside = true;
        return 0;
    }
    if (index >= float(length)) {
        *outside = true;
        return length - 1;
    }
    return int(index);
}

void OpIndexRead(ExecState& x, const Instr& in) {
    const Register& array = x.program->regs[in.args[1]];
    const int length = array.type.arrayLength;
    bool outside = false;
    if (array.isString) {
        int k = ClampIndex(*x.Reg(in.args[2]).data, length, &outside);
        x.Str(in.args[0]) = x.Str(in.args[1], k);
    } else {
        const RegRef d = x.Reg(in.args[0]), a = x.Reg(in.args[1]), idx = x.Reg(in.args[2]);
        PerPoint(x, in, [&](int i) {
            int k = ClampIndex(At(idx, 0, i), length, &outside);
            for (int c = 0; c < d.width; ++c) Out(d, c, i) = At(a, k * d.width + c, i);
        });
    }
    if (outside) x.Warn(in, "array index out of range (clamped)");
}

void OpIndexWrite(ExecState& x, const Instr& in) {
    // args: array, index, value
    const Register& array = x.program->regs[in.args[0]];
    const int length = array.type.arrayLength;
    bool outside = false;
    if (array.isString) {
        int k = ClampIndex(*x.Reg(in.args[1]).data, length, &outside);
        x.Str(in.args[0], k) = x.Str(in.args[2]);
    } else {
        const RegRef a = x.Reg(in.args[0]), idx = x.Reg(in.args[1]), v = x.Reg(in.args[2]);
        const int width = a.width / length;
        auto store = [&](int i) {
            int k = ClampIndex(At(idx, 0, i), length, &outside);
            for (int c = 0; c < width; ++c)
                Out(a, k * width + c, i) = At(v, v.width == 1 ? 0 : c, i);
        };
        if (!a.varying) {
            store(0);
        } else {
            const uint8_t* mask = x.Mask(in);
            for (int i = 0; i < x.n; ++i) {
                if (!mask || mask[i]) store(i);
            }
        }
    }
    if (outside) x.Warn(in, "array index out of range (clamped)");
}

}  // namespace gonio::sl
