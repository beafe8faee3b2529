#include "renderer/shading/point_cloud_store.h"

#include <fstream>
#include <sstream>

#include "base/atomic_file.h"
#include "base/diagnostics.h"

namespace gonio {

namespace {

bool SameChannels(const PointCloud& a, const PointCloud& b) {
    if (a.Channels().size() != b.Channels().size()) return false;
    for (size_t i = 0; i < a.Channels().size(); ++i) {
        const PointCloud::Channel &x = a.Channels()[i], &y = b.Channels()[i];
        if (x.name != y.name || x.width != y.width) return false;
    }
    return true;
}

std::string ChannelText(const PointCloud& cloud) {
    std::string text;
    for (const PointCloud::Channel& c : cloud.Channels())
        text += (text.empty() ? "" : ", ") + c.name + "[" + std::to_string(c.width) + "]";
    return text.empty() ? "none" : text;
}

}  // namespace

bool PointCloudStore::Bake(const std::string& file, const PointCloud& points, std::string* why) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto [it, first] = baked_.try_emplace(file);
    PointCloud& cloud = it->second;
    if (first) {
        for (const PointCloud::Channel& c : points.Channels()) cloud.AddChannel(c.name, c.width);
    } else if (!SameChannels(cloud, points)) {
        *why = "its channels were " + ChannelText(cloud) + " at its first bake, here " +
               ChannelText(points);
        return false;
    }
    for (size_t i = 0; i < points.Size(); ++i)
        cloud.Add(points.Position(i), points.Normal(i), points.Values(i));
    return true;
}

bool PointCloudStore::WriteBaked(Diagnostics& diagnostics) {
    std::lock_guard<std::mutex> lock(mutex_);
    bool ok = true;
    for (auto& [file, cloud] : baked_) {
        cloud.Sort();
        const std::string failure = WriteFileAtomically(file, cloud.Serialize());
        if (failure.empty()) continue;
        diagnostics.Error(FileLoc{}, "cannot write point cloud '" + file + "': " + failure);
        ok = false;
    }
    baked_.clear();
    return ok;
}

const PointCloud* PointCloudStore::Load(const std::string& file, std::string* why) {
    return loaded_
        .Get(file, why,
             [](const std::string& path, std::string* error) -> std::shared_ptr<PointCloud> {
                 std::ifstream in(path, std::ios::binary);
                 std::ostringstream bytes;
                 bytes << in.rdbuf();
                 auto cloud = std::make_shared<PointCloud>();
                 if (!in) {
                     *error = "cannot be read";
                 } else if (cloud->Parse(bytes.str(), error)) {
                     cloud->BuildIndex();
                     return cloud;
                 }
                 return nullptr;
             })
        .get();
}

}  // namespace gonio
