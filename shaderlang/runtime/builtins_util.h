#pragma once
// Shared helpers of the built-in kernels (internal to shaderlang/runtime/): the per-point loop
// that honours masks and uniform/varying arguments, typed accessors over the component-major
// layout of batch.h, and the list the families register their table rows into.

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <cmath>
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "shaderlang/runtime/batch.h"
#include "shaderlang/runtime/builtin_table.h"

namespace gonio::sl::builtins {

using V3 = Imath::V3f;
using M44 = Imath::M44f;

// A call runs over every point when its result or any argument (outputs included) is varying;
// a fully uniform call computes point 0 once, whatever the mask says.
inline bool IsVaryingCall(const BuiltinCall& call) {
    if (call.result.varying) return true;
    for (int i = 0; i < call.argCount; ++i) {
        if (call.args[i].data && call.args[i].varying) return true;
    }
    return false;
}

// Calls fn(point) for each point the kernel must compute (active points of a varying call).
template <typename Fn>
void ForEachPoint(const BuiltinCall& call, Fn&& fn) {
    if (!IsVaryingCall(call)) {
        fn(0);
        return;
    }
    for (int p = 0; p < call.n; ++p) {
        if (call.IsActive(p)) fn(p);
    }
}

inline float Float(const FloatArg& a, int p) { return a.At(0, p); }

// Component c of a per-component operand; a float operand (width 1) is broadcast, which lets one
// kernel serve mix(color, color, float) and clamp(color, float, float) alike.
inline float Comp(const FloatArg& a, int c, int p) { return a.At(a.width == 1 ? 0 : c, p); }

inline V3 Triple(const FloatArg& a, int p, int offset = 0) {
    return V3(a.At(offset, p), a.At(offset + 1, p), a.At(offset + 2, p));
}
inline void SetTriple(const FloatArg& a, int p, const V3& v) {
    a.At(0, p) = v.x;
    a.At(1, p) = v.y;
    a.At(2, p) = v.z;
}

// RSL matrices are row-major with points as row vectors (p' = p·M), as Imath's M44f is.
inline M44 Matrix(const FloatArg& a, int p) {
    M44 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = a.At(i, p);
    return m;
}
inline void SetMatrix(const FloatArg& a, int p, const M44& m) {
    for (int i = 0; i < 16; ++i) a.At(i, p) = m[i / 4][i % 4];
}

inline float Dot(const V3& a, const V3& b) { return a.dot(b); }
inline V3 Normalized(const V3& v) {
    float len = v.length();
    return len > 0.0f ? v / len : v;
}

// The points a plane-wise kernel handles at once, so that its temporaries stay on the stack.
constexpr int kChunk = 64;

// Normalizes count (at most kChunk) vectors given as planes, bit for bit as Normalized() does
// each (Imath's length(), then three divisions), in loops the compiler vectorises: the squared
// lengths, the divisions. Only the square root stays scalar (it may set errno, so it does not
// vectorise), along with Imath's rescaled length of tiny vectors. The output may be the input.
inline void NormalizeChunk(const float* x, const float* y, const float* z, int count, float* ox,
                           float* oy, float* oz) {
    float divisor[kChunk];
    for (int p = 0; p < count; ++p) divisor[p] = x[p] * x[p] + y[p] * y[p] + z[p] * z[p];
    for (int p = 0; p < count; ++p) {
        const float length2 = divisor[p];
        const float length = length2 < 2.0f * std::numeric_limits<float>::min()
                                 ? V3(x[p], y[p], z[p]).length()
                                 : std::sqrt(length2);
        // A zero (or NaN) length leaves the vector as it is: dividing by 1 does that exactly.
        divisor[p] = length > 0.0f ? length : 1.0f;
    }
    for (int p = 0; p < count; ++p) ox[p] = x[p] / divisor[p];
    for (int p = 0; p < count; ++p) oy[p] = y[p] / divisor[p];
    for (int p = 0; p < count; ++p) oz[p] = z[p] / divisor[p];
}

// Rows of the built-in table. Signature strings are interned so generated overloads (min with
// 2..8 arguments, spline with 4..14 values) keep stable `const char*`s for the table's lifetime.
class BuiltinList {
  public:
    void Add(const std::string& name, const std::string& returnType, const std::string& arguments,
             BuiltinKernel kernel, unsigned flags = kBuiltinNone) {
        rows.push_back({Intern(name), Intern(returnType), Intern(arguments), kernel, flags});
    }

    std::vector<BuiltinInfo> rows;

  private:
    const char* Intern(const std::string& s) {
        arena_.push_back(s);
        return arena_.back().c_str();
    }
    std::deque<std::string> arena_;
};

// One registration function per family (builtins_<family>.cpp).
void AddMathBuiltins(BuiltinList* list);
void AddNoiseBuiltins(BuiltinList* list);
void AddGeometricBuiltins(BuiltinList* list);
void AddColorBuiltins(BuiltinList* list);
void AddMatrixBuiltins(BuiltinList* list);
void AddStringBuiltins(BuiltinList* list);
void AddLightingBuiltins(BuiltinList* list);
void AddTextureBuiltins(BuiltinList* list);
void AddMessageBuiltins(BuiltinList* list);
void AddDerivativeBuiltins(BuiltinList* list);
void AddBrdfBuiltins(BuiltinList* list);
void AddRayBuiltins(BuiltinList* list);
void AddGatherBuiltins(BuiltinList* list);
void AddPointCloudBuiltins(BuiltinList* list);

// The point-like and numeric type codes many rows are generated over.
inline const char* const kPointLikeCodes[] = {"p", "v", "n"};
inline const char* const kTripleCodes[] = {"c", "p", "v", "n"};
inline const char* const kNumericCodes[] = {"f", "c", "p", "v", "n"};

}  // namespace gonio::sl::builtins
