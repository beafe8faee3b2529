#pragma once
// How the interpreter lays out values over a batch of shading points, and the calling
// convention of built-in functions (kernels). Every kernel runs once over the whole batch.
//
// Layout: a register of width w (floats per element: 1 float, 3 point/vector/normal, ncomps
// colour, 16 matrix; times the array length for arrays) holds, for a varying register, w
// planes of `n` floats, component-major: component c of point i is data[c * n + i]. A uniform
// register holds one element: component c is data[c]. Strings live in their own registers,
// uniform only (one std::string per array element).
//
// Masks: `active` has one byte per point (non-zero: the point runs); nullptr means all points
// are active. Kernels must not write varying results at inactive points.

#include <cstdint>
#include <string>

#include "shaderlang/types.h"

namespace gonio::sl {

class ShadingContext;
class GlobalsView;  // shaderlang/runtime/globals_view.h

struct FloatArg {
    float* data = nullptr;
    int width = 0;  // floats per point (element width × array length)
    bool varying = false;
    int n = 1;  // points in the batch (a uniform arg still knows n)

    float& At(int component, int point) const {
        return varying ? data[component * n + point] : data[component];
    }
};

struct StringArg {
    std::string* data = nullptr;  // arrayLength (or 1) strings
};

struct BuiltinCall {
    int n = 0;                        // points in the batch
    const uint8_t* active = nullptr;  // nullptr: all points active
    int argCount = 0;
    TypeSpec argTypes[16];
    FloatArg args[16];      // numeric arguments (unused entries for string arguments)
    StringArg strings[16];  // string arguments (unused entries for numeric arguments)
    TypeSpec resultType;
    FloatArg result;  // unused for void and string results
    StringArg stringResult;
    ShadingContext* context = nullptr;  // renderer state, lights, spaces (shading_context.h)
    int colorComponents = 3;
    // The batch's shading globals by name, for kernels flagged kReadsGlobals (globals_view.h).
    const GlobalsView* globals = nullptr;

    bool IsActive(int point) const { return !active || active[point]; }
    // The points a kernel must compute: all n for a varying result, just point 0 for a uniform
    // one (all arguments are then uniform too).
    int ResultPoints() const { return result.varying ? n : 1; }
};

using BuiltinKernel = void (*)(const BuiltinCall& call);

}  // namespace gonio::sl
