// Matrix built-ins (RISpec §15.4): comp, setcomp, determinant, translate, rotate, scale.
// Matrices are row-major and act on row vectors (p' = p·M), as in RenderMan: translate(m, t)
// returns the matrix that first translates by t and then applies m (RiTranslate's rule).

#include <cmath>

#include "shaderlang/runtime/builtins_util.h"

namespace gonio::sl::builtins {

namespace {

void CompKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        int row = static_cast<int>(Float(call.args[1], p));
        int col = static_cast<int>(Float(call.args[2], p));
        bool inside = row >= 0 && row < 4 && col >= 0 && col < 4;
        call.result.At(0, p) = inside ? call.args[0].At(row * 4 + col, p) : 0.0f;
    });
}

// setcomp(output m, row, column, value); indices out of range leave m unchanged.
void SetCompKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        int row = static_cast<int>(Float(call.args[1], p));
        int col = static_cast<int>(Float(call.args[2], p));
        if (row >= 0 && row < 4 && col >= 0 && col < 4) {
            call.args[0].At(row * 4 + col, p) = Float(call.args[3], p);
        }
    });
}

void DeterminantKernel(const BuiltinCall& call) {
    ForEachPoint(call,
                 [&](int p) { call.result.At(0, p) = Matrix(call.args[0], p).determinant(); });
}

// With row vectors, "first T, then m" is T·m.
void TranslateKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        M44 t;
        t.setTranslation(Triple(call.args[1], p));
        SetMatrix(call.result, p, t * Matrix(call.args[0], p));
    });
}

void ScaleKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        M44 s;
        s.setScale(Triple(call.args[1], p));
        SetMatrix(call.result, p, s * Matrix(call.args[0], p));
    });
}

// rotate(m, angle, axis): angle in radians, right-handed about axis (as RiRotate, in radians).
void RotateKernel(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        M44 r;
        r.setAxisAngle(Normalized(Triple(call.args[2], p)), Float(call.args[1], p));
        SetMatrix(call.result, p, r * Matrix(call.args[0], p));
    });
}

}  // namespace

void AddMatrixBuiltins(BuiltinList* list) {
    list->Add("comp", "f", "mff", CompKernel);
    list->Add("setcomp", "x", "Mfff", SetCompKernel);
    list->Add("determinant", "f", "m", DeterminantKernel);
    list->Add("translate", "m", "mv", TranslateKernel);
    list->Add("translate", "m", "mp", TranslateKernel);
    list->Add("scale", "m", "mp", ScaleKernel);
    list->Add("scale", "m", "mv", ScaleKernel);
    list->Add("rotate", "m", "mfv", RotateKernel);
}

}  // namespace gonio::sl::builtins
