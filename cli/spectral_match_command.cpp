// gonio spectral match LIGHT --rgb R G B [--grid 380 780 5] [--brightness euclidean] [-o OUT]:
// the spectral viewer's "Match RGB" (thesis §6.2.2) on the command line. The light (a named
// spectrum or a file) changes as little as possible (L2) to reach the wanted RGB, linear sRGB
// of CIE 1931 XYZ (the thesis's M X, D65 white), staying non-negative; by default the target
// takes the light's brightness (the thesis's normalisation). Prints the Newton steps, the KKT
// residuals, the relative change and the matched light's xy; writes it as a cspec file with -o.
// An RGB no non-negative light has is an error (exit 1) naming the certificate.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "spectral/colorimetry.h"
#include "spectral/light_match.h"
#include "spectral/named_spectra.h"
#include "spectral/number_format.h"
#include "spectral/spectral_error.h"
#include "spectral/spectrum_file.h"
#include "spectral_cli.h"

namespace gonio {
namespace {

using namespace gonio::spectral;

struct MatchRequest {
    std::string light;
    std::vector<double> rgb;
    std::vector<double> grid{380, 780, 5};
    std::string brightness = "euclidean";
    std::string out;
};

// The target as the matcher gets it: the given RGB, or its direction at the light's brightness.
Eigen::Vector3d MatchTarget(const MatchRequest& request, const Eigen::VectorXd& light,
                            const Eigen::Matrix3Xd& m) {
    const Eigen::Vector3d rgb(request.rgb[0], request.rgb[1], request.rgb[2]);
    if (request.brightness == "as-given") return rgb;
    const Brightness brightness =
        request.brightness == "largest" ? Brightness::Largest : Brightness::Euclidean;
    return NormalisedTarget(light, m, rgb, brightness);
}

Eigen::Vector2d Xy(const Eigen::VectorXd& spectrum, const SampledObserver& observer) {
    return Chromaticity(Tristimulus(spectrum, observer));
}

void RunMatch(const MatchRequest& request) {
    const WavelengthGrid grid =
        WavelengthGrid::Make(request.grid[0], request.grid[1], request.grid[2]);
    const Eigen::VectorXd light = SampleSpectrum(LookupSpectrum(request.light), grid);
    const Eigen::Matrix3Xd m = CieRgbMatrix(grid);
    const Eigen::Vector3d target = MatchTarget(request, light, m);
    const LightMatch match = MatchLightToRgb(light, m, target);
    if (!match.reachable) throw SpectralError(match.message);
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), grid);
    const Eigen::Vector2d before = Xy(light, observer);
    const Eigen::Vector2d after = Xy(match.spectrum, observer);
    std::printf("%s matched to linear sRGB %g %g %g (%s brightness: %.6g %.6g %.6g)\n",
                request.light.c_str(), request.rgb[0], request.rgb[1], request.rgb[2],
                request.brightness.c_str(), target.x(), target.y(), target.z());
    std::printf("  newton steps     %d\n", match.newtonSteps);
    std::printf("  rgb residual     %.3g (|M s - t| / |t|)\n", match.rgbResidual);
    std::printf("  complementarity  %.3g\n", match.complementarity);
    std::printf("  relative change  %.2f%% (|s' - s| / |s|)\n", 100 * match.relativeChange);
    std::printf("  xy               %.5f %.5f (was %.5f %.5f)\n", after.x(), after.y(), before.x(),
                before.y());
    if (!match.message.empty() && match.rgbResidual > 1e-9)
        std::printf("  note             %s\n", match.message.c_str());
    if (request.out.empty()) return;
    const std::vector<double> values(match.spectrum.data(), match.spectrum.data() + grid.Count());
    const std::string comment = request.light + " matched to linear sRGB " +
                                ShortestDecimal(request.rgb[0]) + " " +
                                ShortestDecimal(request.rgb[1]) + " " +
                                ShortestDecimal(request.rgb[2]) + " by gonio spectral match";
    WriteSpectrumFile(request.out, Spectrum::OnGrid(grid, values), comment);
    std::printf("  wrote            %s\n", request.out.c_str());
}

}  // namespace

void AddSpectralMatchCommand(CLI::App& spectral, int* exitCode) {
    CLI::App* match = spectral.add_subcommand(
        "match", "Change a light as little as possible (L2) to reach an RGB (thesis §6.2.2)");
    auto request = std::make_shared<MatchRequest>();
    match->add_option("light", request->light, "a named spectrum (D65, F11, ...) or a file")
        ->required();
    match->add_option("--rgb", request->rgb, "the wanted linear sRGB (CIE 1931, D65 white)")
        ->required()
        ->expected(3);
    match->add_option("--grid", request->grid, "START END STEP in nm")
        ->expected(3)
        ->capture_default_str();
    match
        ->add_option("--brightness", request->brightness,
                     "euclidean: the target at the light's |RGB| (thesis §6.2.2); largest: "
                     "their largest components equal; as-given: the RGB as it is")
        ->check(CLI::IsMember({"euclidean", "largest", "as-given"}))
        ->capture_default_str();
    match->add_option("-o,--output", request->out, "write the matched light as a cspec file");
    match->callback(
        [request, exitCode] { RunSpectralGuarded(exitCode, [&] { RunMatch(*request); }); });
}

}  // namespace gonio
