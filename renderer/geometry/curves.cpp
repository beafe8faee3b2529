#include "renderer/geometry/curves.h"

#include <array>

#include "renderer/geometry/primvar_eval.h"

namespace gonio {
namespace {

struct CurveLayout {
    bool cubic = false;
    bool periodic = false;
    PatchBasis basis;

    int Step() const { return cubic ? basis.step : 1; }
    // RISpec §5.5: segments of one curve of n vertices.
    int Segments(int n) const {
        if (!cubic) return periodic ? n : n - 1;
        return periodic ? n / basis.step : (n - 4) / basis.step + 1;
    }
    int VaryingCount(int n) const { return periodic ? Segments(n) : Segments(n) + 1; }

    std::optional<std::string> Check(int n) const {
        const std::string count = std::to_string(n);
        if (!cubic) {
            if (n < 2) return "a linear curve needs at least 2 vertices, got " + count;
            return std::nullopt;
        }
        if (basis.step < 1) return "the v basis step must be at least 1";
        if (periodic && (n < 4 || n % basis.step != 0))
            return "a periodic cubic curve needs a multiple of the v step " +
                   std::to_string(basis.step) + " vertices (at least 4), got " + count;
        if (!periodic && (n < 4 || (n - 4) % basis.step != 0))
            return "a nonperiodic cubic curve needs 4 plus a multiple of the v step " +
                   std::to_string(basis.step) + " vertices, got " + count;
        return std::nullopt;
    }
};

// Where one curve's data starts in the vertex and varying arrays.
struct CurveSpan {
    int firstVertex, vertexCount, firstVarying, segments;
};

// The value of a varying or vertex variable at the start (t = 0) or end (t = 1) of segment s.
void ValueAtSegmentEnd(const PrimVar& var, const CurveLayout& layout, const CurveSpan& curve, int s,
                       float t, float* out) {
    const int k = var.components;
    if (var.decl.cls == ParamClass::Vertex && layout.cubic) {
        const auto w = BasisWeights(layout.basis.matrix, t);
        std::fill(out, out + k, 0.0f);
        for (int a = 0; a < 4; ++a) {
            const int i = (s * layout.Step() + a) % curve.vertexCount;
            const float* src = var.Value(curve.firstVertex + i);
            for (int c = 0; c < k; ++c) out[c] += w[a] * src[c];
        }
        return;
    }
    // Varying values sit at segment ends; so do vertex values of linear curves.
    const bool vertex = var.decl.cls == ParamClass::Vertex;
    const int count = vertex ? curve.vertexCount : layout.VaryingCount(curve.vertexCount);
    const int index = (s + (t > 0 ? 1 : 0)) % count;
    const float* src = var.Value((vertex ? curve.firstVertex : curve.firstVarying) + index);
    std::copy(src, src + k, out);
}

float WidthAt(const PrimVar* width, float constantWidth, const CurveLayout& layout,
              const CurveSpan& curve, int s, float t) {
    if (!width) return constantWidth;
    float w;
    ValueAtSegmentEnd(*width, layout, curve, s, t, &w);
    return w;
}

V3f NormalAt(const PrimVar& n, const CurveLayout& layout, const CurveSpan& curve, int curveIndex,
             int s, float t) {
    if (n.decl.cls == ParamClass::Constant) return V3f(n.values[0], n.values[1], n.values[2]);
    if (n.decl.cls == ParamClass::Uniform) {
        const float* v = n.Value(curveIndex);
        return V3f(v[0], v[1], v[2]);
    }
    float v[3];
    ValueAtSegmentEnd(n, layout, curve, s, t, v);
    return V3f(v[0], v[1], v[2]);
}

}  // namespace

GeometryResult<CurveSet> MakeCurves(const std::string& type, const std::vector<int>& nvertices,
                                    const std::string& wrap, const PatchBasis& vbasis,
                                    const PrimVarSet& vars) {
    using Result = GeometryResult<CurveSet>;
    if (type != "linear" && type != "cubic")
        return Result::Error("unknown curve type \"" + type +
                             "\" (expected \"linear\" or \"cubic\")");
    if (wrap != "periodic" && wrap != "nonperiodic")
        return Result::Error("unknown wrap mode \"" + wrap +
                             "\" (expected \"periodic\" or \"nonperiodic\")");
    const CurveLayout layout{type == "cubic", wrap == "periodic", vbasis};
    std::vector<CurveSpan> curves;
    int vertices = 0, varying = 0;
    for (int n : nvertices) {
        if (auto bad = layout.Check(n)) return Result::Error(*bad);
        curves.push_back({vertices, n, varying, layout.Segments(n)});
        vertices += n;
        varying += layout.VaryingCount(n);
    }
    const ClassCounts counts{static_cast<int>(nvertices.size()), varying, vertices, varying};
    if (auto bad = CheckCounts(vars, counts)) return Result::Error(*bad);
    std::string error;
    const auto points = ReadPositions(vars, &error);
    if (!points) return Result::Error(error);

    const PrimVar* width = vars.Find("width");
    if (width && (width->components != 1 || width->decl.cls == ParamClass::Constant ||
                  width->decl.cls == ParamClass::Uniform))
        width = nullptr;
    float constantWidth = 1.0f;
    if (const PrimVar* cw = vars.Find("constantwidth"); cw && !cw->values.empty())
        constantWidth = cw->values[0];
    const PrimVar* normal = vars.Find("N");
    if (normal && normal->components != 3) normal = nullptr;

    CurveSet set;
    set.basis = layout.cubic ? CurveSet::Basis::Bezier : CurveSet::Basis::Linear;
    set.ribbon = normal != nullptr;
    for (size_t c = 0; c < curves.size(); ++c) {
        const CurveSpan& curve = curves[c];
        const auto vertex = [&](int i) {
            return (*points)[curve.firstVertex + i % curve.vertexCount];
        };
        for (int s = 0; s < curve.segments; ++s) {
            const float r0 = 0.5f * WidthAt(width, constantWidth, layout, curve, s, 0);
            const float r1 = 0.5f * WidthAt(width, constantWidth, layout, curve, s, 1);
            set.curveOfSegment.push_back(static_cast<uint32_t>(c));
            set.segmentV0.push_back(static_cast<float>(s) / curve.segments);
            set.segmentV1.push_back(static_cast<float>(s + 1) / curve.segments);
            if (!layout.cubic) {
                // Linear segments share their end points: a curve's points are consecutive.
                if (s == 0) {
                    set.controlPoints.push_back(vertex(0));
                    set.radii.push_back(r0);
                    if (normal) set.normals.push_back(NormalAt(*normal, layout, curve, c, s, 0));
                }
                set.segmentFirst.push_back(static_cast<uint32_t>(set.controlPoints.size() - 1));
                set.controlPoints.push_back(vertex(s + 1));
                set.radii.push_back(r1);
                if (normal) set.normals.push_back(NormalAt(*normal, layout, curve, c, s, 1));
                continue;
            }
            set.segmentFirst.push_back(static_cast<uint32_t>(set.controlPoints.size()));
            const int first = s * layout.Step();
            const std::array<V3f, 4> g = {vertex(first), vertex(first + 1), vertex(first + 2),
                                          vertex(first + 3)};
            for (const V3f& b : ToBezier(layout.basis.matrix, g)) set.controlPoints.push_back(b);
            for (int k = 0; k < 4; ++k) set.radii.push_back(r0 + (r1 - r0) * k / 3.0f);
            if (!normal) continue;
            if (normal->decl.cls == ParamClass::Vertex) {
                std::array<V3f, 4> gn;
                for (int k = 0; k < 4; ++k) {
                    const float* v =
                        normal->Value(curve.firstVertex + (first + k) % curve.vertexCount);
                    gn[k] = V3f(v[0], v[1], v[2]);
                }
                for (const V3f& b : ToBezier(layout.basis.matrix, gn)) set.normals.push_back(b);
            } else {
                const V3f n0 = NormalAt(*normal, layout, curve, c, s, 0);
                const V3f n1 = NormalAt(*normal, layout, curve, c, s, 1);
                for (int k = 0; k < 4; ++k) set.normals.push_back(n0 + (n1 - n0) * (k / 3.0f));
            }
        }
    }

    for (const PrimVar& var : vars.vars) {
        const std::string& name = var.decl.name;
        if (IsPositionVar(name) || name == "width" || name == "constantwidth" ||
            (normal && name == "N"))
            continue;
        if (var.decl.cls == ParamClass::Constant || var.decl.cls == ParamClass::Uniform) {
            set.vars.vars.push_back(var);
            continue;
        }
        std::vector<float> ends(2 * set.segmentFirst.size() * var.components);
        float* dst = ends.data();
        for (size_t c = 0; c < curves.size(); ++c)
            for (int s = 0; s < curves[c].segments; ++s)
                for (float t : {0.0f, 1.0f}) {
                    ValueAtSegmentEnd(var, layout, curves[c], s, t, dst);
                    dst += var.components;
                }
        set.vars.vars.push_back(WithValues(var, std::move(ends)));
    }
    return set;
}

}  // namespace gonio
