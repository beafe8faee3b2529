#include "renderer/scene/scene_colors.h"

#include "spectral/named_spectra.h"
#include "spectral/render_color_space.h"
#include "spectral/spectral_error.h"

namespace gonio {

bool SceneColorsFromNumbers(const Options& options, const std::vector<float>& values, int count,
                            std::vector<float>* out, std::string* error) {
    const int n = options.colorComponents;
    if (int(values.size()) == n * count) {
        *out = values;
        return true;
    }
    const bool spectral = !options.wavelengths.empty();
    if (!spectral || int(values.size()) != 3 * count) {
        *error = "expected " + std::to_string(n * count) + " numbers" +
                 (spectral ? " (or " + std::to_string(3 * count) + " for RGB)" : "") + ", got " +
                 std::to_string(values.size());
        return false;
    }
    out->assign(size_t(n) * count, 0.0f);
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < n; ++i)
                (*out)[size_t(k) * n + i] +=
                    values[3 * size_t(k) + c] * options.colorFromRgb[size_t(c) * n + i];
    return true;
}

namespace {

// Under "bands" and "svd", the components of Options::colorFromSamples; else the samples.
std::vector<float> ComponentsOfSamples(const Options& options, std::vector<float> samples) {
    if (options.colorFromSamples.empty()) return samples;
    const size_t n = samples.size(), k = options.colorFromSamples.size() / n;
    std::vector<float> components(k, 0.0f);
    for (size_t b = 0; b < k; ++b)
        for (size_t i = 0; i < n; ++i)
            components[b] += options.colorFromSamples[b * n + i] * samples[i];
    return components;
}

}  // namespace

bool SceneColorFromSpectrum(const Options& options, const std::string& nameOrFile,
                            std::vector<float>* out, std::string* error) {
    if (options.spectraAsRgb) {
        try {
            const Eigen::Vector3d rgb = spectral::DisplayRgb(spectral::LookupSpectrum(nameOrFile));
            *out = {float(rgb[0]), float(rgb[1]), float(rgb[2])};
            return true;
        } catch (const spectral::SpectralError& e) {
            *error = e.what();
            return false;
        }
    }
    if (options.wavelengths.empty()) {
        *error = "a spectrum (\"" + nameOrFile +
                 "\") needs Option \"spectral\" \"basis\" "
                 "\"sampled\" (or \"bands\" or \"svd\") before WorldBegin";
        return false;
    }
    try {
        const spectral::Spectrum spectrum = spectral::LookupSpectrum(nameOrFile);
        std::vector<float> samples;
        for (double nm : options.wavelengths) samples.push_back(float(spectrum.Evaluate(nm)));
        *out = ComponentsOfSamples(options, samples);
        return true;
    } catch (const spectral::SpectralError& e) {
        *error = e.what();
        return false;
    }
}

bool SceneColorsFromParam(const Options& options, const Param& param, int count,
                          std::vector<float>* out, std::string* error) {
    if (!param.isString)
        return SceneColorsFromNumbers(
            options, std::vector<float>(param.numbers.begin(), param.numbers.end()), count, out,
            error);
    if (param.strings.size() != 1) {
        *error = "expected one spectrum name or file";
        return false;
    }
    return SceneColorFromSpectrum(options, param.strings[0], out, error);
}

}  // namespace gonio
