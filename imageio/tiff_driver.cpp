// TIFF through libtiff, tagged as OpenImageIO 2.4's TIFF writer tags it: strips of 32 rows,
// deflate with the horizontal (integer) or floating-point predictor by default, associated
// alpha, the data window's origin as XPosition/YPosition and the frame as Pixar's full size.
// Deflate-compressed integer strips are encoded here in parallel (libdeflate), the rest by
// libtiff's codecs.
#include <libdeflate.h>
#include <tbb/parallel_for.h>
#include <tiffio.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "imageio/builtin_drivers.h"

namespace gonio {

namespace {

constexpr int kRowsPerStrip = 32;

int CompressionCode(const std::string& name) {
    if (name == "none") return COMPRESSION_NONE;
    if (name == "lzw") return COMPRESSION_LZW;
    if (name == "packbits") return COMPRESSION_PACKBITS;
    return COMPRESSION_ADOBE_DEFLATE;  // "zip" and anything OpenImageIO does not know
}

int BitsPerSample(PixelType type) {
    return type == PixelType::UInt8 ? 8 : type == PixelType::UInt16 ? 16 : 32;
}

void SetExtraSamples(TIFF* tif, const ImageFileSpec& spec) {
    const int n = spec.Channels();
    if (spec.alphaChannel < 0 && n <= 3) return;
    const int colour = n >= 3 ? 3 : 1;
    std::vector<uint16_t> extra(size_t(n - colour), EXTRASAMPLE_UNSPECIFIED);
    for (int c = colour; c < n; ++c)
        if (spec.alphaChannel == c) extra[c - colour] = EXTRASAMPLE_ASSOCALPHA;
    TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, uint16_t(extra.size()), extra.data());
}

void SetWindows(TIFF* tif, const ImageFileSpec& spec) {
    if (spec.FullWidth() != spec.width || spec.FullHeight() != spec.height) {
        TIFFSetField(tif, TIFFTAG_PIXAR_IMAGEFULLWIDTH, uint32_t(spec.FullWidth()));
        TIFFSetField(tif, TIFFTAG_PIXAR_IMAGEFULLLENGTH, uint32_t(spec.FullHeight()));
    }
    if (spec.x || spec.y) {  // TIFF cannot hold a negative origin
        TIFFSetField(tif, TIFFTAG_XPOSITION, std::max(0.0f, float(spec.x)));
        TIFFSetField(tif, TIFFTAG_YPOSITION, std::max(0.0f, float(spec.y)));
    }
}

void SetMetadata(TIFF* tif, const ImageFileSpec& spec) {
    bool dated = false;
    for (const auto& [name, value] : spec.attributes) {
        if (name == "Software") TIFFSetField(tif, TIFFTAG_SOFTWARE, value.c_str());
        if (name == "ImageDescription") TIFFSetField(tif, TIFFTAG_IMAGEDESCRIPTION, value.c_str());
        if (name == "Artist") TIFFSetField(tif, TIFFTAG_ARTIST, value.c_str());
        if (name == "Copyright") TIFFSetField(tif, TIFFTAG_COPYRIGHT, value.c_str());
        if (name == "DateTime") TIFFSetField(tif, TIFFTAG_DATETIME, value.c_str()), dated = true;
        if (name == "textureformat")  // "Shadow" for a shadow map, as maketx records it
            TIFFSetField(tif, TIFFTAG_PIXAR_TEXTUREFORMAT, value.c_str());
    }
    if (!dated) TIFFSetField(tif, TIFFTAG_DATETIME, CurrentDateTime().c_str());
    // Pixar's matrix tags, which OpenImageIO reads back as "worldtoscreen" and "worldtocamera".
    if (spec.worldToScreen.size() == 16)
        TIFFSetField(tif, TIFFTAG_PIXAR_MATRIX_WORLDTOSCREEN, spec.worldToScreen.data());
    if (spec.worldToCamera.size() == 16)
        TIFFSetField(tif, TIFFTAG_PIXAR_MATRIX_WORLDTOCAMERA, spec.worldToCamera.data());
}

// libtiff reports errors through a global handler; the last one is kept for the caller.
thread_local std::string tiffError;

void KeepError(const char* module, const char* format, va_list args) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    tiffError = module ? std::string(module) + ": " + text : text;
}

// How the strips are compressed: the TIFF code and zlib's level for deflate, read once from
// the spec; and whether they are predicted and compressed here, all at once (deflate of integer
// pixels), at libdeflate's level for that quality.
struct StripCoding {
    int code;
    int quality;  // TIFFTAG_ZIPQUALITY
    int level;    // libdeflate's, for the parallel encoding
    bool parallel;
};

StripCoding ChooseStripCoding(const ImageFileSpec& spec, PixelType type) {
    const auto [name, quality] =
        SplitCompression(spec.compression.empty() ? "zip" : spec.compression);
    StripCoding coding;
    coding.code = CompressionCode(name);
    coding.quality = std::clamp(quality > 0 ? quality : 6, 1, 9);
    // libtiff 4.5 compresses with libdeflate at zlib's levels up to 5 and one above from 6 on
    // (tested: the strips are libtiff's byte for byte at every quality).
    coding.level = coding.quality <= 5 ? coding.quality : coding.quality + 1;
    coding.parallel = coding.code == COMPRESSION_ADOBE_DEFLATE && type != PixelType::Float;
    return coding;
}

void SetCompression(TIFF* tif, const StripCoding& coding, PixelType type) {
    TIFFSetField(tif, TIFFTAG_COMPRESSION, coding.code);
    if (coding.code != COMPRESSION_LZW && coding.code != COMPRESSION_ADOBE_DEFLATE) return;
    TIFFSetField(tif, TIFFTAG_PREDICTOR,
                 type == PixelType::Float ? PREDICTOR_FLOATINGPOINT : PREDICTOR_HORIZONTAL);
    if (coding.code == COMPRESSION_ADOBE_DEFLATE)
        TIFFSetField(tif, TIFFTAG_ZIPQUALITY, coding.quality);
}

// TIFF's horizontal predictor (TIFF 6.0 §14) on one row of `samples` integers, n to a pixel:
// each sample becomes its difference from the same channel of the pixel before, modulo 2^bits.
template <class T>
void DifferenceRow(T* row, size_t samples, size_t n) {
    for (size_t i = samples; i-- > n;) row[i] = T(row[i] - row[i - n]);
}

// The strips of a deflate-compressed integer image, each predicted and compressed on its own
// (they are independent in the file), side by side: serial, deflate is the longest part of
// writing a frame. libdeflate is the library libtiff's own codec uses, at the same level.
std::string WriteDeflateStrips(TIFF* tif, const ImageFileSpec& spec, const PixelBuffer& pixels,
                               int level) {
    const size_t n = size_t(spec.Channels()), bytesPerSample = BitsPerSample(pixels.type) / 8;
    const size_t rowBytes = size_t(spec.width) * n * bytesPerSample;
    const int strips = (spec.height + kRowsPerStrip - 1) / kRowsPerStrip;
    // Each strip's zlib stream; empty where it could not be made (a stream never is).
    std::vector<std::vector<unsigned char>> encoded(static_cast<size_t>(strips));
    const auto encode = [&](int strip) {
        const int y = strip * kRowsPerStrip, rows = std::min(kRowsPerStrip, spec.height - y);
        const auto* first = static_cast<const unsigned char*>(pixels.data) + size_t(y) * rowBytes;
        std::vector<unsigned char> raw(first, first + rowBytes * size_t(rows));
        for (int r = 0; r < rows; ++r) {
            unsigned char* row = raw.data() + size_t(r) * rowBytes;
            if (bytesPerSample == 1)
                DifferenceRow(row, rowBytes, n);
            else
                DifferenceRow(reinterpret_cast<uint16_t*>(row), rowBytes / 2, n);
        }
        std::unique_ptr<libdeflate_compressor, void (*)(libdeflate_compressor*)> compressor(
            libdeflate_alloc_compressor(level), libdeflate_free_compressor);
        if (!compressor) return;
        // Compressed into a buffer of the bound, kept at its own size: the strips of a frame
        // wait together for their turn to be written.
        std::vector<unsigned char> bound(
            libdeflate_zlib_compress_bound(compressor.get(), raw.size()));
        const size_t size = libdeflate_zlib_compress(compressor.get(), raw.data(), raw.size(),
                                                     bound.data(), bound.size());
        encoded[size_t(strip)].assign(bound.begin(), bound.begin() + std::ptrdiff_t(size));
    };
    // A one-strip image (a small or empty frame) on this thread: a parallel loop would start
    // oneTBB's workers for nothing.
    if (strips > 1)
        tbb::parallel_for(0, strips, encode);
    else if (strips == 1)
        encode(0);
    for (int strip = 0; strip < strips; ++strip) {
        std::vector<unsigned char>& out = encoded[size_t(strip)];
        if (out.empty()) return "deflate could not compress a strip";
        if (TIFFWriteRawStrip(tif, uint32_t(strip), out.data(), tmsize_t(out.size())) < 0)
            return tiffError.empty() ? "libtiff could not write a strip" : tiffError;
    }
    return "";
}

}  // namespace

std::string WriteTiffFile(const std::string& path, const ImageFileSpec& spec,
                          const PixelBuffer& pixels) {
    TIFFSetErrorHandler(KeepError);
    TIFFSetWarningHandler(nullptr);
    tiffError.clear();
    std::unique_ptr<TIFF, void (*)(TIFF*)> tif(TIFFOpen(path.c_str(), "w"), TIFFClose);
    if (!tif) return "could not open \"" + path + "\"";
    const int n = spec.Channels();
    TIFFSetField(tif.get(), TIFFTAG_IMAGEWIDTH, uint32_t(spec.width));
    TIFFSetField(tif.get(), TIFFTAG_IMAGELENGTH, uint32_t(spec.height));
    SetWindows(tif.get(), spec);
    TIFFSetField(tif.get(), TIFFTAG_ROWSPERSTRIP, uint32_t(kRowsPerStrip));
    TIFFSetField(tif.get(), TIFFTAG_SAMPLESPERPIXEL, uint16_t(n));
    TIFFSetField(tif.get(), TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
    TIFFSetField(tif.get(), TIFFTAG_BITSPERSAMPLE, uint16_t(BitsPerSample(pixels.type)));
    TIFFSetField(tif.get(), TIFFTAG_SAMPLEFORMAT,
                 pixels.type == PixelType::Float ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT);
    const StripCoding coding = ChooseStripCoding(spec, pixels.type);
    SetCompression(tif.get(), coding, pixels.type);
    TIFFSetField(tif.get(), TIFFTAG_PHOTOMETRIC, n >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    SetExtraSamples(tif.get(), spec);
    TIFFSetField(tif.get(), TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    SetMetadata(tif.get(), spec);
    TIFFCheckpointDirectory(tif.get());  // the directory first, as OpenImageIO lays files out
    if (coding.parallel) {
        const std::string error = WriteDeflateStrips(tif.get(), spec, pixels, coding.level);
        if (!error.empty()) return error;
        if (!TIFFFlush(tif.get())) return tiffError.empty() ? "libtiff could not write" : tiffError;
        return "";
    }
    // The other codecs strip by strip, as OpenImageIO writes; libtiff encodes in place (the
    // predictor), so each strip is copied first.
    const size_t rowBytes = size_t(spec.width) * n * BitsPerSample(pixels.type) / 8;
    std::vector<unsigned char> strip(rowBytes * kRowsPerStrip);
    for (int y = 0; y < spec.height; y += kRowsPerStrip) {
        const size_t bytes = rowBytes * size_t(std::min(kRowsPerStrip, spec.height - y));
        std::memcpy(strip.data(), static_cast<const unsigned char*>(pixels.data) + y * rowBytes,
                    bytes);
        if (TIFFWriteEncodedStrip(tif.get(), uint32_t(y / kRowsPerStrip), strip.data(),
                                  tmsize_t(bytes)) < 0)
            return tiffError.empty() ? "libtiff could not write a strip" : tiffError;
    }
    if (!TIFFFlush(tif.get())) return tiffError.empty() ? "libtiff could not write" : tiffError;
    return "";
}

}  // namespace gonio
