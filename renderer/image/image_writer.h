#pragma once
// Writes one Display of a resolved image to disk, after the RISpec imaging pipeline (§4.1.3):
// exposure (gain, gamma) on colour, then quantization with dither and clamping. The file is
// written by imageio/: built-in drivers for TIFF, PNG, OpenEXR and zfile, the OpenImageIO plugin
// (loaded only then) for any other format.
//
// Choices made here (see README.md):
//  * Display types "file", "tiff" and "framebuffer" (with a one-time note: there is no window to
//    show, so the image goes to the named file) write TIFF unless the file name's extension
//    names another format; "openexr"/"exr" write OpenEXR, "png" PNG. Any other type follows the
//    extension, with a warning.
//  * Depth maps, as PRMan and Pixie write them whatever the file's name: "zfile" writes Pixar's
//    zfile, "shadow" a shadow map (a float TIFF tagged "Shadow", imageio/depth_map_file.h). Both
//    take mode "z" only and record the camera's world-to-camera and world-to-screen matrices.
//  * Crop windows: only the window's pixels are written, with the data window's origin set to
//    the window's place in the frame and the display window set to the full Format (as Aqsis
//    does for TIFF). Formats without data windows (PNG) keep just the window's pixels.
//  * Data type: Quantize one = 0 (or an OpenEXR file) gives float data (EXR: half when the
//    Display parameter "exrpixeltype" is "half"); otherwise 8 bit, or 16 bit when one > 255.
//    A file holds one data type; depth and AOV channels are always float, so a file that holds
//    them is float and its colour channels are exposed but not quantized.
//  * The file is written under a temporary name in the same folder and renamed when complete,
//    so a failed write never leaves a partial image behind.

#include <string>
#include <vector>

#include "base/diagnostics.h"
#include "renderer/image/film.h"
#include "renderer/scene/param_dict.h"

namespace gonio {

struct DisplaySpec {
    std::string name;  // the file name (a leading "+" already removed)
    std::string type;  // "file", "tiff", "openexr", "png", "framebuffer", ...
    std::string mode;  // "rgb", "rgba", "rgbz", "rgbaz", "a", "z", "az", or an AOV name
    // Driver parameters, typed: "compression" (string, as OpenImageIO names them), "exrpixeltype"
    // ("half" | "float"), "origin" (accepted; only a framebuffer would use it), "basis" (int k,
    // mode "spectral": k coefficients of the image's own basis instead of the samples;
    // basis_display.h). Any other is reported as having had no effect.
    ParamDict params;
    FileLoc loc;
    // The frame's wavelengths (Option "spectral"), which mode "spectral" writes as channels.
    std::vector<double> wavelengths;
    // The camera's matrices (ImageFileSpec's worldToCamera, worldToScreen), which "zfile" and
    // "shadow" displays record; empty elsewhere.
    std::vector<float> worldToCamera, worldToScreen;
};

// Quantize "rgba"|"z" one min max ditheramplitude. one = 0 means float output.
struct Quantization {
    int one = 255, min = 0, max = 255;
    float dither = 0.5f;

    bool IsFloat() const { return one == 0; }
};

// RISpec default for depth: float output.
inline Quantization DefaultDepthQuantization() { return Quantization{0, 0, 0, 0.0f}; }

// Exposure gain gamma: colour' = (gain * colour) ^ (1 / gamma).
struct Exposure {
    float gain = 1.0f, gamma = 1.0f;
};

// The image channels `mode` selects: the letters of rgb/rgba/rgbz/rgbaz/a/z/az, or, for an AOV,
// every channel named `mode` or `mode.<component>` (e.g. "N.x", "N.y", "N.z"). Returns indices
// into `channelNames`; empty (with `error` set) when a channel the mode needs is missing.
std::vector<int> SelectDisplayChannels(const std::string& mode,
                                       const std::vector<std::string>& channelNames,
                                       std::string& error);

// Applies exposure to a colour value (RISpec §4.1.3).
float ApplyExposure(float value, const Exposure& exposure);

// Quantizes a value to an integer code in [min, max]: round(one * value + dither * d) with d in
// [-1, 1) drawn from a hash of (x, y, channel), so the dither pattern is fixed for a pixel
// whatever the thread count or the order of writing.
int QuantizeValue(float value, const Quantization& q, int x, int y, int channel);

// Writes `image` (whose channels are named by `channelNames`, see film.h for the convention) as
// the display `display`. Returns false after reporting an error that names the file.
bool WriteDisplay(const DisplaySpec& display, const Image& image,
                  const std::vector<std::string>& channelNames, const Exposure& exposure,
                  const Quantization& colour, const Quantization& depth, Diagnostics& diagnostics);

}  // namespace gonio
