#pragma once
// Photon maps of several runs joined into one (`gonio brdf merge`, and `gonio farm assemble` for
// the shards of a farm job): the rows in input order, the photon and path counts summed, so
// that the estimator divides by every traced path of every run.

#include <string>
#include <vector>

#include "brdfsim/photon_map.h"

namespace gonio {

// Streams `inputs` into `output` (temp + rename). Throws PhotonMapError naming the file for a
// malformed map or maps of different colour counts, PhotonMapIoError for I/O failures. Returns
// the merged header.
PhotonMapHeader MergePhotonMaps(const std::vector<std::string>& inputs, const std::string& output);

}  // namespace gonio
