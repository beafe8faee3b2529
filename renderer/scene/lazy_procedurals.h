#pragma once
// DelayedReadArchives a frame has not read yet (RISpec 3.2 §5.7: a procedural is expanded when
// its bound first matters). The scene builder reads an archive at once when its bound lies in the
// camera's view; one outside it is recorded here, with its world-space bound, and the ray tracer
// marks every one whose bound some ray (camera, trace(), shadow, path) passes through before it
// hits anything. After the frame is rendered, BuildScene (scene_file.h) reads the scene again with
// the marked archives expanded and renders the frame again, until no ray reaches an unread one.
//
// Each is named by a key that stays the same from one reading to the next: its place among the
// procedurals of its frame ("3"), or, inside an archive, among those of that archive ("3/0").
// Expanding an archive then never renames the procedurals outside it.

#include <Imath/ImathBox.h>

#include <atomic>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace gonio {

struct LazyProcedural {
    Imath::Box3f worldBound;
    std::string key;
};

class LazyProcedurals {
  public:
    void Add(LazyProcedural procedural);
    const std::vector<LazyProcedural>& All() const { return procedurals_; }

    // Thread-safe; `index` into All(). Only whether a ray got there counts, so the marks do
    // not depend on which thread traced which ray.
    void MarkReached(size_t index) const;
    // The keys of the marked ones, in the order they were added.
    std::vector<std::string> ReachedKeys() const;

  private:
    std::vector<LazyProcedural> procedurals_;
    // One flag per procedural (a deque: atomics cannot move, and a deque grows without moving
    // them); shared, so that a copied Frame still reports what its rays reached.
    std::shared_ptr<std::deque<std::atomic<bool>>> reached_ =
        std::make_shared<std::deque<std::atomic<bool>>>();
};

}  // namespace gonio
