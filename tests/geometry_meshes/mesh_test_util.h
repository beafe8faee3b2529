#pragma once
// Small helpers for the geometry tests: building PrimVarSets and measuring meshes.

#include <cmath>
#include <string>
#include <vector>

#include "renderer/geometry/shape.h"

namespace gonio::test {

inline PrimVar Var(const std::string& name, ParamClass cls, ParamType type, int components,
                   std::vector<float> values) {
    PrimVar v;
    v.decl.name = name;
    v.decl.cls = cls;
    v.decl.type = type;
    v.components = components;
    v.values = std::move(values);
    return v;
}

inline PrimVar PointVar(const std::vector<V3f>& points, const std::string& name = "P") {
    std::vector<float> values;
    for (const V3f& p : points) values.insert(values.end(), {p.x, p.y, p.z});
    return Var(name, ParamClass::Vertex, ParamType::Point, 3, std::move(values));
}

inline PrimVarSet WithP(const std::vector<V3f>& points, std::vector<PrimVar> more = {}) {
    PrimVarSet set;
    set.vars.push_back(PointVar(points));
    for (PrimVar& v : more) set.vars.push_back(std::move(v));
    return set;
}

inline V3f TriangleNormal(const TriangleMesh& m, size_t t) {
    const V3f& a = m.positions[m.indices[3 * t]];
    const V3f& b = m.positions[m.indices[3 * t + 1]];
    const V3f& c = m.positions[m.indices[3 * t + 2]];
    return (b - a).cross(c - a);  // length: twice the area
}

inline double MeshArea(const TriangleMesh& m) {
    double area = 0;
    for (size_t t = 0; t < m.TriangleCount(); ++t) area += 0.5 * TriangleNormal(m, t).length();
    return area;
}

inline const MeshVar* FindVar(const TriangleMesh& m, const std::string& name) {
    for (const MeshVar& v : m.vars)
        if (v.var.decl.name == name) return &v;
    return nullptr;
}

}  // namespace gonio::test
