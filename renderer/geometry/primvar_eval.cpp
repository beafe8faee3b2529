#include "renderer/geometry/primvar_eval.h"

namespace gonio {

int ClassCounts::For(ParamClass cls) const {
    switch (cls) {
        case ParamClass::Constant:
            return 1;
        case ParamClass::Uniform:
            return uniform;
        case ParamClass::Varying:
            return varying;
        case ParamClass::Vertex:
            return vertex;
        case ParamClass::FaceVarying:
        case ParamClass::FaceVertex:
            return faceVarying;
    }
    return 1;
}

const char* ClassName(ParamClass cls) {
    switch (cls) {
        case ParamClass::Constant:
            return "constant";
        case ParamClass::Uniform:
            return "uniform";
        case ParamClass::Varying:
            return "varying";
        case ParamClass::Vertex:
            return "vertex";
        case ParamClass::FaceVarying:
            return "facevarying";
        case ParamClass::FaceVertex:
            return "facevertex";
    }
    return "?";
}

bool IsPositionVar(const std::string& name) { return name == "P" || name == "Pw" || name == "Pz"; }

std::optional<std::string> CheckCounts(const PrimVarSet& vars, const ClassCounts& counts) {
    for (const PrimVar& v : vars.vars) {
        if (v.components <= 0) continue;
        const int expected = counts.For(v.decl.cls);
        const bool isString = v.values.empty() && !v.strings.empty();
        const int got = isString ? static_cast<int>(v.strings.size()) : v.ValueCount();
        if (got != expected || (!isString && v.values.size() % v.components != 0))
            return std::string(ClassName(v.decl.cls)) + " variable \"" + v.decl.name + "\" needs " +
                   std::to_string(expected) + " values, got " + std::to_string(got);
    }
    return std::nullopt;
}

std::optional<std::vector<V3f>> ReadPositions(const PrimVarSet& vars, std::string* error) {
    if (const PrimVar* p = vars.Find("P"); p && p->components == 3) {
        std::vector<V3f> points(p->ValueCount());
        for (size_t i = 0; i < points.size(); ++i) {
            const float* v = p->Value(static_cast<int>(i));
            points[i] = V3f(v[0], v[1], v[2]);
        }
        return points;
    }
    if (const PrimVar* pw = vars.Find("Pw"); pw && pw->components == 4) {
        std::vector<V3f> points(pw->ValueCount());
        for (size_t i = 0; i < points.size(); ++i) {
            const float* v = pw->Value(static_cast<int>(i));
            if (v[3] == 0.0f) {
                *error = "Pw value " + std::to_string(i) + " has w = 0";
                return std::nullopt;
            }
            points[i] = V3f(v[0], v[1], v[2]) / v[3];
        }
        return points;
    }
    *error = "the primitive needs positions: \"P\" (point) or \"Pw\" (hpoint)";
    return std::nullopt;
}

std::vector<float> ReadHomogeneousPositions(const PrimVarSet& vars) {
    if (const PrimVar* pw = vars.Find("Pw"); pw && pw->components == 4) return pw->values;
    std::vector<float> out;
    if (const PrimVar* p = vars.Find("P"); p && p->components == 3) {
        out.reserve(p->values.size() / 3 * 4);
        for (int i = 0; i < p->ValueCount(); ++i) {
            const float* v = p->Value(i);
            out.insert(out.end(), {v[0], v[1], v[2], 1.0f});
        }
    }
    return out;
}

PrimVar WithValues(const PrimVar& var, std::vector<float> values) {
    PrimVar out;
    out.decl = var.decl;
    out.components = var.components;
    out.values = std::move(values);
    return out;
}

MeshVar UnchangedMeshVar(const PrimVar& var) {
    const bool uniform = var.decl.cls == ParamClass::Uniform;
    return MeshVar{var, uniform ? MeshRate::PerFace : MeshRate::Constant};
}

}  // namespace gonio
