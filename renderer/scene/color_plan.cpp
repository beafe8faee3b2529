#include "renderer/scene/color_plan.h"

#include <string>

#include "base/limits.h"
#include "renderer/scene/scene_spectra.h"
#include "spectral/named_spectra.h"
#include "spectral/patch_analysis.h"
#include "spectral/representations.h"
#include "spectral/spectral_error.h"

namespace gonio {
namespace {

Eigen::VectorXd Samples(const spectral::Spectrum& spectrum, const spectral::WavelengthGrid& grid) {
    const std::vector<double> samples = spectrum.Sample(grid);
    return Eigen::Map<const Eigen::VectorXd>(samples.data(), Eigen::Index(samples.size()));
}

ColorChoice ChooseBands(const Frame& frame, const SceneSpectra& spectra) {
    Eigen::VectorXd light = Eigen::VectorXd::Zero(spectra.grid.Count());
    for (const spectral::Spectrum& l : spectra.lights) light += Samples(l, spectra.grid);
    const std::vector<double> sum(light.data(), light.data() + light.size());
    const spectral::PatchScene scene = spectral::MakePatchScene(
        spectral::Spectrum::OnGrid(spectra.grid, sum), spectra.surfaces,
        spectral::NamedObserver("CIE1931"), spectral::NamedSpectrum("D65"), spectra.grid);
    const std::vector<int> edges = spectral::BandEdges(scene, frame.options.bands);
    return ColorChoice{spectral::BandColorSpace(spectra.grid, edges, light), {}};
}

// One block per light spectrum up to a scale: each light's spectrum is its block's light times
// lightScale[i] (0 for a black light, which takes the first block).
struct LightBlocks {
    std::vector<Eigen::VectorXd> lights;
    std::vector<int> blockOfLight;
    std::vector<double> lightScale;
};

LightBlocks GroupLightsBySpectrum(const SceneSpectra& spectra) {
    LightBlocks blocks;
    for (const spectral::Spectrum& l : spectra.lights) {
        const Eigen::VectorXd samples = Samples(l, spectra.grid);
        const double scale = samples.cwiseAbs().maxCoeff();
        int block = 0;
        if (scale > 0) {
            const Eigen::VectorXd shape = samples / scale;
            while (block < int(blocks.lights.size()) &&
                   (blocks.lights[size_t(block)] - shape).cwiseAbs().maxCoeff() > 1e-6)
                ++block;
            if (block == int(blocks.lights.size())) blocks.lights.push_back(shape);
        }
        blocks.blockOfLight.push_back(block);
        blocks.lightScale.push_back(scale);
    }
    if (blocks.lights.empty()) blocks.lights.push_back(Eigen::VectorXd::Ones(spectra.grid.Count()));
    return blocks;
}

ColorChoice ChooseSvd(const Frame& frame, const SceneSpectra& spectra) {
    const int k = frame.options.svdVectors;
    const LightBlocks grouped = GroupLightsBySpectrum(spectra);
    const size_t components = grouped.lights.size() * size_t(k);
    if (components > size_t(kMaxColorComponents))
        throw spectral::SpectralError("svd: " + std::to_string(k) + " vectors for each of " +
                                      std::to_string(grouped.lights.size()) +
                                      " light spectra make " + std::to_string(components) +
                                      " colour components, at most " +
                                      std::to_string(kMaxColorComponents));
    std::vector<Eigen::VectorXd> surfaces;
    for (const spectral::Spectrum& s : spectra.surfaces)
        surfaces.push_back(Samples(s, spectra.grid));
    std::vector<spectral::SvdBlock> blocks;
    for (const Eigen::VectorXd& light : grouped.lights)
        blocks.push_back({light, spectral::LightSvdBasis(light, surfaces, k)});
    ColorChoice choice{spectral::SvdColorSpace(spectra.grid, blocks), {}};
    for (size_t i = 0; i < grouped.blockOfLight.size(); ++i) {
        std::vector<float> colour(components, 0.0f);
        const size_t first = size_t(grouped.blockOfLight[i]) * size_t(k);
        for (size_t c = first; c < first + size_t(k); ++c) colour[c] = float(grouped.lightScale[i]);
        choice.lightColors.push_back(std::move(colour));
    }
    return choice;
}

}  // namespace

ColorChoice ChooseColorSpace(const Frame& frame) {
    SceneSpectra spectra = CollectSceneSpectra(frame);
    const std::vector<double> flat(size_t(spectra.grid.Count()), 1.0);
    if (spectra.surfaces.empty())
        spectra.surfaces.push_back(spectral::Spectrum::OnGrid(spectra.grid, flat));
    if (frame.options.svdVectors > 0) return ChooseSvd(frame, spectra);
    if (spectra.lights.empty())
        spectra.lights.push_back(spectral::Spectrum::OnGrid(spectra.grid, flat));
    return ChooseBands(frame, spectra);
}

}  // namespace gonio
