#pragma once
// The spectra a sampled frame shows: the colours of its lights and of its surfaces, on its
// wavelengths. They choose the frame's bands or svd basis (color_plan.h) and are what `gonio
// spectral analyze` measures the representations on.

#include <string>
#include <vector>

#include "renderer/scene/frame.h"
#include "spectral/spectrum.h"

namespace gonio {

struct SceneSpectra {
    spectral::WavelengthGrid grid;
    std::vector<std::string> lightLabels;  // "shader handle"
    std::vector<spectral::Spectrum> lights;
    std::vector<spectral::Spectrum> surfaces;
};

// The grid of a frame's wavelengths; throws spectral::SpectralError when it has none (not
// spectral) or they are not evenly spaced.
spectral::WavelengthGrid FrameGrid(const Options& options);

// Each light's "lightcolor" as the scene gives it (a spectrum, RGB uplifted, or white), and the
// distinct Color of the frame's shapes and instances. Throws spectral::SpectralError (located)
// for a lightcolor that cannot be read.
SceneSpectra CollectSceneSpectra(const Frame& frame);

}  // namespace gonio
