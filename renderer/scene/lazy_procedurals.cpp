#include "renderer/scene/lazy_procedurals.h"

namespace gonio {

void LazyProcedurals::Add(LazyProcedural procedural) {
    procedurals_.push_back(std::move(procedural));
    reached_->emplace_back(false);
}

void LazyProcedurals::MarkReached(size_t index) const {
    std::atomic<bool>& flag = (*reached_)[index];
    // Read first: most rays find it marked already, and a load does not contend for the line.
    if (!flag.load(std::memory_order_relaxed)) flag.store(true, std::memory_order_relaxed);
}

std::vector<std::string> LazyProcedurals::ReachedKeys() const {
    std::vector<std::string> keys;
    for (size_t i = 0; i < procedurals_.size(); ++i)
        if ((*reached_)[i].load(std::memory_order_relaxed)) keys.push_back(procedurals_[i].key);
    return keys;
}

}  // namespace gonio
