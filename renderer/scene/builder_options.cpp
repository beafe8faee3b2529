// SceneBuilder: the options of RISpec §4.1.

#include <cmath>
#include <limits>

#include "base/limits.h"
#include "base/search_path.h"
#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/standard_options.h"

namespace gonio {

void SceneBuilder::Declare(const std::string& name, const std::string& declaration,
                           const FileLoc& loc) {
    std::string error;
    if (!declarations_.Declare(name, declaration, &error)) diagnostics_.Error(loc, error);
}

void SceneBuilder::Format(int xres, int yres, float pixelAspect, const FileLoc& loc) {
    if (!RequireOptions("Format", loc)) return;
    if (xres <= 0 || yres <= 0) {
        diagnostics_.Error(loc, "Format needs a positive resolution, got " + std::to_string(xres) +
                                    "x" + std::to_string(yres));
        return;
    }
    if (xres > kMaxResolution || yres > kMaxResolution) {
        diagnostics_.Error(loc, "Format " + std::to_string(xres) + " " + std::to_string(yres) +
                                    ": the resolution must be at most " +
                                    std::to_string(kMaxResolution) + " in each direction");
        return;
    }
    state_->options.xres = xres;
    state_->options.yres = yres;
    state_->options.formatLoc = loc;
    state_->options.pixelAspect = pixelAspect > 0 ? pixelAspect : 1;
}

void SceneBuilder::FrameAspectRatio(float ratio, const FileLoc& loc) {
    if (!RequireOptions("FrameAspectRatio", loc)) return;
    if (ratio <= 0) {
        diagnostics_.Error(loc, "FrameAspectRatio must be positive");
        return;
    }
    state_->options.frameAspect = ratio;
}

void SceneBuilder::ScreenWindow(float left, float right, float bottom, float top,
                                const FileLoc& loc) {
    if (!RequireOptions("ScreenWindow", loc)) return;
    if (left == right || bottom == top) {
        diagnostics_.Error(loc, "ScreenWindow has zero width or height");
        return;
    }
    state_->options.screenWindowSet = true;
    state_->options.screenWindow[0] = left;
    state_->options.screenWindow[1] = right;
    state_->options.screenWindow[2] = bottom;
    state_->options.screenWindow[3] = top;
}

void SceneBuilder::CropWindow(float xmin, float xmax, float ymin, float ymax, const FileLoc& loc) {
    if (!RequireOptions("CropWindow", loc)) return;
    auto clamp01 = [](float x) { return std::fmin(1.f, std::fmax(0.f, x)); };
    xmin = clamp01(xmin), xmax = clamp01(xmax), ymin = clamp01(ymin), ymax = clamp01(ymax);
    if (xmin >= xmax || ymin >= ymax) {
        diagnostics_.Error(loc, "CropWindow is empty");
        return;
    }
    float* crop = state_->options.cropWindow;
    crop[0] = xmin, crop[1] = xmax, crop[2] = ymin, crop[3] = ymax;
}

void SceneBuilder::Projection(const std::string& name, const ParamList& params,
                              const FileLoc& loc) {
    if (!RequireOptions("Projection", loc)) return;
    if (name != "perspective" && name != "orthographic") {
        diagnostics_.Error(
            loc, "Projection \"" + name + "\" is not supported (perspective, orthographic)");
        return;
    }
    state_->options.projection = name;
    for (const Param& p : params) {
        PrimVar var;
        if (!TypeParam(p, declarations_, state_->options.colorComponents, diagnostics_, &var))
            continue;
        if (var.decl.name == "fov" && !var.values.empty())
            state_->options.fov = var.values[0];
        else
            diagnostics_.Warning(p.loc, "Projection: unknown parameter \"" + p.token + "\"");
    }
    // The projection is applied after the current transform: what came before it is the
    // camera's own placement, so the base space starts again from here (RISpec §4.1.1).
    state_->transform = M44f();
}

void SceneBuilder::Clipping(float nearPlane, float farPlane, const FileLoc& loc) {
    if (!RequireOptions("Clipping", loc)) return;
    if (!(nearPlane > 0) || !(farPlane > nearPlane)) {
        diagnostics_.Error(loc, "Clipping needs 0 < near < far");
        return;
    }
    state_->options.nearClip = nearPlane;
    state_->options.farClip = farPlane;
}

void SceneBuilder::ClippingPlane(float, float, float, float, float, float, const FileLoc& loc) {
    IgnoredRequest("ClippingPlane", loc);
}

void SceneBuilder::DepthOfField(float fstop, float focalLength, float focalDistance,
                                const FileLoc& loc) {
    if (!RequireOptions("DepthOfField", loc)) return;
    state_->options.fstop = fstop;
    state_->options.focalLength = focalLength;
    state_->options.focalDistance = focalDistance;
}

void SceneBuilder::Shutter(float open, float close, const FileLoc& loc) {
    if (!RequireOptions("Shutter", loc)) return;
    state_->options.shutterOpen = open;
    state_->options.shutterClose = close;
}

void SceneBuilder::PixelVariance(float, const FileLoc& loc) {
    IgnoredRequest("PixelVariance", loc);
}

void SceneBuilder::PixelSamples(float xsamples, float ysamples, const FileLoc& loc) {
    if (!RequireOptions("PixelSamples", loc)) return;
    if (xsamples < 1 || ysamples < 1) {
        diagnostics_.Error(loc, "PixelSamples must be at least 1 1");
        return;
    }
    if (xsamples > kMaxPixelSamples || ysamples > kMaxPixelSamples) {
        diagnostics_.Error(loc, "PixelSamples must be at most " +
                                    std::to_string(int(kMaxPixelSamples)) + " in each direction");
        return;
    }
    state_->options.xsamples = xsamples;
    state_->options.ysamples = ysamples;
}

void SceneBuilder::PixelFilter(const std::string& name, float xwidth, float ywidth,
                               const FileLoc& loc) {
    if (!RequireOptions("PixelFilter", loc)) return;
    if (!(xwidth > 0) || !(ywidth > 0)) {
        diagnostics_.Error(loc, "PixelFilter widths must be positive");
        return;
    }
    if (xwidth > kMaxFilterWidth || ywidth > kMaxFilterWidth) {
        diagnostics_.Error(loc, "PixelFilter widths must be at most " +
                                    std::to_string(int(kMaxFilterWidth)) + " pixels");
        return;
    }
    state_->options.filterName = name;
    state_->options.filterWidth[0] = xwidth;
    state_->options.filterWidth[1] = ywidth;
}

void SceneBuilder::Exposure(float gain, float gamma, const FileLoc& loc) {
    if (!RequireOptions("Exposure", loc)) return;
    if (!(gamma > 0)) {
        diagnostics_.Error(loc, "Exposure gamma must be positive");
        return;
    }
    state_->options.gain = gain;
    state_->options.gamma = gamma;
}

void SceneBuilder::Imager(const std::string& name, const ParamList& params, const FileLoc& loc) {
    if (!RequireOptions("Imager", loc)) return;
    // Loaded and run after the frame is filtered (shading/imager_shading.h); "null" or an empty
    // name leaves the option unset.
    SetShader(&state_->options.imager, name, params, loc);
}

void SceneBuilder::Quantize(const std::string& type, int one, int min, int max, float dither,
                            const FileLoc& loc) {
    if (!RequireOptions("Quantize", loc)) return;
    QuantizeSetting setting{one, min, max, dither};
    if (type == "rgba")
        state_->options.colorQuantize = setting;
    else if (type == "z")
        state_->options.depthQuantize = setting;
    else
        diagnostics_.Warning(loc, "Quantize \"" + type + "\" is not a known type (rgba, z)");
}

void SceneBuilder::Display(const std::string& name, const std::string& type,
                           const std::string& mode, const ParamList& params, const FileLoc& loc) {
    if (!RequireOptions("Display", loc)) return;
    DisplayRequest display{name, type, mode, {}, loc};
    for (const Param& p : params) {
        TypedParam typed;
        if (TypeOptionParam("Display", "", p, &typed)) display.params.Set(std::move(typed), p.loc);
    }
    // "+name" adds a display; a plain name replaces all earlier ones (RISpec §4.1.3).
    if (!name.empty() && name[0] == '+') {
        display.name = name.substr(1);
    } else {
        state_->options.displays.clear();
    }
    state_->options.displays.push_back(std::move(display));
}

void SceneBuilder::Hider(const std::string& type, const ParamList&, const FileLoc& loc) {
    if (!RequireOptions("Hider", loc)) return;
    state_->options.hider = type;
    if (type != "hidden" && type != "raytrace" && type != "null")
        diagnostics_.WarningOnce("Hider", loc, "Hider \"" + type + "\" is treated as \"hidden\"");
}

void SceneBuilder::ColorSamples(const std::vector<float>& nRGB, const std::vector<float>& RGBn,
                                const FileLoc& loc) {
    if (!RequireOptions("ColorSamples", loc)) return;
    if (nRGB.size() != RGBn.size() || nRGB.empty() || nRGB.size() % 3 != 0) {
        diagnostics_.Error(loc, "ColorSamples needs two matrices of 3·n numbers each");
        return;
    }
    if (nRGB.size() / 3 > size_t(kMaxColorComponents)) {
        diagnostics_.Error(loc, "ColorSamples: at most " + std::to_string(kMaxColorComponents) +
                                    " colour components, got " + std::to_string(nRGB.size() / 3));
        return;
    }
    SetColorComponents(static_cast<int>(nRGB.size() / 3), nRGB, RGBn, {});
}

void SceneBuilder::RelativeDetail(float relativeDetail, const FileLoc& loc) {
    if (!(relativeDetail >= 0) || !std::isfinite(relativeDetail)) {
        diagnostics_.Error(loc, "RelativeDetail must be a finite number >= 0");
        return;
    }
    state_->options.relativeDetail = relativeDetail;
}

bool SceneBuilder::TypeOptionParam(const std::string& request, const std::string& name,
                                   const Param& param, TypedParam* out) {
    const int ncomps = state_->options.colorComponents;
    std::string unused;
    const bool inline_ = param.token.find(' ') != std::string::npos;
    Param typed = param;
    if (!inline_ && !declarations_.Resolve(param.token, &unused)) {
        const std::string standard = StandardParamDeclaration(request, name, param.token);
        if (standard.empty()) {
            const std::string what = name.empty() ? request : request + " \"" + name + "\"";
            diagnostics_.WarningOnce(request + " " + name + " " + param.token, param.loc,
                                     what + ": unknown parameter \"" + param.token + "\" ignored");
            return false;
        }
        typed.token = standard + " " + param.token;
    }
    PrimVar var;
    if (!TypeParam(typed, declarations_, ncomps, diagnostics_, &var)) return false;
    *out = TypedParam{var.decl, param.numbers, param.strings, typed.token != param.token};
    return true;
}

void SceneBuilder::Option(const std::string& name, const ParamList& params, const FileLoc& loc) {
    if (!RequireOptions("Option", loc)) return;
    if (!IsKnownOptionName(true, name))
        diagnostics_.WarningOnce("Option " + name, loc, "unknown Option \"" + name + "\" ignored");
    ParamDict& merged = state_->options.user[name];
    for (const Param& p : params) {
        TypedParam typed;
        if (!TypeOptionParam("Option", name, p, &typed)) continue;
        // '&' is the path before this request (RISpec §4.1.4), which the next one replaces.
        if (name == "searchpath" && typed.strings.size() == 1)
            typed.strings[0] =
                SubstitutePreviousPath(typed.strings[0], merged.GetString(typed.decl.name, "@"));
        merged.Set(std::move(typed), p.loc);
    }
    // The RIB front end follows the archive path itself (rib_session.cpp), before any target.
    if (name == "searchpath") merged.MarkRead("archive");
    if (name == "spectral") SpectralOption(merged, loc);
}

}  // namespace gonio
