#include "viewer/illuminants.h"

#include <algorithm>

#include "spectral/named_spectra.h"
#include "spectral/spectral_error.h"
#include "viewer/reflectance_image.h"

namespace gonio::viewer {

namespace {

bool IsIlluminantName(const std::string& name) {
    return name.rfind("TCS", 0) != 0 && name.rfind("CIE", 0) != 0;
}

// IEC 61966-2-1: the luminance of linear sRGB.
double Luminance(const Eigen::Vector3d& rgb) {
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

}  // namespace

std::vector<std::string> IlluminantNames() {
    std::vector<std::string> names;
    for (const std::string& name : spectral::NamedSpectrumNames())
        if (IsIlluminantName(name)) names.push_back(name);
    return names;
}

nlohmann::json IlluminantPreset(const std::string& name, const std::vector<double>& wavelengths,
                                const Eigen::Matrix3Xd& cieToRgb) {
    const std::vector<std::string> names = IlluminantNames();
    const auto found = std::find_if(names.begin(), names.end(), [&](const std::string& n) {
        return std::equal(n.begin(), n.end(), name.begin(), name.end(),
                          [](char a, char b) { return std::tolower(a) == std::tolower(b); });
    });
    if (found == names.end()) throw ViewerError("no illuminant named \"" + name + "\"");
    Eigen::VectorXd raw(wavelengths.size());
    try {
        const spectral::Spectrum table = spectral::NamedSpectrum(*found);
        for (size_t i = 0; i < wavelengths.size(); ++i)
            raw[i] =
                table.Covers(wavelengths[i], wavelengths[i]) ? table.Evaluate(wavelengths[i]) : 0.0;
    } catch (const spectral::SpectralError& e) {
        throw ViewerError(e.what());
    }
    const double y = Luminance(cieToRgb * raw);
    const double scale = y > 0 ? 1 / y : 1;
    const Eigen::VectorXd values = raw * scale;
    return {{"name", *found},
            {"raw", std::vector<double>(raw.begin(), raw.end())},
            {"values", std::vector<double>(values.begin(), values.end())},
            {"scale", scale}};
}

}  // namespace gonio::viewer
