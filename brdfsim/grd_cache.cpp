#include "brdfsim/grd_cache.h"

namespace gonio {

std::shared_ptr<const GrdFile> GrdCache::Get(const std::string& path, std::string* error) {
    // Loading under the lock is deliberate: threads asking for a file being loaded need it
    // anyway, and reading a file twice would cost more than waiting.
    std::lock_guard<std::mutex> lock(mutex_);
    auto found = entries_.find(path);
    if (found == entries_.end()) {
        Entry entry;
        try {
            entry.file = std::make_shared<const GrdFile>(ReadGrd(path));
        } catch (const std::exception& e) {
            entry.error = e.what();
        }
        found = entries_.emplace(path, std::move(entry)).first;
    }
    *error = found->second.error;
    return found->second.file;
}

}  // namespace gonio
