#pragma once
// `gonio farm plan`: a scene's frames cut into farm tasks. A BRDFLight frame becomes photon
// shards (consecutive ranges of its path indices: disjoint random sub-streams whose maps, merged
// in order, are exactly the unsplit run's map); an image frame becomes one task, or C×R tiles
// (crop windows sharing their edges, joined exactly into the whole image).

#include <string>
#include <vector>

#include "farm/manifest.h"

namespace gonio {

// What the planner needs to know of one frame of the scene (read by the command from the RIB).
struct SceneFrame {
    int number = 0;
    bool brdfLight = false;
    uint64_t rays = 0;     // BRDFLight paths
    std::string fileName;  // the first Display's, or the photon map's, file name
};

struct PlanRequest {
    std::string scene, gonio;  // absolute
    uint64_t seed = 0;         // passed to gonio render --seed
    int photonShards = 1;
    int tileColumns = 1, tileRows = 1;
    int chunk = 1, retries = 2;
    std::vector<std::string> brdf;  // `gonio brdf` tool and arguments for the merged maps, or {}
    SlurmSettings slurm;
};

// The manifest of the job (outputs relative to the job folder). Throws FarmError for a request
// that cannot be planned (no frame, tiles of a format without data windows, ...).
FarmManifest PlanJob(const PlanRequest& request, const std::vector<SceneFrame>& frames);

}  // namespace gonio
