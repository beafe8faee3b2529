// OpenEXR through the OpenEXR library, written as OpenImageIO 2.4's OpenEXR writer writes a
// scanline image: zip (level 4) by default, increasing Y, the data and display windows, the
// date as capDate, other string metadata as string attributes under OpenEXR's names. Built as
// the plugin libgonio_exr.so (imageio/exr_plugin.h), whose entry point returns WriteExrFile.
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <map>
#include <vector>

#include "imageio/builtin_drivers.h"
#include "imageio/exr_plugin.h"

namespace gonio {

namespace {

Imf::Compression CompressionCode(const std::string& name) {
    static const std::map<std::string, Imf::Compression> kCodes = {
        {"none", Imf::NO_COMPRESSION},     {"rle", Imf::RLE_COMPRESSION},
        {"zips", Imf::ZIPS_COMPRESSION},   {"zip", Imf::ZIP_COMPRESSION},
        {"deflate", Imf::ZIP_COMPRESSION}, {"piz", Imf::PIZ_COMPRESSION},
        {"pxr24", Imf::PXR24_COMPRESSION}, {"b44", Imf::B44_COMPRESSION},
        {"b44a", Imf::B44A_COMPRESSION},   {"dwaa", Imf::DWAA_COMPRESSION},
        {"dwab", Imf::DWAB_COMPRESSION}};
    auto found = kCodes.find(name);
    return found == kCodes.end() ? Imf::ZIP_COMPRESSION : found->second;
}

void SetCompression(Imf::Header& header, const ImageFileSpec& spec) {
    auto [name, quality] = SplitCompression(spec.compression.empty() ? "zip" : spec.compression);
    // OpenImageIO's dwa needs tiles of a power of two for one channel; scanlines get zip.
    if (spec.Channels() == 1 && name.rfind("dwa", 0) == 0) name = "zip";
    header.compression() = CompressionCode(name);
    if (name.rfind("dwa", 0) == 0)
        header.insert("dwaCompressionLevel",
                      Imf::FloatAttribute(quality > 0 ? float(quality) : 45.0f));
    if (name.rfind("zip", 0) == 0)
        header.zipCompressionLevel() = quality >= 1 && quality <= 9 ? quality : 4;
}

// OpenImageIO's names for the standard attributes, as OpenEXR spells them.
std::string ExrAttributeName(const std::string& name) {
    if (name == "ImageDescription" || name == "description") return "comments";
    if (name == "Copyright") return "owner";
    if (name == "DateTime") return "capDate";
    return name;
}

void SetMetadata(Imf::Header& header, const ImageFileSpec& spec) {
    bool dated = false;
    for (const auto& [name, value] : spec.attributes) {
        header.insert(ExrAttributeName(name), Imf::StringAttribute(value));
        dated |= name == "DateTime";
    }
    if (!dated) header.insert("capDate", Imf::StringAttribute(CurrentDateTime()));
}

}  // namespace

std::string WriteExrFile(const std::string& path, const ImageFileSpec& spec,
                         const PixelBuffer& pixels) {
    if (pixels.type != PixelType::Float) return "OpenEXR files are written from float pixels";
    const int n = spec.Channels();
    const bool half = spec.fileType == PixelType::Half;
    const Imath::Box2i displayWindow({0, 0}, {spec.FullWidth() - 1, spec.FullHeight() - 1});
    const Imath::Box2i dataWindow({spec.x, spec.y},
                                  {spec.x + spec.width - 1, spec.y + spec.height - 1});
    Imf::Header header(displayWindow, dataWindow);
    const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
    for (const std::string& name : spec.channelNames)
        header.channels().insert(name, Imf::Channel(type));
    SetCompression(header, spec);
    header.lineOrder() = Imf::INCREASING_Y;
    SetMetadata(header, spec);

    const float* values = static_cast<const float*>(pixels.data);
    const size_t count = size_t(spec.width) * spec.height * n;
    std::vector<Imath::half> halves(half ? count : 0);
    for (size_t i = 0; i < halves.size(); ++i) halves[i] = Imath::half(values[i]);
    const size_t sampleBytes = half ? sizeof(Imath::half) : sizeof(float);
    const char* base =
        half ? reinterpret_cast<const char*>(halves.data()) : reinterpret_cast<const char*>(values);
    // OpenEXR addresses the buffer by frame coordinates: shift it back by the origin.
    const size_t xStride = sampleBytes * n, yStride = xStride * spec.width;
    base -= spec.x * ptrdiff_t(xStride) + spec.y * ptrdiff_t(yStride);
    try {
        Imf::FrameBuffer frame;
        for (int c = 0; c < n; ++c)
            frame.insert(
                spec.channelNames[c],
                Imf::Slice(type, const_cast<char*>(base) + c * sampleBytes, xStride, yStride));
        // Our own stream, because OpenEXR's closes its file without checking: a small image on
        // a full disk sat in the stream's buffer and was lost unnoticed.
        std::ofstream out(path, std::ios::binary);
        if (!out) return "could not open \"" + path + "\"";
        {
            Imf::StdOFStream stream(out, path.c_str());
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(spec.height);
        }
        out.close();
        if (!out) return "could not write \"" + path + "\": " + std::strerror(errno);
    } catch (const std::exception& e) {
        return std::string("OpenEXR: ") + e.what();
    }
    return "";
}

}  // namespace gonio

extern "C" __attribute__((visibility("default"))) gonio::ExrWriter GonioExrWriter() {
    return &gonio::WriteExrFile;
}
