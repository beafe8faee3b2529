#pragma once
// Shadow-map lookups for shadow() (RISpec §15.7.3): percentage-closer filtering (Reeves, Salesin
// and Cook 1987, "Rendering Antialiased Shadows with Depth Maps"): the depths of the map over a
// filter region around the point's place in it are each compared with the point's own depth,
// and the fraction that lies in front of the point is the fraction in shadow. The region is
// sampled at stratified, jittered positions (a g × g grid of strata), deterministic for a seed.

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/file_cache.h"

namespace gonio {

// shadow()'s filter, in PRMan's and Pixie's parameter names.
struct ShadowFilter {
    int samples = 16;              // rounded up to a square, g × g strata
    float swidth = 1, twidth = 1;  // scale the shaded point's footprint in the map
    float sblur = 0, tblur = 0;    // added to the region, as fractions of the map's width/height
    float bias = -1;               // depth offset (camera units); negative: DefaultBias
};

class ShadowMap {
  public:
    // `depth`: width × height camera-space depths, rows from the top (+inf where nothing was
    // seen); the matrices take world space to the map's camera and to its screen, the map
    // covering [-1, 1]² (x right, y up), for row vectors as RenderMan writes them.
    ShadowMap(int width, int height, std::vector<float> depth, const Imath::M44f& cameraFromWorld,
              const Imath::M44f& screenFromWorld);

    // Reads a shadow map or a depth map (renderer/scene/depth_map_camera.h); null and the reason
    // when the file is missing, is not a depth map or records no camera.
    static std::unique_ptr<ShadowMap> Read(const std::string& path, std::string* error);

    // The fraction of the filter region around world-space point P that is in shadow: 0 lit,
    // 1 shadowed. `footprint` is the world-space width of what the point stands for (a camera
    // pixel's width there; 0 for none): its image in the map, scaled by the widths, plus the
    // blurs, is the region, never smaller than one texel. A point outside the map or behind its
    // camera is lit. `seed` chooses the jitter.
    float Occlusion(const Imath::V3f& P, float footprint, const ShadowFilter& filter,
                    uint64_t seed) const;

    // The bias used when the shader gives none: twice the world-space extent, at the point's
    // depth, of one texel plus half the filter region (`regionTexels` wide), which is how far
    // a surface's depth can differ from the map's at slopes up to 63° to the light (a
    // min-depth texel is up to one texel off, the region's samples up to half of it).
    float DefaultBias(float texelWorld, float regionTexels) const {
        return 2 * texelWorld * (1 + 0.5f * regionTexels);
    }

    int Width() const { return width_; }
    int Height() const { return height_; }

  private:
    // The map position (s, t) in [0, 1]² (t down) of camera-space point Pc.
    Imath::V2f MapPosition(const Imath::V3f& Pc) const;
    // The depth of texel (x, y); +inf outside the map.
    float Depth(int x, int y) const;

    int width_, height_;
    std::vector<float> depth_;
    Imath::M44f cameraFromWorld_, screenFromCamera_;
};

// The shadow maps of one render, each read once for all threads (base/file_cache.h).
class ShadowMapCache {
  public:
    // The map in `path`, or null with the reason in `error`.
    std::shared_ptr<const ShadowMap> Get(const std::string& path, std::string* error) {
        return maps_.Get(path, error, ShadowMap::Read);
    }

  private:
    FileCache<ShadowMap> maps_;
};

}  // namespace gonio
