#pragma once
// The table of built-in functions (RISpec §15): one row per overload. The type checker resolves
// calls against it and the code generator emits a call to the row's kernel. Adding a built-in is
// one kernel and one row.
//
// Signature codes, one character per type: f float, s string, c color, p point, v vector,
// n normal, m matrix, x void (return only). An upper-case code is an output argument the kernel
// writes. A trailing "*" accepts any further arguments of any type (printf, format, texture
// options); "[]" after a code is an array argument of any length ("f[]").

#include <string>
#include <vector>

#include "shaderlang/runtime/batch.h"

namespace gonio::sl {

enum BuiltinFlags : unsigned {
    kBuiltinNone = 0,
    kVaryingResult = 1u << 0,     // varying even when every argument is uniform (random, area)
    kReadsGlobals = 1u << 1,      // reads shading globals (P, N, I, Cl, ...) through the context
    kUsesLights = 1u << 2,        // ambient, diffuse, specular, phong: runs the light shaders
    kHasSideEffects = 1u << 3,    // printf: never removed as dead code, never folded
    kNeedsDerivatives = 1u << 4,  // Du, Dv, Deriv, area, calculatenormal
    kReadsFiles = 1u << 5,        // brdf: reads files through the renderer, so runs only then
    kTracesRays = 1u << 6,        // trace: asks the renderer to trace rays
    // occlusion, indirectdiffuse, gather, transmission, visibility: ask the renderer to trace
    // sampled rays (ShadingContext::TraceSampledRays). Unlike trace()'s, their results are
    // shared by a hit's neighbour points, so they need no ray differentials.
    kSamplesRays = 1u << 7,
    // occlusion: an option ("environmentcolor", c) writes its variable c (IsOutputOption).
    kOutputOptions = 1u << 8,
    // transform("space", ...) and the like: the renderer's coordinate systems, known only when
    // the shader runs (so a constant operand is not folded with identity spaces).
    kUsesSpaces = 1u << 9,
    // texture3d: every ("name", variable) pair after the parameters writes its variable.
    kOutputPairs = 1u << 10,
    // random, __uniform_random: the next value of a random stream, so never folded (a uniform
    // random() has no varying result, yet differs from run to run).
    kDrawsRandom = 1u << 11,
};

// Whether the value after the option `name` is an output variable in a call with `flags`:
// every option's with kOutputPairs; with kOutputOptions, occlusion's ("environmentcolor", c),
// of colour type.
inline bool IsOutputOption(unsigned flags, const std::string& name) {
    return (flags & kOutputPairs) || ((flags & kOutputOptions) && name == "environmentcolor");
}

struct BuiltinInfo {
    const char* name;
    const char* returnType;  // one code
    const char* arguments;   // codes, see above
    BuiltinKernel kernel;
    unsigned flags = kBuiltinNone;
};

// Every built-in overload, in a fixed order (indices are stable within a run).
const std::vector<BuiltinInfo>& BuiltinTable();

// The TypeSpec of a signature code ('f', 'C', ...): arrayLength 0; Void for 'x'.
TypeSpec TypeOfCode(char code);

// A row's argument codes, parsed once for the compiler's overload resolution and code.
struct BuiltinParameter {
    TypeSpec type;        // the element type of an array parameter
    bool output = false;  // upper-case code: the kernel writes the argument
    bool array = false;   // "[]": an array of any length
};

struct BuiltinSignature {
    TypeSpec result;
    std::vector<BuiltinParameter> parameters;
    bool varargs = false;  // a trailing "*": any further arguments
};

// The signature of BuiltinTable()[row].
const BuiltinSignature& BuiltinSignatureOf(int row);
// The rows of the built-in `name` in table order; empty when there is none.
const std::vector<int>& BuiltinRowsNamed(const std::string& name);

}  // namespace gonio::sl
