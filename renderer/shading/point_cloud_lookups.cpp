// The renderer's side of bake3d(), texture3d() and bake() (shaderlang/runtime/
// builtins_pointcloud.cpp): the shading language's current-space points stored in and looked
// up from the frame's PointCloudStore in world space, so that a cloud baked through one camera
// serves another.

#include <algorithm>

#include "renderer/shading/point_cloud_store.h"
#include "renderer/shading/render_context.h"

namespace gonio {

namespace {

V3f Plane3(const float* planes, int count, int k) {
    return V3f(planes[k], planes[count + k], planes[2 * size_t(count) + k]);
}

}  // namespace

bool RenderContext::BakePoints(const std::string& file, const float* P, const float* N,
                               const uint8_t* active,
                               const std::vector<sl::PointChannel>& channels) {
    PointCloud points;
    for (const sl::PointChannel& c : channels) {
        if (!points.AddChannel(c.name, c.width)) {
            RuntimeWarning("bake3d " + file, "bake3d(\"" + file + "\"): channel '" + c.name +
                                                 "' is given twice; nothing is baked");
            return false;
        }
    }
    // Normals go to world space by the inverse transpose of worldFromCurrent: n ·
    // (currentFromWorld)ᵀ.
    const M44f normalToWorld = shaders_.CurrentFromWorld().transposed();
    std::vector<float> values(size_t(points.ValueWidth()));
    // Neighbour points (i >= MainCount()) are copies a pixel away for derivatives: not baked.
    for (int i = 0; i < MainCount(); ++i) {
        if (active && !active[i]) continue;
        V3f Pw, Nw;
        worldFromCurrent_.multVecMatrix(Plane3(P, n_, i), Pw);
        normalToWorld.multDirMatrix(Plane3(N, n_, i), Nw);
        for (size_t c = 0; c < channels.size(); ++c)
            for (int k = 0; k < channels[c].width; ++k)
                values[size_t(points.Channels()[c].offset + k)] = channels[c].values.At(k, i);
        points.Add(Pw, Nw, values.data());
    }
    std::string why;
    if (pointClouds_.Bake(file, points, &why)) return true;
    RuntimeWarning("bake3d " + file, "bake3d(\"" + file + "\"): " + why + "; not baked");
    return false;
}

bool RenderContext::LookupPoints(const std::string& file, const float* P, const float*,
                                 const uint8_t* active,
                                 const std::vector<sl::PointChannel>& channels) {
    for (const sl::PointChannel& c : channels)
        for (int k = 0; k < c.width; ++k) std::fill_n(c.values.data + size_t(k) * n_, n_, 0.0f);
    std::string why;
    const PointCloud* cloud = pointClouds_.Load(file, &why);
    if (!cloud) {
        RuntimeWarning("texture3d " + file,
                       "texture3d(\"" + file + "\"): " + why + "; the values are 0");
        return false;
    }
    bool ok = true;
    std::vector<const PointCloud::Channel*> found;
    for (const sl::PointChannel& c : channels) {
        const PointCloud::Channel* stored = cloud->FindChannel(c.name);
        if (!stored || stored->width != c.width) {
            RuntimeWarning("texture3d " + file + " " + c.name,
                           "texture3d(\"" + file + "\"): the cloud has no channel '" + c.name +
                               "' of " + std::to_string(c.width) + " floats; it gives 0");
            ok = false;
            stored = nullptr;
        }
        found.push_back(stored);
    }
    for (int i = 0; i < n_; ++i) {
        if (active && !active[i]) continue;
        V3f Pw;
        worldFromCurrent_.multVecMatrix(Plane3(P, n_, i), Pw);
        const long nearest = cloud->Nearest(Pw);
        if (nearest < 0) continue;
        const float* values = cloud->Values(size_t(nearest));
        for (size_t c = 0; c < channels.size(); ++c) {
            if (!found[c]) continue;
            for (int k = 0; k < channels[c].width; ++k)
                channels[c].values.At(k, i) = values[found[c]->offset + k];
        }
    }
    return ok && cloud->Size() > 0;
}

}  // namespace gonio
