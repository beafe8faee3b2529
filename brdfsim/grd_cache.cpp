#include "brdfsim/grd_cache.h"

namespace gonio {

std::shared_ptr<const GrdFile> GrdCache::Get(const std::string& path, std::string* error) {
    return files_.Get(path, error,
                      [](const std::string& file, std::string* why) -> std::shared_ptr<GrdFile> {
                          try {
                              return std::make_shared<GrdFile>(ReadGrd(file));
                          } catch (const std::exception& e) {
                              *why = e.what();
                              return nullptr;
                          }
                      });
}

}  // namespace gonio
