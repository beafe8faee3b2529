#pragma once
// Option "spectral" "basis" "bands" (thesis §6.1.2): k bands whose edges follow the spectra the
// frame actually shows, its lights reflected by its surfaces. Those come after the option, so a
// frame that asks for bands is built twice: first sampled, to choose its bands from its own
// spectra, then with them (BuildScene, renderer/scene/scene_file.h).

#include <map>
#include <vector>

#include "renderer/scene/frame.h"

namespace gonio {

struct BandChoice {
    std::vector<int> edges;     // k + 1 sample indices, spectral::BandEdges
    std::vector<double> light;  // the frame's lights summed, on its samples: the band weights
};

// The bands of each frame that asks for them, by its world's ordinal (Frame::ordinal).
using BandPlan = std::map<int, BandChoice>;

// Chooses options.bands bands for a frame built sampled (options.colorFromSamples empty), as
// spectral::BandEdges does for the frame's lights (summed: the one-bounce energy is linear in the
// light) and the distinct colours of its shapes; a frame without lights takes the equal-energy
// light, one without shapes a white surface. Throws spectral::SpectralError for a light colour
// that cannot be read.
BandChoice ChooseBands(const Frame& frame);

}  // namespace gonio
