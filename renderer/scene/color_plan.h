#pragma once
// Option "spectral" "basis" "bands" and "svd" (thesis §6.1.2): colour spaces fitted to the
// spectra the frame actually shows, its lights reflected by its surfaces. Those come after the
// option, so such a frame is built twice: first sampled, to choose its colour space from its own
// spectra, then in it (BuildScene, renderer/scene/scene_file.h).

#include <map>
#include <vector>

#include "renderer/scene/frame.h"
#include "spectral/render_color_space.h"

namespace gonio {

struct ColorChoice {
    spectral::RenderColorSpace space;
    // "svd": for each of the frame's lights (Frame::lights' order), the "lightcolor" it is given
    // in `space`: its spectrum's scale in the components of its block, 0 elsewhere. Empty for
    // "bands", whose lights keep their colours.
    std::vector<std::vector<float>> lightColors;
};

// The colour space of each frame that asks for one fitted to it, by its world's ordinal
// (Frame::ordinal).
using ColorPlan = std::map<int, ColorChoice>;

// Chooses the colour space a frame built sampled (options.colorFromSamples empty) asks for, from
// its lights' "lightcolor" and the distinct colours of its shapes (scene_spectra.h); a frame
// without lights takes the equal-energy light, one without shapes a white surface.
// * "bands": options.bands bands as spectral::BandEdges chooses them for the lights summed (the
//   one-bounce energy is linear in the light), weighted by that sum.
// * "svd": options.svdVectors vectors per distinct light spectrum (lights whose spectra differ
//   only by a scale share one block), spectral::LightSvdBasis.
// Throws spectral::SpectralError for a light colour that cannot be read, or more components than
// a render carries.
ColorChoice ChooseColorSpace(const Frame& frame);

}  // namespace gonio
