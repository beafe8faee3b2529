#pragma once
// Work items [0, total) cut into `shards` consecutive ranges, as even as integers allow: shard s
// is [⌊total·s/shards⌋, ⌊total·(s+1)/shards⌋). The BRDFLight tracer (gonio render
// --photon-shard) and the farm planner (the paths each shard's map must count) both use it.

#include <cstdint>

namespace gonio {

struct ShardRange {
    uint64_t first = 0, count = 0;
};

inline ShardRange ShardOf(uint64_t total, uint64_t shard, uint64_t shards) {
    // A 128-bit product: total·s overflows 64 bits for 10^18 paths and 16+ shards.
    const auto edge = [&](uint64_t s) {
        return static_cast<uint64_t>(static_cast<unsigned __int128>(total) * s / shards);
    };
    return {edge(shard), edge(shard + 1) - edge(shard)};
}

}  // namespace gonio
