#pragma once
// .grd files loaded once and shared by every thread: the brdf() shading builtin asks for a
// file from each shading batch, so the first request reads it and later ones (from any
// thread) get the same BRDF. The renderer keeps one cache per render. A file that cannot be read is
// remembered too, so a bad name costs one attempt and one message, not one per batch.

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "brdfsim/grd_file.h"

namespace gonio {

class GrdCache {
  public:
    // The BRDF in `path`, or null with *error saying why the file cannot be used.
    std::shared_ptr<const GrdFile> Get(const std::string& path, std::string* error);

  private:
    struct Entry {
        std::shared_ptr<const GrdFile> file;
        std::string error;
    };

    std::mutex mutex_;
    std::map<std::string, Entry> entries_;
};

}  // namespace gonio
