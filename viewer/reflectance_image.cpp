#include "viewer/reflectance_image.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <regex>
#include <stdexcept>

#include "imageio/oiio_plugin.h"
#include "spectral/image_basis_layout.h"
#include "spectral/spectral_error.h"

namespace gonio::viewer {

namespace {

struct SpectralChannel {
    int index;  // in the file
    double nm;
};

[[noreturn]] void Fail(const std::string& path, const std::string& why) {
    throw ViewerError(path + ": error: " + why);
}

std::vector<SpectralChannel> FindSpectralChannels(const ImageFileSpec& spec) {
    std::vector<SpectralChannel> channels;
    for (int c = 0; c < spec.Channels(); ++c) {
        double nm = 0;
        if (ParseSpectralChannelName(spec.channelNames[size_t(c)], &nm))
            channels.push_back({c, nm});
    }
    std::sort(channels.begin(), channels.end(),
              [](const SpectralChannel& a, const SpectralChannel& b) { return a.nm < b.nm; });
    return channels;
}

// OpenEXR files begin with the magic number 20000630 (little-endian; OpenEXR file layout).
bool IsOpenExr(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    unsigned char magic[4] = {0, 0, 0, 0};
    file.read(reinterpret_cast<char*>(magic), 4);
    return file && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

// Every channel, through the OpenImageIO plugin (loaded now, for this image).
ImageFileContents ReadAllChannels(const std::string& path) {
    std::string error;
    ImageFileContents contents;
    try {
        contents = LoadOiioPlugin("the reflectance image \"" + path + "\"").ReadImage(path, &error);
    } catch (const std::runtime_error& e) {
        Fail(path, e.what());
    }
    if (!error.empty()) Fail(path, "cannot read the image: " + error);
    return contents;
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

std::vector<int> PreviewChannels(const ImageFileSpec& spec) {
    std::vector<int> indices;
    for (const char* name : {"R", "G", "B"}) {
        const auto found = std::find(spec.channelNames.begin(), spec.channelNames.end(), name);
        if (found == spec.channelNames.end()) return {};
        indices.push_back(int(found - spec.channelNames.begin()));
    }
    return indices;
}

// The channels basis.00 … basis.(k−1) by index; empty when the file has none.
std::vector<int> FindBasisChannels(const std::string& path, const ImageFileSpec& spec) {
    std::vector<std::pair<int, int>> found;  // (basis index, channel)
    for (int c = 0; c < spec.Channels(); ++c) {
        int index = 0;
        if (spectral::ParseBasisChannelName(spec.channelNames[size_t(c)], &index))
            found.push_back({index, c});
    }
    std::sort(found.begin(), found.end());
    std::vector<int> channels;
    for (size_t i = 0; i < found.size(); ++i) {
        if (found[i].first != int(i))
            Fail(path, "the basis channels are not basis.00 to basis." +
                           std::to_string(found.size() - 1) + " (basis." +
                           std::to_string(found[i].first) + " is out of place)");
        channels.push_back(found[i].second);
    }
    return channels;
}

bool AllFinite(const std::vector<float>& values) {
    return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

// An image in a basis: its coefficients, the basis from the header, and the spectra it codes.
void ReadBasisCoding(const ImageFileContents& contents, const std::vector<int>& channels,
                     ReflectanceImage* image) {
    spectral::StoredBasis stored;
    try {
        stored = spectral::ReadBasisHeader(contents.spec.attributes, int(channels.size()));
    } catch (const spectral::SpectralError& e) {
        Fail(image->path, std::string("a bad basis header: ") + e.what());
    }
    image->wavelengths = stored.wavelengths;
    image->basis = stored.vectors;
    image->coefficients = GatherChannels(contents.pixels, contents.spec.Channels(), channels);
    if (!AllFinite(image->coefficients)) Fail(image->path, "a basis coefficient is not finite");
    const int n = image->SampleCount(), k = int(channels.size());
    const size_t pixels = image->coefficients.size() / size_t(k);
    image->spectra.resize(pixels * size_t(n));
    const Eigen::MatrixXf basis = stored.vectors.cast<float>();
    for (size_t p = 0; p < pixels; ++p)
        Eigen::Map<Eigen::VectorXf>(&image->spectra[p * size_t(n)], n) =
            basis * Eigen::Map<const Eigen::VectorXf>(&image->coefficients[p * size_t(k)], k);
}

// An image of samples: the channels S0.<λ>nm in increasing wavelength.
void ReadSampleChannels(const ImageFileContents& contents, ReflectanceImage* image) {
    const std::string& path = image->path;
    const std::vector<SpectralChannel> channels = FindSpectralChannels(contents.spec);
    if (channels.size() < 3)
        Fail(path,
             "no spectral channels (S0.<wavelength>nm): render it with Option \"spectral\" "
             "\"basis\" \"sampled\" and Display \"" +
                 path + "\" \"openexr\" \"spectral\"");
    for (size_t k = 1; k < channels.size(); ++k)
        if (channels[k].nm == channels[k - 1].nm)
            Fail(path, "two spectral channels at " + std::to_string(channels[k].nm) + " nm");
    std::vector<int> indices;
    for (const SpectralChannel& c : channels) {
        image->wavelengths.push_back(c.nm);
        indices.push_back(c.index);
    }
    image->spectra = GatherChannels(contents.pixels, contents.spec.Channels(), indices);
    if (!AllFinite(image->spectra)) Fail(path, "a spectral sample is not a finite number");
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
    if (!std::ifstream(path)) Fail(path, "cannot open the image");
    if (!IsOpenExr(path))
        Fail(path,
             "not an OpenEXR file: the viewer reads the spectral EXR of Display \"openexr\" "
             "\"spectral\"");
    const ImageFileContents contents = ReadAllChannels(path);
    const ImageFileSpec& spec = contents.spec;
    ReflectanceImage image;
    image.path = path;
    image.width = spec.width;
    image.height = spec.height;
    const std::vector<int> basisChannels = FindBasisChannels(path, spec);
    if (basisChannels.empty())
        ReadSampleChannels(contents, &image);
    else
        ReadBasisCoding(contents, basisChannels, &image);
    const std::vector<float>& pixels = contents.pixels;
    const std::vector<int> preview = PreviewChannels(spec);
    if (!preview.empty()) image.previewRgb = GatherChannels(pixels, spec.Channels(), preview);
    return image;
}

}  // namespace gonio::viewer
