#pragma once
// What gonio asks of OpenImageIO, behind an interface so that the executable does not link it:
// Debian's OpenImageIO brings 260 shared libraries whose loading costs 0.15-0.4 s at every
// start. The implementation is the plugin libgonio_oiio.so (imageio/oiio/), next to the gonio
// executable, opened with dlopen the first time something needs it: a texture, environment or
// shadow lookup, a file format the built-in drivers do not write, reading an arbitrary image,
// or a raster plot's text. Nothing here includes OpenImageIO.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/texture_wrap.h"
#include "imageio/image_file.h"

namespace gonio {

// Filtered, cached lookups (OpenImageIO's TextureSystem); thread-safe. The arguments are those
// of renderer/image/texture_lookup.h, which documents them.
class TextureSystem {
  public:
    virtual ~TextureSystem() = default;
    virtual bool Texture(const std::string& file, int firstChannel, int channels,
                         const TextureWrapModes& wrap, int n, const float* s, const float* t,
                         const float* dsdx, const float* dtdx, const float* dsdy, const float* dtdy,
                         const uint8_t* active, float* out) = 0;
    virtual bool Environment(const std::string& file, int firstChannel, int channels, int n,
                             const float* directions, const uint8_t* active, float* out) = 0;
    virtual bool Info(const std::string& file, const std::string& dataname,
                      std::vector<float>* floats, std::string* text) = 0;
    virtual std::string LastError() = 0;
};

// An RGB float canvas for raster plots (OpenImageIO's ImageBufAlgo): aliased one-pixel lines,
// text in a named font, written box-filtered down to the plot's size.
class PlotCanvas {
  public:
    enum class Align { Left, Center, Right };
    struct Box {
        int x0, x1, y0, y1;  // half-open
    };
    virtual ~PlotCanvas() = default;
    // A one-pixel line, drawn only inside `clip` (the whole canvas when null).
    virtual void Line(int x0, int y0, int x1, int y1, const float rgb[3], const Box* clip) = 0;
    // Black text on the baseline at (x, y); returns why it could not be drawn, "" if it was.
    virtual std::string Text(int x, int y, const std::string& text, int size,
                             const std::string& font, Align align) = 0;
    // Black text turned 90° counter-clockwise, centred on (x, y).
    virtual std::string VerticalText(int x, int y, const std::string& text, int size,
                                     const std::string& font) = 0;
    // The canvas box-filtered to width × height, as float RGB (for WriteImageFile).
    virtual std::vector<float> Downsampled(int width, int height) = 0;
};

// How OpenImageIO's make_texture (what `maketx` runs) makes a tiled, MIP-mapped texture file.
struct TextureMakeOptions {
    // A plain texture (MakeTxTexture) or a lat-long environment (MakeTxEnvLatl), its picture
    // in OpenImageIO's layout (+y up: imageio/environment_layout.h).
    bool latLongEnvironment = false;
    // Recorded as the file's "wrapmodes", which lookups follow unless they ask for another mode;
    // an environment map's wrap follows from its layout instead (periodic in s, clamped in t).
    TextureWrapModes wrap;
    // OpenImageIO's name of the filter that makes the MIP levels ("box", "gaussian",
    // "catmull-rom", ...); "" its default.
    std::string filter;
    // With a filter: its widths in s and t, in pixels of the level being made (RISpec's swidth
    // and twidth, as PixelFilter's are in pixels of the image made), and the files, named and
    // removed by the caller, that levels 1, 2, ... are written to (float TIFF), each filtered
    // from the one before; make_texture then takes them as its levels ("maketx:mipimages").
    // Without scratch files make_texture filters at its own width for the filter.
    float swidth = 1, twidth = 1;
    std::vector<std::string> levelFiles;
    // OpenImageIO's name of the file's format ("tiff", "openexr"): the file is written under a
    // temporary name that says nothing.
    std::string format = "tiff";
};

class OiioPlugin {
  public:
    virtual ~OiioPlugin() = default;
    // OpenImageIO's format name for a file name extension (no dot), "" when none knows it.
    virtual std::string FormatForExtension(const std::string& extension) = 0;
    // Writes `pixels` as `spec` says in `format` to `path` (the caller renames it into place).
    // Returns the reason on failure, "" on success.
    virtual std::string WriteImage(const std::string& format, const std::string& path,
                                   const ImageFileSpec& spec, const PixelBuffer& pixels) = 0;
    // Every channel of the file's first subimage, with its string metadata; the reason in
    // `error` when it cannot be read.
    virtual ImageFileContents ReadImage(const std::string& path, std::string* error) = 0;
    // Makes `picture` (its samples stored as picture.spec.fileType says) a texture file at
    // `path` (the caller renames it into place). Returns the reason on failure, "" on success.
    virtual std::string MakeTexture(const ImageFileContents& picture, const std::string& path,
                                    const TextureMakeOptions& options) = 0;
    virtual std::unique_ptr<TextureSystem> NewTextureSystem() = 0;
    virtual std::unique_ptr<PlotCanvas> NewPlotCanvas(int width, int height) = 0;
};

// The plugin, opened on the first call. `purpose` says what needs it ("the texture
// \"grid.tx\""), for the error thrown (std::runtime_error) when the plugin is missing or
// cannot be opened. Thread-safe. The plugin is looked for as $GONIO_OIIO_PLUGIN, else as
// libgonio_oiio.so beside the running executable.
OiioPlugin& LoadOiioPlugin(const std::string& purpose);

// The entry point the plugin exports with C linkage.
using OiioPluginEntry = OiioPlugin* (*)();
inline constexpr const char* kOiioPluginEntry = "GonioOiioPlugin";

}  // namespace gonio
