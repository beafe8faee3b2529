#include "renderer/image/shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/hash.h"
#include "renderer/scene/depth_map_camera.h"

namespace gonio {

ShadowMap::ShadowMap(int width, int height, std::vector<float> depth,
                     const Imath::M44f& cameraFromWorld, const Imath::M44f& screenFromWorld)
    : width_(width),
      height_(height),
      depth_(std::move(depth)),
      cameraFromWorld_(cameraFromWorld),
      screenFromCamera_(cameraFromWorld.inverse() * screenFromWorld) {}

std::unique_ptr<ShadowMap> ShadowMap::Read(const std::string& path, std::string* error) {
    std::unique_ptr<DepthMapCamera> map = ReadDepthMapCamera(path, error);
    if (!map) return nullptr;
    return std::make_unique<ShadowMap>(map->width, map->height, std::move(map->depth),
                                       map->cameraFromWorld, map->screenFromWorld);
}

Imath::V2f ShadowMap::MapPosition(const Imath::V3f& Pc) const {
    Imath::V3f screen;
    screenFromCamera_.multVecMatrix(Pc, screen);  // divides by w: perspective maps
    return Imath::V2f((screen.x + 1) / 2, (1 - screen.y) / 2);
}

float ShadowMap::Depth(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_)
        return std::numeric_limits<float>::infinity();
    return depth_[size_t(y) * width_ + x];
}

float ShadowMap::Occlusion(const Imath::V3f& P, float footprint, const ShadowFilter& filter,
                           uint64_t seed) const {
    Imath::V3f Pc;
    cameraFromWorld_.multVecMatrix(P, Pc);
    if (!(Pc.z > 0)) return 0;  // behind the map's camera: nothing it saw lies in between
    const Imath::V2f st = MapPosition(Pc);
    // Map units per camera unit across the view at the point's depth (a perspective map's
    // texels grow with depth), from a small step along the map camera's x and y.
    const float step = 1e-3f * std::max(1.f, Pc.z);
    const float sPerUnit = std::fabs(MapPosition(Pc + Imath::V3f(step, 0, 0)).x - st.x) / step;
    const float tPerUnit = std::fabs(MapPosition(Pc + Imath::V3f(0, step, 0)).y - st.y) / step;
    if (!(sPerUnit > 0) || !(tPerUnit > 0) || !std::isfinite(sPerUnit * tPerUnit)) return 0;
    const float reach = std::isfinite(footprint) ? std::max(footprint, 0.f) : 0.f;
    const float regionS = std::max(filter.swidth * reach * sPerUnit + filter.sblur, 1.f / width_);
    const float regionT = std::max(filter.twidth * reach * tPerUnit + filter.tblur, 1.f / height_);
    float bias = filter.bias;
    if (!(bias >= 0)) {
        const float texelWorld = std::max(1 / (width_ * sPerUnit), 1 / (height_ * tPerUnit));
        bias = DefaultBias(texelWorld, std::max(regionS * width_, regionT * height_));
    }
    const float depth = Pc.z - bias;
    // Stratified: one jittered sample in each of g × g cells of the region.
    const int g = std::max(1, int(std::ceil(std::sqrt(float(std::max(filter.samples, 1))))));
    int shadowed = 0;
    for (int j = 0; j < g; ++j)
        for (int i = 0; i < g; ++i) {
            const uint64_t bits = MixBits(HashCombine(seed, uint64_t(j) * g + i));
            const float u = (i + ToUnitFloat(bits)) / g, v = (j + ToUnitFloat(bits << 24)) / g;
            const float s = st.x + (u - 0.5f) * regionS, t = st.y + (v - 0.5f) * regionT;
            shadowed += Depth(int(std::floor(s * width_)), int(std::floor(t * height_))) < depth;
        }
    return float(shadowed) / float(g * g);
}

}  // namespace gonio
