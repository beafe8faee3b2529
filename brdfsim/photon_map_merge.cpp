#include "brdfsim/photon_map_merge.h"

#include <memory>

namespace gonio {

PhotonMapHeader MergePhotonMaps(const std::vector<std::string>& inputs, const std::string& output) {
    PhotonMapHeader total;
    for (const std::string& path : inputs) {
        const PhotonMapHeader header = ReadPhotonMapHeader(path);
        total.count += header.count;
        total.paths += header.paths;
    }
    std::unique_ptr<PhotonMapWriter> writer;
    int ncomps = 0;
    for (const std::string& path : inputs) {
        PhotonMapReader reader(path);
        std::vector<float> rows;
        bool more = true;
        while (more) {
            rows.clear();
            more = reader.ReadBatch(1 << 18, rows);
            if (rows.empty()) continue;
            if (!writer) {
                ncomps = reader.NumComponents();
                writer = std::make_unique<PhotonMapWriter>(output, total, ncomps);
            } else if (reader.NumComponents() != ncomps) {
                throw PhotonMapError(path + ": " + std::to_string(reader.NumComponents()) +
                                     " colour values per photon, the maps before have " +
                                     std::to_string(ncomps));
            }
            const int stride = kFirstColour + ncomps;
            for (std::size_t i = 0; i < rows.size(); i += stride) writer->Append(&rows[i]);
        }
    }
    if (!writer) throw PhotonMapError("the photon maps hold no photons");
    writer->Close();
    return total;
}

}  // namespace gonio
