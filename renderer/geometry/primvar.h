#pragma once
// Primitive variables after the scene builder has typed them (declarations.h) and checked their
// value counts against the primitive: what the geometry code interpolates to a hit point.

#include <string>
#include <vector>

#include "renderer/rib/declarations.h"

namespace gonio {

struct PrimVar {
    ParamDecl decl;
    int components = 1;                // floats per value (3 for point, ncomps for color, ...)
    std::vector<float> values;         // numeric data, `components` floats per value
    std::vector<std::string> strings;  // string data (constant/uniform string parameters)

    int ValueCount() const { return components ? static_cast<int>(values.size()) / components : 0; }
    const float* Value(int i) const { return values.data() + i * components; }
};

// All primitive variables of one primitive, P among them.
struct PrimVarSet {
    std::vector<PrimVar> vars;

    const PrimVar* Find(const std::string& name) const {
        for (const PrimVar& v : vars)
            if (v.decl.name == name) return &v;
        return nullptr;
    }
};

}  // namespace gonio
