#include "spectral/patch_analysis.h"

#include <algorithm>

#include "spectral/spectral_error.h"

namespace gonio::spectral {

namespace {

ErrorStats Compare(const Eigen::Matrix3Xd& got, const Eigen::Matrix3Xd& reference, const Xyz& white,
                   double scale) {
    ErrorStats stats;
    for (Eigen::Index c = 0; c < reference.cols(); ++c) {
        const double de = Ciede2000(XyzToLab(scale * reference.col(c), white),
                                    XyzToLab(scale * got.col(c), white));
        stats.mean += de;
        stats.max = std::max(stats.max, de);
    }
    stats.mean /= double(reference.cols());
    return stats;
}

}  // namespace

std::string RepresentationName(RepresentationKind kind, int k) {
    switch (kind) {
        case RepresentationKind::Rgb:
            return "rgb";
        case RepresentationKind::Bands:
            return "bands-" + std::to_string(k);
        case RepresentationKind::SvdExactDirect:
            return "svd-" + std::to_string(k) + " exact-direct";
        case RepresentationKind::SvdRendered:
            return "svd-" + std::to_string(k) + " rendered";
        case RepresentationKind::SvdEq69:
            return "svd-" + std::to_string(k) + " eq. 6.9";
    }
    return "?";
}

PatchScene MakePatchScene(const Spectrum& light, const std::vector<Spectrum>& reflectances,
                          const Observer& observer, const Spectrum& rgbIlluminant,
                          const WavelengthGrid& grid) {
    if (reflectances.empty()) throw SpectralError("a patch scene needs at least one surface");
    PatchScene scene;
    scene.observer = SampleObserver(observer, grid);
    scene.light = SampleSpectrum(light, grid);
    scene.rgbIlluminant = SampleSpectrum(rgbIlluminant, grid);
    scene.reflectances.resize(grid.Count(), Eigen::Index(reflectances.size()));
    for (size_t j = 0; j < reflectances.size(); ++j)
        scene.reflectances.col(Eigen::Index(j)) = SampleSpectrum(reflectances[j], grid);
    return scene;
}

std::vector<PatchScene> TestColourScenes(const std::vector<std::string>& lights) {
    const Observer observer = NamedObserver("CIE1931");
    const Spectrum d65 = NamedSpectrum("D65");
    std::vector<Spectrum> surfaces;
    for (int i = 1; i <= 14; ++i)
        surfaces.push_back(NamedSpectrum((i < 10 ? "TCS0" : "TCS") + std::to_string(i)));
    std::vector<PatchScene> scenes;
    for (const std::string& light : lights)
        scenes.push_back(MakePatchScene(LookupSpectrum(light), surfaces, observer, d65));
    return scenes;
}

int MaxK(const PatchScene& scene, RepresentationKind kind) {
    switch (kind) {
        case RepresentationKind::Rgb:
            return 3;
        case RepresentationKind::Bands:
            return int(scene.light.size());
        case RepresentationKind::SvdExactDirect:
        case RepresentationKind::SvdEq69:
            return int(std::min(scene.reflectances.rows(), scene.reflectances.cols()));
        case RepresentationKind::SvdRendered:  // completed to the samples (LightSvdBasis)
            return int(scene.light.size());
    }
    return 0;
}

RepresentationError EvaluateRepresentation(const PatchScene& scene, RepresentationKind kind,
                                           int k) {
    BounceColours colours;
    switch (kind) {
        case RepresentationKind::Rgb:
            colours = RgbColours(scene);
            k = 3;
            break;
        case RepresentationKind::Bands:
            colours = BandColours(scene, k);
            break;
        case RepresentationKind::SvdExactDirect:
            colours = SvdExactDirectColours(scene, k);
            break;
        case RepresentationKind::SvdRendered:
            colours = SvdRenderedColours(scene, k);
            break;
        case RepresentationKind::SvdEq69:
            colours = SvdEq69Colours(scene, k);
            break;
    }
    const BounceColours reference = ReferenceColours(scene);
    const Xyz lightXyz = Tristimulus(scene.light, scene.observer);
    const double scale = 100 / lightXyz.y();
    const Xyz white = lightXyz * scale;
    RepresentationError error{kind, k, {}, {}};
    error.oneBounce = Compare(colours.oneBounce, reference.oneBounce, white, scale);
    error.twoBounce = Compare(colours.twoBounce, reference.twoBounce, white, scale);
    return error;
}

int SmallestK(const std::vector<PatchScene>& scenes, RepresentationKind kind, double targetDe) {
    if (scenes.empty()) return -1;
    int most = MaxK(scenes.front(), kind);
    for (const PatchScene& scene : scenes) most = std::min(most, MaxK(scene, kind));
    const int first = kind == RepresentationKind::Rgb ? 3 : 1;
    for (int k = first; k <= most; ++k) {
        bool met = true;
        for (const PatchScene& scene : scenes) {
            const RepresentationError error = EvaluateRepresentation(scene, kind, k);
            met = met && error.oneBounce.mean <= targetDe && error.twoBounce.mean <= targetDe;
            if (!met) break;
        }
        if (met) return k;
    }
    return -1;
}

}  // namespace gonio::spectral
