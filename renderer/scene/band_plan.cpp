#include "renderer/scene/band_plan.h"

#include "renderer/scene/scene_spectra.h"
#include "spectral/named_spectra.h"
#include "spectral/patch_analysis.h"
#include "spectral/representations.h"

namespace gonio {

BandChoice ChooseBands(const Frame& frame) {
    SceneSpectra spectra = CollectSceneSpectra(frame);
    const std::vector<double> flat(size_t(spectra.grid.Count()), 1.0);
    if (spectra.lights.empty())
        spectra.lights.push_back(spectral::Spectrum::OnGrid(spectra.grid, flat));
    if (spectra.surfaces.empty())
        spectra.surfaces.push_back(spectral::Spectrum::OnGrid(spectra.grid, flat));
    std::vector<double> light(flat.size(), 0.0);
    for (const spectral::Spectrum& l : spectra.lights) {
        const std::vector<double> samples = l.Sample(spectra.grid);
        for (size_t i = 0; i < light.size(); ++i) light[i] += samples[i];
    }
    const spectral::PatchScene scene = spectral::MakePatchScene(
        spectral::Spectrum::OnGrid(spectra.grid, light), spectra.surfaces,
        spectral::NamedObserver("CIE1931"), spectral::NamedSpectrum("D65"), spectra.grid);
    return BandChoice{spectral::BandEdges(scene, frame.options.bands), light};
}

}  // namespace gonio
