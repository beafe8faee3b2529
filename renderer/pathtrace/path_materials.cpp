#include "renderer/pathtrace/path_materials.h"

#include "base/math.h"
#include "base/search_path.h"
#include "shaderlang/brdf_files.h"

namespace gonio {
namespace {

// The shader's "specularcolor" as ncomps values (one value stands for all), or empty when it
// has none.
std::vector<float> SpecularColor(const sl::ShaderInstance& surface, int ncomps) {
    std::vector<float> color = surface.FloatParameter("specularcolor");
    if (color.size() == 1) color.assign(size_t(ncomps), color[0]);
    if (color.size() != size_t(ncomps)) color.clear();
    return color;
}

}  // namespace

PathMaterials::PathMaterials(const Frame& frame, const FrameShaders& shaders,
                             Diagnostics& diagnostics)
    : frame_(frame), shaders_(shaders), diagnostics_(diagnostics) {
    auto add = [&](const Attributes* attributes) {
        if (!materials_.count(attributes)) materials_.emplace(attributes, Make(*attributes));
    };
    for (const SceneShape& shape : frame.shapes) add(shape.attributes.get());
    for (const ObjectInstanceUse& use : frame.instances)
        for (const auto& attributes : use.shapeAttributes) add(attributes.get());
}

const PathMaterial& PathMaterials::Of(const Attributes* attributes) const {
    auto it = materials_.find(attributes);
    return it == materials_.end() ? matte_ : it->second;
}

PathMaterial PathMaterials::Make(const Attributes& attributes) {
    const ShaderGroup* group = shaders_.Group(&attributes);
    // Without a Surface (or with one that failed to load) a surface is matte (Kd 1), as the
    // photon tracer takes it.
    if (!group || !group->surface) return matte_;
    const sl::ShaderInstance& surface = *group->surface;
    const std::vector<std::string> grids = sl::BrdfFiles(surface);
    PathMaterial material;
    if (grids.empty()) {
        material.phong = MicroBrdfFromShader(surface, attributes, diagnostics_);
        material.specularColor = SpecularColor(surface, frame_.options.colorComponents);
        return material;
    }
    if (grids.size() > 1)
        diagnostics_.WarningOnce(
            "pathtrace grids " + surface.Master().Name(), attributes.surface.loc,
            "path tracing: surface shader \"" + surface.Master().Name() +
                "\" reads several .grd files; its paths sample \"" + grids[0] + "\"");
    material.splat = MakeSplat(surface, grids[0], attributes);
    if (!material.splat) material.phong = MicroBrdf{0, 0, 1};  // black, as brdf() shades it
    return material;
}

std::shared_ptr<const SplatSurface> PathMaterials::MakeSplat(const sl::ShaderInstance& surface,
                                                             const std::string& grid,
                                                             const Attributes& attributes) {
    const std::string path = FindOnSearchPath(grid, shaders_.TextureSearchPath());
    if (path.empty()) {
        diagnostics_.Error(attributes.surface.loc,
                           "path tracing: BRDF grid \"" + grid + "\" not found");
        return nullptr;
    }
    auto known = grids_.find(path);
    if (known == grids_.end()) {
        Grid loaded;
        try {
            loaded.file = std::make_shared<const GrdFile>(ReadGrd(path));
        } catch (const std::exception& e) {
            // The .grd reader's messages name the file.
            diagnostics_.Error(attributes.surface.loc, std::string("path tracing: ") + e.what());
            return nullptr;
        }
        loaded.sampler =
            std::make_shared<const SplatSampler>(loaded.file->splats, *loaded.file->grid);
        known = grids_.emplace(path, loaded).first;
    }
    auto splat = std::make_shared<SplatSurface>();
    splat->file = known->second.file;
    splat->sampler = known->second.sampler;
    const std::vector<float> kb = surface.FloatParameter("Kb");
    splat->scale = kb.empty() ? 1.0f : kb[0];
    // The x axis of the BRDF as the shipped shaders orient it: brushedmetal.sl across its
    // scratches (N × dPdu, or N × dPdv), grass.sl dPdu turned by `angle` about N,
    // brdfsurface.sl dPdu, dPdv or a `direction`.
    const std::string brushing = surface.StringParameter("brushing");
    const std::string orientation = surface.StringParameter("orientation");
    if (!brushing.empty()) {
        splat->axis =
            brushing == "dPdv" ? SplatSurface::Axis::kAcrossDPdv : SplatSurface::Axis::kAcrossDPdu;
    } else if (orientation == "dPdv") {
        splat->axis = SplatSurface::Axis::kDPdv;
    } else if (orientation == "direction") {
        const std::vector<float> d = surface.FloatParameter("direction");
        if (d.size() == 3) {  // loaded in current space (frame_shaders.h)
            splat->axis = SplatSurface::Axis::kDirection;
            frame_.options.cameraFromWorld.inverse().multDirMatrix(Imath::V3f(d[0], d[1], d[2]),
                                                                   splat->direction);
        }
    }
    const std::vector<float> angle = surface.FloatParameter("angle");
    if (!angle.empty()) splat->angle = angle[0] * float(kDegree);
    return splat;
}

}  // namespace gonio
