#pragma once
// The files shaders read by name during one render, each opened once for all threads:
// textures (OpenImageIO's cache), shadow maps, measured BRDFs (.grd files for brdf()) and point
// clouds. The renderer owns one per render, so that a file rewritten between renders is read
// again.

#include "brdfsim/grd_cache.h"
#include "renderer/image/shadow_map.h"
#include "renderer/image/texture_lookup.h"
#include "renderer/shading/point_cloud_store.h"

namespace gonio {

struct ShadingFiles {
    TextureLookup textures;       // thread-safe
    GrdCache brdfs;               // thread-safe
    ShadowMapCache shadowMaps;    // thread-safe
    PointCloudStore pointClouds;  // thread-safe: bake3d() and texture3d()
};

}  // namespace gonio
