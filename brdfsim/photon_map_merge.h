#pragma once
// Photon maps of several runs joined into one (`gonio brdf merge`, and `gonio farm assemble` for
// the shards of a farm job): the rows in input order, the photon and path counts summed, so
// that the estimator divides by every traced path of every run. Bounce tags are kept when every
// input has them, and may select the photons of some bounce counts only.

#include <cstdint>
#include <string>
#include <vector>

#include "brdfsim/photon_map.h"

namespace gonio {

// The bounce counts a merge keeps, inclusive.
struct BounceRange {
    std::uint32_t low = 0, high = kMaxBounces;
};

// Streams `inputs` into `output` (temp + rename), keeping only the photons whose bounce count
// lies in `*bounces` when it is given (every input must then carry bounce tags; the path count
// still sums every traced path). Throws PhotonMapError naming the file for a malformed map,
// maps of different colour counts or a map without the tags a selection needs,
// PhotonMapIoError for I/O failures. Returns the merged header.
PhotonMapHeader MergePhotonMaps(const std::vector<std::string>& inputs, const std::string& output,
                                const BounceRange* bounces = nullptr);

}  // namespace gonio
