#include "viewer/light_files.h"

#include "spectral/spectral_error.h"
#include "spectral/spectrum_file.h"
#include "viewer/json_fields.h"
#include "viewer/reflectance_image.h"

namespace gonio::viewer {

namespace {

std::vector<std::string> SplitLines(const std::string& text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        start = end + 1;
    }
    return lines;
}

// A light emits nothing where its file has no data: the thesis's files span 400-700 nm, the
// images 380-780 nm.
std::vector<double> LightAt(const spectral::Spectrum& light, const std::vector<double>& nm,
                            bool* covered) {
    std::vector<double> values;
    *covered = true;
    for (double w : nm) {
        const bool inside = light.Covers(w, w);
        *covered = *covered && inside;
        values.push_back(inside ? light.Evaluate(w) : 0.0);
    }
    return values;
}

spectral::Spectrum CurveOf(const nlohmann::json& request) {
    const std::vector<double> wavelengths = NumberArray(request, "wavelengths", 2);
    const std::vector<double> values = NumberArray(request, "values", 2);
    if (wavelengths.size() != values.size())
        throw ViewerError("\"wavelengths\" and \"values\" differ in length");
    spectral::Spectrum curve(wavelengths, values, spectral::Interpolation::CatmullRom);
    curve.SetPhantoms(OptionalNumber(request, "before", values.front()),
                      OptionalNumber(request, "after", values.back()));
    return curve;
}

spectral::Spectrum SamplesOf(const nlohmann::json& request) {
    return spectral::Spectrum::Regular(Number(request, "start"), Number(request, "step"),
                                       NumberArray(request, "values", 2));
}

}  // namespace

nlohmann::json LoadLightFile(const std::string& text, const std::string& name,
                             const std::vector<double>& imageWavelengths) {
    spectral::Spectrum light;
    try {
        light = spectral::ParseSpectrumFile(SplitLines(text), name);
    } catch (const spectral::SpectralError& e) {
        throw ViewerError(e.what());
    }
    const bool curve = light.GetInterpolation() == spectral::Interpolation::CatmullRom;
    nlohmann::json answer = {{"kind", curve ? "curve" : "samples"},
                             {"wavelengths", light.Wavelengths()},
                             {"values", light.Values()}};
    if (curve) {
        answer["before"] = light.PhantomBefore();
        answer["after"] = light.PhantomAfter();
    }
    bool covered = true;
    answer["atImage"] = LightAt(light, imageWavelengths, &covered);
    if (!covered)
        answer["note"] = name + " covers " + std::to_string(int(light.MinWavelength())) + "-" +
                         std::to_string(int(light.MaxWavelength())) +
                         " nm only: the light is 0 at the image's other wavelengths";
    return answer;
}

std::string SaveLightFile(const nlohmann::json& request) {
    const std::string format = String(request, "format");
    if (format != "cspec" && format != "curve")
        throw ViewerError("unknown light format \"" + format + "\": expected cspec or curve");
    try {
        const spectral::Spectrum light = format == "curve" ? CurveOf(request) : SamplesOf(request);
        return spectral::FormatSpectrumFile(light, "saved by gonio view");
    } catch (const spectral::SpectralError& e) {
        throw ViewerError(e.what());
    }
}

}  // namespace gonio::viewer
