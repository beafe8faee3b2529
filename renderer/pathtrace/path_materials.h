#pragma once
// The PathMaterial of every attribute state of a frame, read off its surface shader instance
// (docs/path-tracing.md): a shader whose code calls brdf() with a constant file name is
// sampled from that .grd; any other is the normalised Phong of its Kd, Ks and roughness, as
// the BRDFLight photon tracer reads them. Built once per frame, then read-only.

#include <map>
#include <memory>
#include <string>

#include "base/diagnostics.h"
#include "renderer/pathtrace/path_bsdf.h"
#include "renderer/scene/frame.h"
#include "renderer/shading/frame_shaders.h"

namespace gonio {

class PathMaterials {
  public:
    PathMaterials(const Frame& frame, const FrameShaders& shaders, Diagnostics& diagnostics);
    // The material of a hit's attributes (the frame's attribute states all have one).
    const PathMaterial& Of(const Attributes* attributes) const;

  private:
    PathMaterial Make(const Attributes& attributes);
    std::shared_ptr<const SplatSurface> MakeSplat(const sl::ShaderInstance& surface,
                                                  const std::string& grid,
                                                  const Attributes& attributes);

    const Frame& frame_;
    const FrameShaders& shaders_;
    Diagnostics& diagnostics_;
    std::map<const Attributes*, PathMaterial> materials_;
    // One loaded file and sampler per resolved path, shared by every shader that names it.
    struct Grid {
        std::shared_ptr<const GrdFile> file;
        std::shared_ptr<const SplatSampler> sampler;
    };
    std::map<std::string, Grid> grids_;
    PathMaterial matte_;
};

}  // namespace gonio
