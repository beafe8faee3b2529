#pragma once
// Per-cell splat lists in compressed form (offsets + entries), built on both cores in two passes
// (count, then fill) so the order inside each list is the splat order whatever the thread count:
// sums over a list, and so lookups, are then deterministic.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

namespace gonio {

// Called with the fraction done, from one thread at a time.
using ProgressFn = std::function<void(double)>;

// An entry names a splat and the image through which it reaches the cell.
constexpr int kImageShift = 29;
constexpr std::uint32_t kSplatMask = (1u << kImageShift) - 1;

struct CellLists {
    std::vector<std::uint64_t> offsets;  // cells + 1
    std::vector<std::uint32_t> entries;

    std::size_t NumCells() const { return offsets.empty() ? 0 : offsets.size() - 1; }
    std::size_t Bytes() const { return offsets.size() * 8 + entries.size() * 4; }

    // emit(k, add) calls add(cell, entry) for every cell splat k reaches.
    template <typename Emit>
    static CellLists Build(std::size_t numCells, std::size_t numSplats, const Emit& emit,
                           const ProgressFn& progress);
};

template <typename Emit>
CellLists CellLists::Build(std::size_t numCells, std::size_t numSplats, const Emit& emit,
                           const ProgressFn& progress) {
    // Per-chunk counters cost 12 bytes a cell: keep them to some tens of MB for fine grids.
    const std::size_t byMemory = std::max<std::size_t>(2, (std::size_t(1) << 21) / numCells);
    const std::size_t chunks =
        std::max<std::size_t>(1, std::min({(numSplats + 1023) / 1024, byMemory, std::size_t(256)}));
    std::vector<std::uint32_t> counts(chunks * numCells, 0);
    std::atomic<std::size_t> done{0};
    std::mutex progressMutex;
    auto report = [&](std::size_t n) {
        const std::size_t total = done += n;
        if (progress) {
            std::lock_guard<std::mutex> lock(progressMutex);
            progress(total / (2.0 * numSplats));
        }
    };
    auto range = [&](std::size_t c) {
        return std::make_pair(numSplats * c / chunks, numSplats * (c + 1) / chunks);
    };
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
        std::uint32_t* mine = &counts[c * numCells];
        const auto [begin, end] = range(c);
        for (std::size_t k = begin; k < end; ++k) {
            emit(k, [&](std::size_t cell, std::uint32_t) { ++mine[cell]; });
        }
        report(end - begin);
    });
    CellLists lists;
    lists.offsets.assign(numCells + 1, 0);
    std::vector<std::uint64_t> starts(chunks * numCells);
    std::uint64_t total = 0;
    for (std::size_t cell = 0; cell < numCells; ++cell) {
        lists.offsets[cell] = total;
        for (std::size_t c = 0; c < chunks; ++c) {
            starts[c * numCells + cell] = total;
            total += counts[c * numCells + cell];
        }
    }
    lists.offsets[numCells] = total;
    counts = {};
    lists.entries.resize(total);
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
        std::uint64_t* next = &starts[c * numCells];
        const auto [begin, end] = range(c);
        for (std::size_t k = begin; k < end; ++k) {
            emit(k, [&](std::size_t cell, std::uint32_t entry) {
                lists.entries[next[cell]++] = entry;
            });
        }
        report(end - begin);
    });
    return lists;
}

}  // namespace gonio
