#pragma once
// Measures the colour representations of representations.h against the 81-sample reference:
// CIEDE2000 between what a representation computes and the reference, in CIELAB relative to the
// light's white (its XYZ, Y = 100), over the one-bounce and the two-bounce paths.

#include <string>
#include <vector>

#include "spectral/named_spectra.h"
#include "spectral/representations.h"

namespace gonio::spectral {

enum class RepresentationKind { Rgb, Bands, SvdExactDirect, SvdRendered, SvdEq69 };

struct ErrorStats {
    double mean = 0;
    double max = 0;
};

struct RepresentationError {
    RepresentationKind kind;
    int k = 3;  // values per colour (3 for rgb)
    ErrorStats oneBounce;
    ErrorStats twoBounce;
};

// "rgb", "bands-16", "svd-6 exact-direct", "svd-6 rendered", "svd-6 eq. 6.9".
std::string RepresentationName(RepresentationKind kind, int k);

// Resamples everything onto `grid` (each spectrum by its own interpolation) and builds the scene.
// Throws SpectralError when a spectrum does not cover the grid.
PatchScene MakePatchScene(const Spectrum& light, const std::vector<Spectrum>& reflectances,
                          const Observer& observer, const Spectrum& rgbIlluminant,
                          const WavelengthGrid& grid = ReferenceGrid());

// The TCS01..TCS14 of ref/CIE-TCS.sp (TCS15's table is zero outside 380-780 nm; the CIE 13.3
// colour rendering index uses 1-14) under each named light, with the CIE 1931 observer.
std::vector<PatchScene> TestColourScenes(const std::vector<std::string>& lights);

RepresentationError EvaluateRepresentation(const PatchScene& scene, RepresentationKind kind, int k);
// The largest k a representation accepts for this scene (rgb: 3).
int MaxK(const PatchScene& scene, RepresentationKind kind);

// The smallest k for which both the one- and the two-bounce mean ΔE2000 are ≤ targetDe in every
// scene, or -1 if no k up to MaxK meets it.
int SmallestK(const std::vector<PatchScene>& scenes, RepresentationKind kind, double targetDe);

}  // namespace gonio::spectral
