#pragma once
// The options of RISpec §4.1 as they stand at WorldBegin, which freezes them for the frame.

#include <Imath/ImathMatrix.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "base/file_loc.h"
#include "renderer/rib/param_list.h"
#include "renderer/scene/attributes.h"
#include "renderer/scene/param_dict.h"

namespace gonio {

struct DisplayRequest {
    std::string name, type, mode;
    ParamDict params;
    FileLoc loc;
};

struct QuantizeSetting {
    int one = 255, min = 0, max = 255;
    float dither = 0.5f;
};

struct Options {
    // Camera and image.
    int xres = 640, yres = 480;  // RISpec leaves the default to the device; Aqsis uses 640x480
    FileLoc formatLoc;           // the Format request, for a resolution too large to render
    float pixelAspect = 1;
    float frameAspect = 0;  // 0: derived from the format
    bool screenWindowSet = false;
    float screenWindow[4] = {-1, 1, -1, 1};  // left right bottom top
    float cropWindow[4] = {0, 1, 0, 1};      // xmin xmax ymin ymax (NDC)
    std::string projection = "orthographic";
    float fov = 90;
    float nearClip = 1e-10f, farClip = std::numeric_limits<float>::infinity();
    float relativeDetail = 1;  // RelativeDetail: scales every Detail bound's raster area
    float fstop = std::numeric_limits<float>::infinity(), focalLength = 0, focalDistance = 0;
    float shutterOpen = 0, shutterClose = 0;
    float xsamples = 2, ysamples = 2;
    std::string filterName = "gaussian";
    float filterWidth[2] = {2, 2};
    float gain = 1, gamma = 1;
    QuantizeSetting colorQuantize, depthQuantize{0, 0, 0, 0};
    std::vector<DisplayRequest> displays;
    int colorComponents = 3;  // ColorSamples
    // ColorSamples' nRGB: n rows of 3, RGB = Σ colour[i]·row i. Empty: the colours are RGB.
    std::vector<float> colorToRgb;
    // ColorSamples' RGBn: 3 rows of n, colour = Σ RGB[c]·row c. Empty: the colours are RGB.
    std::vector<float> colorFromRgb;
    // Option "spectral": the wavelengths (nm) spectra are sampled at; under "sampled" each is a
    // colour component. Empty: the components are RGB, or whatever ColorSamples made them.
    std::vector<double> wavelengths;
    // "bands", "svd": k rows of wavelengths.size(), the components of a sampled spectrum. Empty:
    // the components are the samples.
    std::vector<float> colorFromSamples;
    // "bands": the number of bands asked for; "svd": the number of basis vectors per light
    // spectrum. Both are chosen for each frame from its own spectra
    // (renderer/scene/color_plan.h); until then (colorFromSamples empty) the frame is built
    // sampled.
    int bands = 0;
    int svdVectors = 0;
    bool FitsColorSpaceToFrame() const { return bands > 0 || svdVectors > 0; }
    // Option "spectral" "basis" "rgb": colours given as spectra are reduced to their RGB first,
    // as an RGB renderer must (the RGB image of thesis fig. 6.5).
    bool spectraAsRgb = false;
    // Imager: the shader run over the filtered pixels (unset, or "null": none).
    ShaderInstance imager;
    std::string hider = "hidden";
    // ErrorHandler: "print" (RISpec's default: report and go on, skipping the bad request),
    // "ignore" (the same; messages are still printed), or "abort" (no frame is rendered once an
    // error has been reported).
    std::string errorHandler = "print";
    // The transform current at WorldBegin: camera space from world space (RIB row vectors).
    Imath::M44f cameraFromWorld;
    // A moving camera: cameraFromWorld at each of these times (empty: static).
    std::vector<float> cameraMotionTimes;
    std::vector<Imath::M44f> cameraMotion;
    // Every Option request by name, merged and typed (searchpath, BRDFLight, trace, ...).
    std::map<std::string, ParamDict> user;
};

}  // namespace gonio
