#pragma once
// Files read once per render and shared by every thread (.grd BRDFs, shadow maps, point
// clouds): the first request for a path reads it, and later ones, from any thread, get the
// same object. A file that cannot be read is remembered with its reason, so a bad name costs
// one attempt and one message, not one per shading batch. Reading under the lock is
// deliberate: threads asking for a file being read need it anyway, and reading it twice would
// cost more than waiting.

#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace gonio {

template <class T>
class FileCache {
  public:
    // What read(path, &error) returned on the first request for `path`: the object, or null
    // with the reason in *error.
    template <class Read>
    std::shared_ptr<const T> Get(const std::string& path, std::string* error, Read&& read) {
        const std::lock_guard<std::mutex> lock(mutex_);
        auto [entry, first] = entries_.try_emplace(path);
        if (first) entry->second.value = read(path, &entry->second.error);
        *error = entry->second.error;
        return entry->second.value;
    }

  private:
    struct Entry {
        std::shared_ptr<const T> value;
        std::string error;
    };
    std::mutex mutex_;
    std::map<std::string, Entry> entries_;
};

}  // namespace gonio
