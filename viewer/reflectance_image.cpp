// One of the two files of the viewer that include OpenImageIO (the other writes exports).
#include "viewer/reflectance_image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <regex>

namespace gonio::viewer {

namespace {

struct SpectralChannel {
    int index;  // in the file
    double nm;
};

[[noreturn]] void Fail(const std::string& path, const std::string& why) {
    throw ViewerError(path + ": error: " + why);
}

std::vector<SpectralChannel> FindSpectralChannels(const OIIO::ImageSpec& spec) {
    std::vector<SpectralChannel> channels;
    for (int c = 0; c < spec.nchannels; ++c) {
        double nm = 0;
        if (ParseSpectralChannelName(spec.channel_name(c), &nm)) channels.push_back({c, nm});
    }
    std::sort(channels.begin(), channels.end(),
              [](const SpectralChannel& a, const SpectralChannel& b) { return a.nm < b.nm; });
    return channels;
}

std::vector<float> ReadAllChannels(OIIO::ImageInput& input, const OIIO::ImageSpec& spec,
                                   const std::string& path) {
    std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
    if (!input.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        Fail(path, "cannot read the pixels: " + input.geterror());
    return pixels;
}

// Copies the channels `indices` of every pixel, in that order, into a pixel-major array.
std::vector<float> GatherChannels(const std::vector<float>& pixels, int channelCount,
                                  const std::vector<int>& indices) {
    const size_t pixelCount = pixels.size() / channelCount;
    std::vector<float> result(pixelCount * indices.size());
    for (size_t p = 0; p < pixelCount; ++p)
        for (size_t k = 0; k < indices.size(); ++k)
            result[p * indices.size() + k] = pixels[p * channelCount + indices[k]];
    return result;
}

std::vector<int> PreviewChannels(const OIIO::ImageSpec& spec) {
    std::vector<int> indices;
    for (const char* name : {"R", "G", "B"}) {
        const int index = spec.channelindex(name);
        if (index < 0) return {};
        indices.push_back(index);
    }
    return indices;
}

}  // namespace

bool ParseSpectralChannelName(const std::string& name, double* nm) {
    // Fichet et al. 2021 §3.1: "S0." then the wavelength, its decimal point a comma, then a unit.
    static const std::regex kEmissive(R"(S0\.([0-9]+)(?:[,.]([0-9]+))?nm)");
    std::smatch match;
    if (!std::regex_match(name, match, kEmissive)) return false;
    const std::string number = match[1].str() + (match[2].matched ? "." + match[2].str() : "");
    *nm = std::stod(number);
    return true;
}

ReflectanceImage ReadReflectanceImage(const std::string& path) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) Fail(path, "cannot open the image: " + OIIO::geterror());
    if (std::string(input->format_name()) != "openexr")
        Fail(path, std::string("not an OpenEXR file (it is ") + input->format_name() +
                       "): the viewer reads the spectral EXR of Display \"openexr\" \"spectral\"");
    const OIIO::ImageSpec spec = input->spec();
    const std::vector<SpectralChannel> channels = FindSpectralChannels(spec);
    if (channels.size() < 3)
        Fail(path,
             "no spectral channels (S0.<wavelength>nm): render it with Option \"spectral\" "
             "\"basis\" \"sampled\" and Display \"" +
                 path + "\" \"openexr\" \"spectral\"");
    for (size_t k = 1; k < channels.size(); ++k)
        if (channels[k].nm == channels[k - 1].nm)
            Fail(path, "two spectral channels at " + std::to_string(channels[k].nm) + " nm");

    const std::vector<float> pixels = ReadAllChannels(*input, spec, path);
    ReflectanceImage image;
    image.path = path;
    image.width = spec.width;
    image.height = spec.height;
    std::vector<int> indices;
    for (const SpectralChannel& c : channels) {
        image.wavelengths.push_back(c.nm);
        indices.push_back(c.index);
    }
    image.spectra = GatherChannels(pixels, spec.nchannels, indices);
    if (!std::all_of(image.spectra.begin(), image.spectra.end(),
                     [](float v) { return std::isfinite(v); }))
        Fail(path, "a spectral sample is not a finite number");
    const std::vector<int> preview = PreviewChannels(spec);
    if (!preview.empty()) image.previewRgb = GatherChannels(pixels, spec.nchannels, preview);
    return image;
}

}  // namespace gonio::viewer
