#include "renderer/geometry/tensor_grid.h"

#include <algorithm>
#include <cmath>

#include "renderer/geometry/primvar_eval.h"

namespace gonio {

int TessellationRates::StepsWithinBudget(int steps, long cells) const {
    if (cells <= 0) return steps;
    while (steps > minSteps && cells * (steps + 1L) * (steps + 1L) > vertexBudget) --steps;
    return steps;
}

namespace {

// Adds `weight` times control value (iu, iv) of a `components`-wide array to `out`.
struct ControlGrid {
    const float* values;
    int components, countU, countV;

    void Accumulate(const GridAxis::Sample& su, const GridAxis::Sample& sv, float* out) const {
        std::fill(out, out + components, 0.0f);
        for (size_t b = 0; b < sv.weights.size(); ++b) {
            const int iv = (sv.firstControl + static_cast<int>(b)) % countV;
            for (size_t a = 0; a < su.weights.size(); ++a) {
                const int iu = (su.firstControl + static_cast<int>(a)) % countU;
                const float w = su.weights[a] * sv.weights[b];
                const float* src = values + (static_cast<size_t>(iv) * countU + iu) * components;
                for (int c = 0; c < components; ++c) out[c] += w * src[c];
            }
        }
    }

    void Bilinear(const GridAxis::Sample& su, const GridAxis::Sample& sv, float* out) const {
        const int u0 = su.varyingCell % countU, u1 = (su.varyingCell + 1) % countU;
        const int v0 = sv.varyingCell % countV, v1 = (sv.varyingCell + 1) % countV;
        const float s = su.varyingT, t = sv.varyingT;
        auto at = [&](int iu, int iv) {
            return values + (static_cast<size_t>(iv) * countU + iu) * components;
        };
        const float *a = at(u0, v0), *b = at(u1, v0), *c = at(u0, v1), *d = at(u1, v1);
        for (int k = 0; k < components; ++k)
            out[k] = (1 - t) * ((1 - s) * a[k] + s * b[k]) + t * ((1 - s) * c[k] + s * d[k]);
    }
};

// A vertex or varying variable evaluated at every grid vertex.
std::vector<float> EvaluateOnGrid(const PrimVar& var, const GridAxis& u, const GridAxis& v) {
    const bool vertexClass = var.decl.cls == ParamClass::Vertex;
    const ControlGrid grid{var.values.data(), var.components,
                           vertexClass ? u.controlCount : u.varyingCount,
                           vertexClass ? v.controlCount : v.varyingCount};
    std::vector<float> out(u.samples.size() * v.samples.size() * var.components);
    float* dst = out.data();
    for (const auto& sv : v.samples)
        for (const auto& su : u.samples) {
            if (vertexClass)
                grid.Accumulate(su, sv, dst);
            else
                grid.Bilinear(su, sv, dst);
            dst += var.components;
        }
    return out;
}

std::vector<V3f> AsPoints(const std::vector<float>& v) {
    std::vector<V3f> out(v.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) out[i] = V3f(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    return out;
}

void AttachGridNormals(const PrimVar& n, const GridAxis& u, const GridAxis& v, TriangleMesh* mesh) {
    switch (n.decl.cls) {
        case ParamClass::Constant:
            mesh->normals.assign(mesh->positions.size(),
                                 V3f(n.values[0], n.values[1], n.values[2]));
            break;
        case ParamClass::Uniform:
            for (uint32_t face : mesh->faceOfTriangle) {
                const float* f = n.Value(static_cast<int>(face));
                mesh->cornerNormals.insert(mesh->cornerNormals.end(), 3, V3f(f[0], f[1], f[2]));
            }
            break;
        default:
            mesh->normals = AsPoints(EvaluateOnGrid(n, u, v));
            break;
    }
}

// A curved surface shades smoothly although it is drawn as flat triangles: each grid vertex
// gets dPdu × dPdv estimated by differences to its grid neighbours (one-sided at the edges),
// oriented like the triangles. Where the surface degenerates (a pole), the estimate is zero and
// the renderer falls back to the triangle's own normal.
void AttachSmoothNormals(int nu, int nv, TriangleMesh* mesh) {
    const std::vector<V3f>& p = mesh->positions;
    mesh->normals.resize(p.size());
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, nu - 1);
            const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, nv - 1);
            const V3f du = p[j * nu + i1] - p[j * nu + i0];
            const V3f dv = p[j1 * nu + i] - p[j0 * nu + i];
            const V3f n = du.cross(dv);
            const float len = n.length();
            mesh->normals[j * nu + i] = len > 0 ? n / len : V3f(0, 0, 0);
        }
}

}  // namespace

TriangleMesh TessellateTensorGrid(const GridAxis& u, const GridAxis& v,
                                  const std::vector<float>& homogeneousP, bool rational,
                                  const PrimVarSet& vars) {
    TriangleMesh mesh;
    const int nu = static_cast<int>(u.samples.size()), nv = static_cast<int>(v.samples.size());
    const ControlGrid controls{homogeneousP.data(), 4, u.controlCount, v.controlCount};
    mesh.positions.reserve(static_cast<size_t>(nu) * nv);
    mesh.uv.reserve(static_cast<size_t>(nu) * nv);
    for (const auto& sv : v.samples)
        for (const auto& su : u.samples) {
            float h[4];
            controls.Accumulate(su, sv, h);
            const float w = rational && h[3] != 0 ? h[3] : 1.0f;
            mesh.positions.push_back(V3f(h[0], h[1], h[2]) / w);
            mesh.uv.push_back(V2f(su.param, sv.param));
        }
    for (int j = 0; j + 1 < nv; ++j)
        for (int i = 0; i + 1 < nu; ++i) {
            const uint32_t p00 = j * nu + i, p10 = p00 + 1, p01 = p00 + nu, p11 = p01 + 1;
            mesh.indices.insert(mesh.indices.end(), {p00, p10, p11, p00, p11, p01});
            const uint32_t face = v.intervalCell[j] * u.cellCount + u.intervalCell[i];
            mesh.faceOfTriangle.insert(mesh.faceOfTriangle.end(), {face, face});
        }
    for (const PrimVar& var : vars.vars) {
        if (IsPositionVar(var.decl.name)) continue;
        if (var.decl.name == "N" && var.components == 3) {
            AttachGridNormals(var, u, v, &mesh);
            continue;
        }
        if (var.decl.cls == ParamClass::Constant || var.decl.cls == ParamClass::Uniform)
            mesh.vars.push_back(UnchangedMeshVar(var));
        else
            mesh.vars.push_back({WithValues(var, EvaluateOnGrid(var, u, v)), MeshRate::PerVertex});
    }
    if (mesh.normals.empty() && mesh.cornerNormals.empty()) AttachSmoothNormals(nu, nv, &mesh);
    return mesh;
}

}  // namespace gonio
