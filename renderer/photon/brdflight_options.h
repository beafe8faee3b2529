#pragma once
// `Option "BRDFLight"` (thesis Appendix C.2, plus the parameters this project adds), read from the
// typed option list the scene builder keeps in Frame::options.user["BRDFLight"].

#include <cstdint>
#include <string>

#include "base/diagnostics.h"
#include "renderer/scene/frame.h"

namespace gonio {

struct BrdfLightOptions {
    std::string textureName;  // the photon map to write
    int64_t rays = 100000;    // photon paths
    float area = 0.1f;        // side of the square sampling area (and of a periodic tile)
    bool isotropic = false;   // φ_in = 0
    // Isotropic runs: light from every azimuth, stored relative to it (see photon_tracer.h).
    bool averageAzimuth = false;
    bool hasSeed = false;
    uint64_t seed = 0;
    int maxDepth = 100;  // bounces
    bool periodic = false;
    bool bounces = false;               // tag every photon of the map with its bounce count
    float thetaMin = 0, thetaMax = 90;  // incidence range, degrees
    FileLoc loc;                        // of the first BRDFLight parameter, for messages
};

// Whether the frame asked for a photon map instead of an image.
bool IsBrdfLightFrame(const Frame& frame);

// Reads and checks the options; reports every bad value and returns false if there was one.
// A missing texturename becomes the scene's name with ".pm".
bool ReadBrdfLightOptions(const Frame& frame, Diagnostics& diagnostics, BrdfLightOptions* out);

}  // namespace gonio
