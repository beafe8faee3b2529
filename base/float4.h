#pragma once
// Four floats in one SIMD register, through the vector extension GCC and Clang share (SSE on
// x86-64, NEON on ARM): for loops over a pixel's samples that the compilers do not vectorise
// on their own (a sample's weights for the pixels it reaches). Comparisons give Int4 masks of all
// ones or zeros.

#include <cstdint>
#include <cstring>

namespace gonio {

typedef float Float4 __attribute__((vector_size(16)));
typedef int32_t Int4 __attribute__((vector_size(16)));
constexpr int kFloat4Lanes = 4;

inline Float4 Load4(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline Float4 Abs4(Float4 v) { return Float4(Int4(v) & 0x7fffffff); }
// Where mask holds, a's lanes, elsewhere b's.
inline Float4 Select4(Int4 mask, Float4 a, Float4 b) {
    return Float4((mask & Int4(a)) | (~mask & Int4(b)));
}

}  // namespace gonio
