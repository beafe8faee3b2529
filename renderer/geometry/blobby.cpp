#include "renderer/geometry/blobby.h"

#include <array>
#include <cmath>
#include <memory>

#include "renderer/geometry/blobby_field.h"
#include "renderer/geometry/primvar_eval.h"
#include "renderer/geometry/surface_nets.h"

namespace gonio {

namespace {

// The grid layout of PolygonizeSurfaceNets over `box` with cells of side `cell`: its origin
// and blocks per axis.
struct BlockLayout {
    V3f origin;
    std::array<long, 3> blocks{};
    BlockLayout(const Box3f& box, float cell) : origin(box.min - V3f(cell)) {
        for (int a = 0; a < 3; ++a)
            blocks[a] =
                long(std::ceil((box.max[a] - box.min[a]) / cell) + 2) / kSurfaceNetsBlock + 1;
    }
    double Count() const { return double(blocks[0]) * blocks[1] * blocks[2]; }
};

// Whether PolygonizeSurfaceNets samples at most `budget` points: those of the blocks some
// support reaches.
bool WithinBudget(const std::vector<Box3f>& supports, const BlockLayout& layout, float cell,
                  double budget) {
    const double side = double(kSurfaceNetsBlock) * cell;
    const double perBlock = std::pow(double(kSurfaceNetsBlock), 3);
    std::vector<uint8_t> reached(size_t(layout.Count()), 0);
    double points = 0;
    for (const Box3f& s : supports) {
        std::array<long, 3> lo, hi;
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(0L, long(std::floor((s.min[a] - layout.origin[a] - cell) / side)) - 1);
            hi[a] = std::min(layout.blocks[a] - 1,
                             long(std::floor((s.max[a] - layout.origin[a] + cell) / side)));
        }
        for (long z = lo[2]; z <= hi[2]; ++z)
            for (long y = lo[1]; y <= hi[1]; ++y)
                for (long x = lo[0]; x <= hi[0]; ++x) {
                    uint8_t& r = reached[x + layout.blocks[0] * (y + layout.blocks[1] * z)];
                    points += r ? 0 : perBlock;
                    r = 1;
                }
        if (points > budget) return false;
    }
    return true;
}

// Unit shading normals pointing out of the surface: −∇F, or the mean of the vertex's facet
// normals where the gradient vanishes (a saddle, or F flat at the threshold).
std::vector<V3f> OutwardNormals(const IsoMesh& iso) {
    std::vector<V3f> facets(iso.positions.size(), V3f(0));
    for (size_t t = 0; t + 2 < iso.indices.size(); t += 3) {
        const V3f& a = iso.positions[iso.indices[t]];
        const V3f n =
            (iso.positions[iso.indices[t + 1]] - a).cross(iso.positions[iso.indices[t + 2]] - a);
        for (int k = 0; k < 3; ++k) facets[iso.indices[t + k]] += n;
    }
    std::vector<V3f> normals(iso.positions.size());
    for (size_t i = 0; i < normals.size(); ++i) {
        const V3f n = iso.gradients[i].length2() > 0 ? -iso.gradients[i] : facets[i];
        normals[i] = n.length2() > 0 ? n.normalized() : V3f(0, 0, 1);
    }
    return normals;
}

// The vertex-rate variables blended at each mesh vertex by the leaves' weights there.
void AddBlendedVars(const BlobbyField& field, const PrimVarSet& vars, TriangleMesh* mesh) {
    std::vector<const PrimVar*> blended;
    for (const PrimVar& var : vars.vars) {
        if (IsPositionVar(var.decl.name) || var.decl.name == "N") continue;
        const bool perLeaf = var.decl.cls == ParamClass::Vertex ||
                             var.decl.cls == ParamClass::Varying ||
                             var.decl.cls == ParamClass::FaceVarying;
        if (perLeaf && var.strings.empty())
            blended.push_back(&var);
        else
            mesh->vars.push_back(UnchangedMeshVar(var));
    }
    if (blended.empty()) return;
    std::vector<std::vector<float>> values(blended.size());
    std::vector<FieldSample> scratch;
    std::vector<float> weights;
    for (const V3f& p : mesh->positions) {
        field.LeafWeights(p, &scratch, &weights);
        for (size_t v = 0; v < blended.size(); ++v) {
            const PrimVar& var = *blended[v];
            const size_t first = values[v].size();
            values[v].resize(first + var.components, 0.f);
            for (size_t leaf = 0; leaf < weights.size(); ++leaf) {
                if (weights[leaf] == 0) continue;
                const float* value = var.Value(static_cast<int>(leaf));
                for (int c = 0; c < var.components; ++c)
                    values[v][first + c] += weights[leaf] * value[c];
            }
        }
    }
    for (size_t v = 0; v < blended.size(); ++v)
        mesh->vars.push_back(
            MeshVar{WithValues(*blended[v], std::move(values[v])), MeshRate::PerVertex});
}

// Each repelling plane's depth map; a plane whose map cannot be had keeps z = 0 of object space.
void AttachDepthMaps(const BlobbyDepthMapLookup& findDepthMap, BlobbyProgram* program,
                     std::vector<std::string>* notes) {
    for (BlobbyLeaf& leaf : program->leaves) {
        if (leaf.kind != BlobbyLeaf::Kind::Plane) continue;
        std::string why = "no depth maps are read here";
        if (findDepthMap) leaf.depthMap = findDepthMap(leaf.name, &why);
        if (!leaf.depthMap)
            notes->push_back("the repelling plane's depth map \"" + leaf.name + "\" is not used (" +
                             why +
                             "): the plane is z = 0 of object space, with z the height above it");
    }
}

}  // namespace

float BlobbyTessellation::CellSize(float feature, const std::vector<Box3f>& supports,
                                   const Box3f& box) const {
    float cell = feature * std::sqrt(shadingRate) / kCellsPerRadius;
    const Imath::V3f size = box.size();
    const float largest = std::max({size.x, size.y, size.z});
    if (!(cell > 0) || !std::isfinite(cell)) cell = largest / 64;
    for (;; cell *= 1.25f) {
        const BlockLayout layout(box, cell);
        if (layout.Count() <= double(kBlockBudget) &&
            WithinBudget(supports, layout, cell, double(kGridBudget)))
            return cell;
    }
}

GeometryResult<BlobbyMesh> MakeBlobby(int nleaf, const std::vector<int>& code,
                                      const std::vector<float>& floats,
                                      const std::vector<std::string>& strings,
                                      const PrimVarSet& vars, const BlobbyTessellation& rates,
                                      std::vector<std::string>* notes,
                                      const BlobbyDepthMapLookup& findDepthMap) {
    using Result = GeometryResult<BlobbyMesh>;
    auto program = DecodeBlobby(nleaf, code, floats, strings, notes);
    if (!program) return Result::Error(program.Error());
    AttachDepthMaps(findDepthMap, &program.Value(), notes);
    const int leaves = static_cast<int>(program.Value().leaves.size());
    if (auto bad = CheckCounts(vars, ClassCounts{1, leaves, leaves, leaves}))
        return Result::Error(*bad);
    if (vars.Find("N")) notes->push_back("N is ignored: normals come from the field's gradient");

    const BlobbyField field(program.Take());
    BlobbyMesh out;
    if (field.Bounds().isEmpty()) {
        notes->push_back(
            "the code has no ellipsoid or segment blob: there is no closed surface "
            "to render");
        return out;
    }
    const bool everywhere = field.FarValue() > BlobbyField::kThreshold;
    if (everywhere)
        notes->push_back(
            "the field is above the threshold away from every blob: the surface is "
            "cut off at the blobs' bound");

    auto local = std::make_shared<BlobbyField::Local>();
    IsoField iso;
    iso.near = [&](const Box3f& box) -> IsoEvaluator {
        if (!field.Localize(box, local.get()) && !everywhere) return {};
        return [&field, local](const V3f& p, float* value, V3f* gradient) {
            const FieldSample s = field.Evaluate(p, local.get());
            *value = s.value - BlobbyField::kThreshold;
            *gradient = s.gradient;
        };
    };
    const Box3f bounds = field.Bounds();
    std::vector<Box3f> supports;
    for (const BlobbyLeaf& leaf : field.Program().leaves)
        if (!leaf.support.isEmpty()) supports.push_back(leaf.support);
    out.cell = rates.CellSize(field.SmallestFeature(), supports, bounds);
    IsoMesh surface = PolygonizeSurfaceNets(iso, bounds, out.cell);

    TriangleMesh& mesh = out.mesh;
    mesh.normals = OutwardNormals(surface);
    mesh.positions = std::move(surface.positions);
    mesh.indices = std::move(surface.indices);
    mesh.faceOfTriangle.assign(mesh.TriangleCount(), 0);  // one uniform value: one "face"
    out.sampledPoints = surface.sampledPoints;
    AddBlendedVars(field, vars, &mesh);
    return out;
}

}  // namespace gonio
