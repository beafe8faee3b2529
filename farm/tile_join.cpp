#include "farm/tile_join.h"

#include <algorithm>
#include <climits>

#include "imageio/image_formats.h"
#include "imageio/oiio_plugin.h"

namespace gonio {
namespace {

struct Window {
    int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;  // x1, y1 exclusive

    void Extend(const ImageFileSpec& s) {
        x0 = std::min(x0, s.x), y0 = std::min(y0, s.y);
        x1 = std::max(x1, s.x + s.width), y1 = std::max(y1, s.y + s.height);
    }
    int Width() const { return x1 - x0; }
    int Height() const { return y1 - y0; }
};

// A tile that cannot join the first one: another frame size or other channels.
std::string Mismatch(const ImageFileSpec& first, const ImageFileSpec& tile) {
    if (tile.FullWidth() != first.FullWidth() || tile.FullHeight() != first.FullHeight())
        return "its frame is " + std::to_string(tile.FullWidth()) + "x" +
               std::to_string(tile.FullHeight()) + ", the first tile's " +
               std::to_string(first.FullWidth()) + "x" + std::to_string(first.FullHeight());
    if (tile.channelNames != first.channelNames || tile.fileType != first.fileType)
        return "its channels or pixel type differ from the first tile's";
    return "";
}

// Copies `tile` into `image` (of window `w`), counting the tiles over each pixel.
void Paste(const ImageFileContents& tile, const Window& w, std::vector<float>& image,
           std::vector<unsigned char>& cover) {
    const ImageFileSpec& s = tile.spec;
    const int channels = s.Channels();
    for (int y = 0; y < s.height; ++y) {
        const size_t row = size_t(s.y + y - w.y0) * w.Width() + (s.x - w.x0);
        std::copy_n(tile.pixels.begin() + size_t(y) * s.width * channels, s.width * channels,
                    image.begin() + row * channels);
        for (int x = 0; x < s.width; ++x) cover[row + x] = std::min(cover[row + x] + 1, 2);
    }
}

}  // namespace

std::string JoinTiles(const std::vector<std::string>& tiles, const std::string& output) {
    if (tiles.empty()) return "no tiles to join";
    std::vector<ImageFileContents> read;
    Window window;
    for (const std::string& path : tiles) {
        std::string error;
        try {
            read.push_back(
                LoadOiioPlugin("joining the tiles of \"" + output + "\"").ReadImage(path, &error));
        } catch (const std::exception& e) {
            error = e.what();
        }
        if (error.empty()) error = Mismatch(read.front().spec, read.back().spec);
        if (!error.empty()) return "tile \"" + path + "\": " + error;
        window.Extend(read.back().spec);
    }
    const ImageFileSpec& first = read.front().spec;
    const int channels = first.Channels();
    std::vector<float> image(size_t(window.Width()) * window.Height() * channels);
    std::vector<unsigned char> cover(size_t(window.Width()) * window.Height(), 0);
    for (const ImageFileContents& tile : read) Paste(tile, window, image, cover);
    for (size_t i = 0; i < cover.size(); ++i) {
        if (cover[i] == 1) continue;
        const int x = window.x0 + int(i % window.Width()), y = window.y0 + int(i / window.Width());
        return "pixel " + std::to_string(x) + "," + std::to_string(y) + " is in " +
               (cover[i] == 0 ? "no tile" : "more than one tile") + " of " + output;
    }
    ImageFileSpec spec = first;
    spec.width = window.Width(), spec.height = window.Height();
    spec.x = window.x0, spec.y = window.y0;
    spec.fullWidth = first.FullWidth(), spec.fullHeight = first.FullHeight();
    std::string format;
    try {
        format = FormatForFileName(output);
    } catch (const std::exception& e) {
        return e.what();
    }
    const std::string error =
        WriteImageFile(format, output, spec, PixelBuffer{PixelType::Float, image.data()});
    return error.empty() ? "" : "cannot write \"" + output + "\": " + error;
}

}  // namespace gonio
