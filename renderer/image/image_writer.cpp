// The imaging pipeline of a Display; the file itself is written by imageio/'s drivers.
#include "renderer/image/image_writer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <type_traits>

#include "imageio/image_formats.h"
#include "renderer/image/basis_display.h"

namespace gonio {

namespace {

namespace fs = std::filesystem;

enum class ChannelKind { Colour, Alpha, Depth, Aov };

struct OutputChannel {
    int source;  // index into the image's channels
    ChannelKind kind;
    std::string name;  // as written to the file
};

std::string Lowercase(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The format a Display writes; see image_writer.h for the rules. Only a name whose extension
// no built-in driver knows asks OpenImageIO (loading its plugin), and only when the type
// leaves the choice to the extension.
std::string ChooseFormat(const DisplaySpec& display, Diagnostics& diagnostics) {
    std::string type = Lowercase(display.type);
    if (type == "openexr" || type == "exr") return "openexr";
    if (type == "png") return "png";
    if (type == "zfile") return "zfile";
    if (type == "shadow") return "tiff";
    const std::string byExtension = FormatForFileName(display.name);
    if (type == "framebuffer" || type == "zframebuffer")
        diagnostics.NoteOnce("display-framebuffer", display.loc,
                             "Display type \"" + display.type +
                                 "\": gonio has no window to show images in; writing the file \"" +
                                 display.name + "\" instead");
    if (type == "file" || type == "tiff" || type == "framebuffer" || type == "zframebuffer")
        return byExtension.empty() ? "tiff" : byExtension;
    diagnostics.WarningOnce(
        "display-type-" + type, display.loc,
        "unknown Display type \"" + display.type + "\"; writing " +
            (byExtension.empty()
                 ? std::string("TIFF")
                 : "the format of the extension " + fs::path(display.name).extension().string()));
    return byExtension.empty() ? "tiff" : byExtension;
}

// Formats whose OpenImageIO writer keeps float pixels (others convert them to 8 bit).
bool FormatHoldsFloat(const std::string& format, const std::string& fileName) {
    static const std::set<std::string> kFloatFormats = {"openexr", "tiff", "hdr", "fits", "zfile"};
    if (format == "pnm") return Lowercase(fs::path(fileName).extension().string()) == ".pfm";
    return kFloatFormats.count(format) > 0;
}

bool IsStandardMode(const std::string& mode) {
    static const std::set<std::string> kModes = {"rgb", "rgba", "rgbz", "rgbaz", "a", "z", "az"};
    return kModes.count(mode) > 0;
}

int FindChannel(const std::vector<std::string>& names, const std::string& name) {
    auto found = std::find(names.begin(), names.end(), name);
    return found == names.end() ? -1 : int(found - names.begin());
}

std::vector<OutputChannel> SelectOutputChannels(const std::string& mode,
                                                const std::vector<std::string>& names,
                                                std::string& error) {
    if (mode == "spectral") {  // the RGB preview and alpha, then the spectrum (WriteDisplay)
        std::vector<OutputChannel> channels = SelectOutputChannels("rgba", names, error);
        const std::vector<OutputChannel> spectrum = SelectOutputChannels("Ci", names, error);
        if (channels.empty() || spectrum.empty()) return {};
        channels.insert(channels.end(), spectrum.begin(), spectrum.end());
        return channels;
    }
    std::vector<OutputChannel> channels;
    if (IsStandardMode(mode)) {
        for (char letter : mode) {
            if (letter == 'g' || letter == 'b') continue;  // taken with 'r'
            std::vector<std::pair<std::string, ChannelKind>> wanted;
            if (letter == 'r')
                wanted = {{"r", ChannelKind::Colour},
                          {"g", ChannelKind::Colour},
                          {"b", ChannelKind::Colour}};
            else if (letter == 'a')
                wanted = {{"a", ChannelKind::Alpha}};
            else
                wanted = {{"z", ChannelKind::Depth}};
            for (const auto& [name, kind] : wanted) {
                int source = FindChannel(names, name);
                if (source < 0) {
                    error = "Display mode \"" + mode + "\" needs the channel \"" + name +
                            "\", which the renderer did not produce";
                    return {};
                }
                channels.push_back({source, kind, std::string(1, char(std::toupper(name[0])))});
            }
        }
        return channels;
    }
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == mode || names[i].rfind(mode + ".", 0) == 0)
            channels.push_back({int(i), ChannelKind::Aov, names[i]});
    if (channels.empty())
        error = "Display mode \"" + mode +
                "\" is neither rgb, rgba, rgbz, rgbaz, a, z, az nor an output the renderer "
                "produced";
    return channels;
}

// A well-mixed 32-bit hash (the finaliser of MurmurHash3) of a pixel and channel, so that the
// dither of a pixel is fixed whatever the thread count or write order.
uint32_t HashPixel(int x, int y, int channel) {
    uint32_t h =
        uint32_t(x) * 0x9E3779B1u ^ uint32_t(y) * 0x85EBCA77u ^ uint32_t(channel) * 0xC2B2AE3Du;
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return h;
}

struct PixelData {
    PixelType type;  // of `bytes`
    std::vector<unsigned char> bytes;
};

// Whether the integer codes of `channels` need 16 bits.
bool NeedsSixteenBits(const std::vector<OutputChannel>& channels, const Quantization& colour,
                      const Quantization& depth) {
    for (const OutputChannel& channel : channels) {
        const Quantization& q = channel.kind == ChannelKind::Depth ? depth : colour;
        if (std::max(q.one, q.max) > 255) return true;
    }
    return false;
}

// Runs the imaging pipeline on every output value into `bytes` as T: exposed colour for a float
// file (T = float), the quantized codes clamped to [0, largest] for an integer one (Quantize
// ranges may reach below 0 or above the type: RISpec's example is -1024..3071). Straight into
// the file's type, as a float copy of a large frame would be most of a render's memory.
template <class T>
void StorePixels(const Image& image, const std::vector<OutputChannel>& channels,
                 const Exposure& exposure, const Quantization& colour, const Quantization& depth,
                 float largest, std::vector<unsigned char>& bytes) {
    constexpr bool kFloat = std::is_same_v<T, float>;
    const int n = int(channels.size());
    bytes.resize(size_t(image.width) * image.height * n * sizeof(T));
    T* const values = reinterpret_cast<T*>(bytes.data());
    const auto storeRow = [&](int y) {
        for (int x = 0; x < image.width; ++x) {
            const float* in = image.At(x, y);
            T* out = &values[(size_t(y) * image.width + x) * n];
            for (int c = 0; c < n; ++c) {
                const OutputChannel& channel = channels[c];
                float v = in[channel.source];
                if (channel.kind == ChannelKind::Colour) v = ApplyExposure(v, exposure);
                if constexpr (kFloat) {
                    out[c] = v;
                } else {
                    const Quantization& q = channel.kind == ChannelKind::Depth ? depth : colour;
                    const float code =
                        float(QuantizeValue(v, q, image.xorigin + x, image.yorigin + y, c));
                    out[c] = T(std::min(std::max(code, 0.0f), largest));
                }
            }
        }
    };
    // Rows side by side (the frame's last serial step otherwise), but a small frame, an empty
    // one, on this thread: a parallel loop would start oneTBB's workers for nothing.
    constexpr size_t kParallelPixels = 64 * 64;
    if (size_t(image.width) * image.height >= kParallelPixels)
        tbb::parallel_for(0, image.height, storeRow);
    else
        for (int y = 0; y < image.height; ++y) storeRow(y);
}

PixelData ComputePixels(const Image& image, const std::vector<OutputChannel>& channels,
                        const Exposure& exposure, const Quantization& colour,
                        const Quantization& depth, bool writeFloat) {
    PixelData data;
    if (writeFloat) {
        data.type = PixelType::Float;  // the driver converts to half where asked
        StorePixels<float>(image, channels, exposure, colour, depth, 0, data.bytes);
    } else if (NeedsSixteenBits(channels, colour, depth)) {
        data.type = PixelType::UInt16;
        StorePixels<uint16_t>(image, channels, exposure, colour, depth, 65535.0f, data.bytes);
    } else {
        data.type = PixelType::UInt8;
        StorePixels<uint8_t>(image, channels, exposure, colour, depth, 255.0f, data.bytes);
    }
    return data;
}

// How the pixels are stored: float (half on request in OpenEXR) or integer codes.
struct StorageChoice {
    bool isFloat = false;
    bool half = false;
    Quantization colour, depth;
};

StorageChoice ChooseStorage(const DisplaySpec& display, const std::string& format,
                            const std::vector<OutputChannel>& channels, const Quantization& colour,
                            const Quantization& depth, Diagnostics& diagnostics) {
    StorageChoice type;
    type.colour = colour;
    type.depth = depth;
    bool wantFloat = format == "openexr";
    for (const OutputChannel& channel : channels) {
        const Quantization& q = channel.kind == ChannelKind::Depth ? depth : colour;
        if (channel.kind == ChannelKind::Aov || q.IsFloat()) wantFloat = true;
    }
    type.isFloat = wantFloat;
    if (wantFloat && !FormatHoldsFloat(format, display.name)) {
        diagnostics.WarningOnce("display-float-" + format, display.loc,
                                "the " + format + " format cannot hold float pixels; writing \"" +
                                    display.name + "\" with integer pixels instead");
        type.isFloat = false;
        type.colour = type.depth = Quantization{65535, 0, 65535, 0.5f};
    }
    type.half = type.isFloat && format == "openexr" &&
                display.params.GetString("exrpixeltype", "float") == "half";
    return type;
}

ImageFileSpec MakeFileSpec(const Image& image, const std::vector<OutputChannel>& channels,
                           PixelType fileType, const ParamDict& params) {
    ImageFileSpec spec;
    spec.width = image.width;
    spec.height = image.height;
    // Data window: the crop window where it lies in the frame; display window: the frame.
    spec.x = image.xorigin;
    spec.y = image.yorigin;
    spec.fullWidth = image.fullWidth;
    spec.fullHeight = image.fullHeight;
    for (size_t c = 0; c < channels.size(); ++c) {
        spec.channelNames.push_back(channels[c].name);
        if (channels[c].kind == ChannelKind::Alpha) spec.alphaChannel = int(c);
        if (channels[c].kind == ChannelKind::Depth) spec.zChannel = int(c);
    }
    spec.fileType = fileType;
    spec.compression = params.GetString("compression", "");
    spec.attributes = {{"Software", "gonio"}};
    return spec;
}

// A "zfile" or "shadow" display: one depth channel, and the camera it was seen from.
bool IsDepthMapDisplay(const DisplaySpec& display) {
    const std::string type = Lowercase(display.type);
    return type == "zfile" || type == "shadow";
}

void RecordCamera(const DisplaySpec& display, ImageFileSpec* spec) {
    spec->worldToCamera = display.worldToCamera;
    spec->worldToScreen = display.worldToScreen;
    if (Lowercase(display.type) == "shadow")
        spec->attributes.emplace_back("textureformat", "Shadow");
}

}  // namespace

std::vector<int> SelectDisplayChannels(const std::string& mode,
                                       const std::vector<std::string>& channelNames,
                                       std::string& error) {
    std::vector<int> indices;
    for (const OutputChannel& channel : SelectOutputChannels(mode, channelNames, error))
        indices.push_back(channel.source);
    return indices;
}

float ApplyExposure(float value, const Exposure& exposure) {
    // RISpec §4.1.3 (RiExposure): colour' = (colour * gain) ^ (1 / gamma).
    float exposed = value * exposure.gain;
    if (exposure.gamma == 1.0f || !(exposure.gamma > 0.0f) || !(exposed > 0.0f)) return exposed;
    return std::pow(exposed, 1.0f / exposure.gamma);
}

int QuantizeValue(float value, const Quantization& q, int x, int y, int channel) {
    // RISpec §4.1.3 (RiQuantize): round(one * value + ditheramplitude * random()), random() in
    // [-1, 1], then clamp to [min, max]. Clamping before rounding keeps infinities in range.
    double random = HashPixel(x, y, channel) * (2.0 / 4294967296.0) - 1.0;
    double v = std::isnan(value) ? 0.0 : double(q.one) * value + q.dither * random;
    v = std::min(std::max(v, double(q.min)), double(q.max));
    // std::lround's halves away from zero, without its library call (a value per channel).
    return v >= 0 ? int(v + 0.5) : -int(0.5 - v);
}

// Fichet, Pacanowski and Wilkie 2021, "An OpenEXR Layout for Spectral Images" (JCGT 10(3)): an
// emissive sample is the channel "S0.<wavelength>nm", written with a comma for the decimal
// point ("S0.552,50nm").
std::string SpectralChannelName(double nm) {
    char text[32];
    std::snprintf(text, sizeof text, "S0.%.2fnm", nm);
    std::string name = text;
    std::replace(name.begin(), name.end(), '.', ',');
    name[2] = '.';  // "S0." keeps its dot: only the wavelength's decimal point is a comma
    return name;
}

// A "spectral" display's channels before its spectrum: R, G, B and A.
constexpr int kSpectralPreviewChannels = 4;

// Names the spectral channels of a "spectral" display (after the RGB preview and alpha) by
// their wavelengths; false when the frame is not spectral or the file cannot hold them.
bool NameSpectralChannels(const DisplaySpec& display, const std::string& format,
                          std::vector<OutputChannel>& channels, std::string* error) {
    const size_t preview = kSpectralPreviewChannels;
    if (format != "openexr") {
        *error = "Display mode \"spectral\" needs an OpenEXR file";
        return false;
    }
    if (display.wavelengths.size() + preview != channels.size()) {
        *error = "Display mode \"spectral\" needs Option \"spectral\" \"basis\" \"sampled\"";
        return false;
    }
    for (size_t k = 0; k < display.wavelengths.size(); ++k)
        channels[preview + k].name = SpectralChannelName(display.wavelengths[k]);
    return true;
}

// "int basis" [k]: the n spectral channels of `data` become the k coefficients of the image's
// own basis (basis_display.h), whose vectors go in the header.
spectral::HeaderAttributes ReplaceSamplesByBasis(const DisplaySpec& display,
                                                 std::vector<OutputChannel>& channels,
                                                 PixelData& data) {
    const float* floats = reinterpret_cast<const float*>(data.bytes.data());
    const std::vector<float> values(floats, floats + data.bytes.size() / sizeof(float));
    const BasisCodedPixels coded = EncodeInImageBasis(
        values, kSpectralPreviewChannels, display.wavelengths, display.params.GetInt("basis", 0));
    channels.resize(kSpectralPreviewChannels);
    for (const std::string& name : coded.coefficientNames)
        channels.push_back({-1, ChannelKind::Aov, name});  // no source: computed, not selected
    data.bytes.resize(coded.values.size() * sizeof(float));
    std::memcpy(data.bytes.data(), coded.values.data(), data.bytes.size());
    return coded.attributes;
}

bool WriteDisplay(const DisplaySpec& display, const Image& image,
                  const std::vector<std::string>& channelNames, const Exposure& exposure,
                  const Quantization& colour, const Quantization& depth, Diagnostics& diagnostics) {
    auto fail = [&](const std::string& why) {
        diagnostics.Error(display.loc, "cannot write image \"" + display.name + "\": " + why);
        return false;
    };
    if (int(channelNames.size()) != image.channels)
        return fail(std::to_string(channelNames.size()) + " channel names for an image of " +
                    std::to_string(image.channels) + " channels");
    std::string error;
    std::vector<OutputChannel> channels = SelectOutputChannels(display.mode, channelNames, error);
    if (channels.empty()) return fail(error);
    if (IsDepthMapDisplay(display) &&
        (channels.size() != 1 || channels[0].kind != ChannelKind::Depth))
        return fail("a \"" + display.type +
                    "\" display writes depth: its mode must be \"z\", not \"" + display.mode +
                    "\"");

    std::string format;
    try {
        format = ChooseFormat(display, diagnostics);
    } catch (const std::runtime_error& e) {  // the OpenImageIO plugin is missing
        return fail(e.what());
    }
    if (display.mode == "spectral" && !NameSpectralChannels(display, format, channels, &error))
        return fail(error);
    // A depth map's depths are floats whatever Quantize "z" says: they are compared, not shown.
    const Quantization& depthCodes =
        IsDepthMapDisplay(display) ? DefaultDepthQuantization() : depth;
    StorageChoice type = ChooseStorage(display, format, channels, colour, depthCodes, diagnostics);
    display.params.MarkRead("origin");  // accepted: a window position only a framebuffer uses
    PixelData data =
        ComputePixels(image, channels, exposure, type.colour, type.depth, type.isFloat);
    spectral::HeaderAttributes basisAttributes;
    if (display.mode == "spectral" && display.params.Has("basis")) {
        try {
            basisAttributes = ReplaceSamplesByBasis(display, channels, data);
        } catch (const std::invalid_argument& e) {
            return fail(e.what());
        }
    }
    ImageFileSpec spec =
        MakeFileSpec(image, channels, type.half ? PixelType::Half : data.type, display.params);
    if (IsDepthMapDisplay(display)) RecordCamera(display, &spec);
    if (display.mode == "spectral") {
        spec.attributes.emplace_back("spectralLayoutVersion", "1.0");
        spec.attributes.emplace_back("emissiveUnits", "W.m^-2.sr^-1");
        spec.attributes.insert(spec.attributes.end(), basisAttributes.begin(),
                               basisAttributes.end());
    }
    error = WriteImageFile(format, display.name, spec, PixelBuffer{data.type, data.bytes.data()});
    display.params.ReportUnused("Display \"" + display.name + "\"", diagnostics);
    return error.empty() || fail(error);
}

}  // namespace gonio
