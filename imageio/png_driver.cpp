// PNG through libpng, written as OpenImageIO 2.4's PNG writer writes it: zlib level 6 without
// row filters, the data window's origin as an oFFs chunk, string metadata as tEXt chunks, and
// colour divided by alpha (PNG's alpha is unassociated) on the integer codes.
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "imageio/builtin_drivers.h"

namespace gonio {

namespace {

int CompressionStrategy(const std::string& name) {
    if (name == "filtered") return Z_FILTERED;
    if (name == "huffman") return Z_HUFFMAN_ONLY;
    if (name == "rle") return Z_RLE;
    if (name == "fixed") return Z_FIXED;
    return Z_DEFAULT_STRATEGY;
}

// PNG fixes which channel is alpha by the channel count, whatever the channels are.
int AlphaChannel(int channels) { return channels == 2 ? 1 : channels == 4 ? 3 : -1; }

template <typename T>
void Deassociate(T* row, int width, int channels, int alpha) {
    const unsigned max = std::numeric_limits<T>::max();
    for (int x = 0; x < width; ++x, row += channels) {
        if (!row[alpha]) continue;
        for (int c = 0; c < channels; ++c)
            if (c != alpha) row[c] = T(std::min(max, unsigned(row[c]) * max / row[alpha]));
    }
}

struct PngText {
    std::vector<std::string> keys, values;
    std::vector<png_text> chunks;
};

// tEXt chunks under PNG's keywords; DateTime becomes a tIME chunk.
void SetMetadata(png_structp png, png_infop info, const ImageFileSpec& spec, PngText& text) {
    for (const auto& [name, value] : spec.attributes) {
        if (name == "DateTime") {
            png_time time{};
            int year, month, day, hour, minute, second;
            if (std::sscanf(value.c_str(), "%d:%d:%d %d:%d:%d", &year, &month, &day, &hour, &minute,
                            &second) != 6)
                continue;
            time.year = png_uint_16(year), time.month = png_byte(month);
            time.day = png_byte(day), time.hour = png_byte(hour);
            time.minute = png_byte(minute), time.second = png_byte(second);
            png_set_tIME(png, info, &time);
            continue;
        }
        const std::string key = name == "Artist"         ? "Author"
                                : name == "DocumentName" ? "Title"
                                : name == "ImageDescription" || name == "description"
                                    ? "Description"
                                    : name;
        text.keys.push_back(key);
        text.values.push_back(value);
    }
    for (size_t i = 0; i < text.keys.size(); ++i) {
        png_text chunk{};
        chunk.compression = PNG_TEXT_COMPRESSION_NONE;
        chunk.key = text.keys[i].data();
        chunk.text = text.values[i].data();
        text.chunks.push_back(chunk);
    }
    if (!text.chunks.empty()) png_set_text(png, info, text.chunks.data(), int(text.chunks.size()));
}

struct Writer {
    FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    std::string error;
    ~Writer() {
        if (png) png_destroy_write_struct(&png, info ? &info : nullptr);
        if (file) std::fclose(file);
    }
};

void KeepError(png_structp png, png_const_charp message) {
    static_cast<Writer*>(png_get_error_ptr(png))->error = message;
    png_longjmp(png, 1);
}

void IgnoreWarning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp: each call that may fail has a frame of its own.
bool WriteRow(Writer& w, png_bytep row) {
    if (setjmp(png_jmpbuf(w.png))) return false;
    png_write_row(w.png, row);
    return true;
}

bool WriteEnd(Writer& w) {
    if (setjmp(png_jmpbuf(w.png))) return false;
    png_write_end(w.png, w.info);
    return true;
}

// The rows, each copied so that alpha can be divided out and 16-bit codes made big-endian.
bool WriteRows(Writer& w, const ImageFileSpec& spec, const PixelBuffer& pixels) {
    const int n = spec.Channels(), alpha = AlphaChannel(n);
    const bool sixteen = pixels.type == PixelType::UInt16;
    const size_t rowBytes = size_t(spec.width) * n * (sixteen ? 2 : 1);
    std::vector<unsigned char> row(rowBytes);
    for (int y = 0; y < spec.height; ++y) {
        std::memcpy(row.data(), static_cast<const unsigned char*>(pixels.data) + y * rowBytes,
                    rowBytes);
        if (sixteen) {
            auto* codes = reinterpret_cast<uint16_t*>(row.data());
            if (alpha >= 0) Deassociate(codes, spec.width, n, alpha);
            for (size_t i = 0; i < rowBytes / 2; ++i)
                codes[i] = uint16_t(codes[i] << 8 | codes[i] >> 8);
        } else if (alpha >= 0) {
            Deassociate(row.data(), spec.width, n, alpha);
        }
        if (!WriteRow(w, row.data())) return false;
    }
    return WriteEnd(w);
}

}  // namespace

std::string WritePngFile(const std::string& path, const ImageFileSpec& spec,
                         const PixelBuffer& pixels) {
    const int n = spec.Channels();
    if (n < 1 || n > 4) return "PNG only supports 1-4 channels, not " + std::to_string(n);
    static const int kColourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                       PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    Writer w;
    w.file = std::fopen(path.c_str(), "wb");
    if (!w.file) return "could not open \"" + path + "\"";
    w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w, KeepError, IgnoreWarning);
    if (w.png) w.info = png_create_info_struct(w.png);
    if (!w.png || !w.info) return "could not create the PNG writer";
    PngText text;
    if (setjmp(png_jmpbuf(w.png))) return "PNG library error: " + w.error;
    png_init_io(w.png, w.file);
    png_set_compression_level(w.png, 6);
    png_set_compression_strategy(w.png, CompressionStrategy(spec.compression));
    png_set_filter(w.png, 0, PNG_NO_FILTERS);
    png_set_IHDR(w.png, w.info, png_uint_32(spec.width), png_uint_32(spec.height),
                 pixels.type == PixelType::UInt16 ? 16 : 8, kColourTypes[n - 1], PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_oFFs(w.png, w.info, spec.x, spec.y, PNG_OFFSET_PIXEL);
    SetMetadata(w.png, w.info, spec, text);
    png_write_info(w.png, w.info);
    if (!WriteRows(w, spec, pixels)) return "PNG library error: " + w.error;
    const bool closed = std::fclose(w.file) == 0;
    w.file = nullptr;
    return closed ? "" : "could not finish writing \"" + path + "\"";
}

}  // namespace gonio
