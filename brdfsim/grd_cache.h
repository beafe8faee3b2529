#pragma once
// .grd files loaded once and shared by every thread (base/file_cache.h): the brdf() shading
// builtin asks for a file from each shading batch, so the first request reads it and later ones
// get the same BRDF. The renderer keeps one cache per render.

#include <memory>
#include <string>

#include "base/file_cache.h"
#include "brdfsim/grd_file.h"

namespace gonio {

class GrdCache {
  public:
    // The BRDF in `path`, or null with *error saying why the file cannot be used.
    std::shared_ptr<const GrdFile> Get(const std::string& path, std::string* error);

  private:
    FileCache<GrdFile> files_;
};

}  // namespace gonio
