#pragma once
// The point clouds of one frame, shared by its threads: what bake3d() stores, gathered from
// every thread and written (sorted, atomically) when the frame ends, and the files texture3d()
// reads, each read and indexed once. A frame reads the files as they were when it started to
// look them up: a cloud baked in a frame is for the frames after it.

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "base/file_cache.h"
#include "renderer/shading/point_cloud.h"

namespace gonio {

class Diagnostics;

class PointCloudStore {
  public:
    // Adds `points` to the cloud that `file` will hold. Its channels must be those of the
    // file's first bake (names and widths, in order); false with the reason if not.
    bool Bake(const std::string& file, const PointCloud& points, std::string* why);
    // Writes every cloud baked since the last call, each sorted (PointCloud::Sort) so that the
    // file does not depend on the thread count; reports each failure as an error. False if
    // any failed.
    bool WriteBaked(Diagnostics& diagnostics);
    // The cloud in `file` with its index built, read on first use; null with the reason.
    const PointCloud* Load(const std::string& file, std::string* why);

  private:
    std::mutex mutex_;  // guards baked_
    std::map<std::string, PointCloud> baked_;
    FileCache<PointCloud> loaded_;
};

}  // namespace gonio
