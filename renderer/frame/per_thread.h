#pragma once
// One object per thread that asks for it, made at its first request: what each thread of a
// frame's tile loop keeps (its shading worker, its tile renderer). oneTBB's
// enumerable_thread_specific does this too, but its constructor opens libtbbmalloc (its pools,
// three /proc reads, 4 MB of mappings), a tenth of the start-up of a frame that has one tile or
// none; Local() is called once per tile, so a lock costs nothing here.

#include <map>
#include <mutex>
#include <thread>

namespace gonio {

template <class T>
class PerThread {
  public:
    // The calling thread's object, value-initialised at its first call.
    T& Local() {
        const std::lock_guard<std::mutex> lock(mutex_);
        return objects_[std::this_thread::get_id()];
    }
    // Every thread's object (call when no thread is using them).
    template <class Visit>
    void ForEach(Visit&& visit) const {
        for (const auto& entry : objects_) visit(entry.second);
    }

  private:
    std::mutex mutex_;
    std::map<std::thread::id, T> objects_;
};

}  // namespace gonio
