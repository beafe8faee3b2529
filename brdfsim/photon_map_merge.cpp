#include "brdfsim/photon_map_merge.h"

#include <algorithm>
#include <memory>

namespace gonio {
namespace {

// Calls `photons(rows, bounces)` for every batch of every input, checking that all have the same
// number of colour values (`ncomps` on return).
template <typename Photons>
void ForEachBatch(const std::vector<std::string>& inputs, int* ncomps, Photons photons) {
    *ncomps = 0;
    for (const std::string& path : inputs) {
        PhotonMapReader reader(path);
        std::vector<float> rows;
        std::vector<std::uint16_t> bounces;
        bool more = true;
        while (more) {
            rows.clear();
            bounces.clear();
            more = reader.ReadBatch(1 << 18, rows, &bounces);
            if (rows.empty()) continue;
            if (*ncomps == 0) {
                *ncomps = reader.NumComponents();
            } else if (reader.NumComponents() != *ncomps) {
                throw PhotonMapError(path + ": " + std::to_string(reader.NumComponents()) +
                                     " colour values per photon, the maps before have " +
                                     std::to_string(*ncomps));
            }
            photons(rows, bounces);
        }
    }
}

}  // namespace

PhotonMapHeader MergePhotonMaps(const std::vector<std::string>& inputs, const std::string& output,
                                const BounceRange* bounces) {
    PhotonMapHeader total;
    total.bounces = true;
    for (const std::string& path : inputs) {
        const PhotonMapHeader header = ReadPhotonMapHeader(path);
        total.count += header.count;
        total.paths += header.paths;
        total.bounces &= header.bounces;
        if (bounces && !header.bounces)
            throw PhotonMapError(path +
                                 ": selecting bounce counts needs bounce tags (trace with "
                                 "Option \"BRDFLight\" \"integer bounces\" 1)");
    }
    auto kept = [&](std::uint16_t b) {
        return !bounces || (b >= bounces->low && b <= bounces->high);
    };
    int ncomps = 0;
    if (bounces) {  // the count leads the file: a first pass counts the kept photons
        total.count = 0;
        ForEachBatch(inputs, &ncomps,
                     [&](const std::vector<float>&, const std::vector<std::uint16_t>& b) {
                         total.count += std::count_if(b.begin(), b.end(), kept);
                     });
    }
    std::unique_ptr<PhotonMapWriter> writer;
    ForEachBatch(inputs, &ncomps,
                 [&](const std::vector<float>& rows, const std::vector<std::uint16_t>& tags) {
                     if (!writer) writer = std::make_unique<PhotonMapWriter>(output, total, ncomps);
                     const int stride = kFirstColour + ncomps;
                     for (std::size_t i = 0; i * stride < rows.size(); ++i) {
                         const std::uint16_t b = tags.empty() ? 0 : tags[i];
                         if (kept(b)) writer->Append(&rows[i * stride], b);
                     }
                 });
    if (!writer) throw PhotonMapError("the photon maps hold no photons");
    writer->Close();
    return total;
}

}  // namespace gonio
