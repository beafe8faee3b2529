#include "renderer/scene/view_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/math.h"

namespace gonio {
namespace {

using Imath::V3f;

// The box's corners in camera space.
void Corners(const Imath::M44f& cameraFromObject, const float b[6], V3f corners[8]) {
    for (int i = 0; i < 8; ++i)
        cameraFromObject.multVecMatrix(V3f(b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + (i >> 2)]),
                                       corners[i]);
}

// Whether every corner has a negative value of `f` (it lies outside that plane).
template <typename Plane>
bool AllOutside(const V3f corners[8], Plane f) {
    return std::all_of(corners, corners + 8, [&](const V3f& c) { return f(c) < 0; });
}

// Screen coordinates are x / (z tan(fov/2)) under perspective, x itself otherwise: the divisor.
struct ScreenDepth {
    bool perspective;
    float tanHalfFov;
    float operator()(const V3f& p) const { return perspective ? tanHalfFov * p.z : 1.f; }
};

ScreenDepth ScreenDepthOf(const Options& options) {
    const bool perspective = options.projection == "perspective";
    return {perspective, perspective ? std::tan(options.fov * kPiF / 360.f) : 1};
}

// The raster area of the screen rectangle about the corners c of a box, the screen window w;
// infinite when a corner lies behind the eye.
float CornersDetail(const Options& options, const V3f c[8], const float w[4],
                    const ScreenDepth& scale) {
    float lo[2] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    float hi[2] = {-lo[0], -lo[1]};
    for (int i = 0; i < 8; ++i) {
        const V3f& p = c[i];
        if (scale.perspective && p.z <= 0) return std::numeric_limits<float>::infinity();
        const float s[2] = {p.x / scale(p), p.y / scale(p)};
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], s[k]), hi[k] = std::max(hi[k], s[k]);
    }
    // Screen to raster: the window spans the resolution.
    return (hi[0] - lo[0]) / (w[1] - w[0]) * options.xres * (hi[1] - lo[1]) / (w[3] - w[2]) *
           options.yres;
}

}  // namespace

void EffectiveScreenWindow(const Options& options, float window[4]) {
    const float aspect = options.frameAspect > 0
                             ? options.frameAspect
                             : options.xres * options.pixelAspect / float(options.yres);
    if (options.screenWindowSet) {
        std::copy(options.screenWindow, options.screenWindow + 4, window);
    } else if (aspect >= 1) {
        window[0] = -aspect, window[1] = aspect, window[2] = -1, window[3] = 1;
    } else {
        window[0] = -1, window[1] = 1, window[2] = -1 / aspect, window[3] = 1 / aspect;
    }
}

float BoxDetail(const Options& options, const Imath::M44f& cameraFromObject,
                const float bound6[6]) {
    V3f c[8];
    Corners(cameraFromObject, bound6, c);
    float w[4];
    EffectiveScreenWindow(options, w);
    return CornersDetail(options, c, w, ScreenDepthOf(options));
}

bool BoxInViewFrustum(const Options& options, const Imath::M44f& cameraFromObject,
                      const float bound6[6], float* detail) {
    V3f c[8];
    Corners(cameraFromObject, bound6, c);
    float w[4];
    EffectiveScreenWindow(options, w);
    const ScreenDepth scale = ScreenDepthOf(options);
    // The frustum's sides are the screen window's edges, scaled by depth under perspective.
    if (AllOutside(c, [&](const V3f& p) { return p.z - options.nearClip; }) ||
        AllOutside(c, [&](const V3f& p) { return options.farClip - p.z; }) ||
        AllOutside(c, [&](const V3f& p) { return p.x - w[0] * scale(p); }) ||
        AllOutside(c, [&](const V3f& p) { return w[1] * scale(p) - p.x; }) ||
        AllOutside(c, [&](const V3f& p) { return p.y - w[2] * scale(p); }) ||
        AllOutside(c, [&](const V3f& p) { return w[3] * scale(p) - p.y; }))
        return false;
    *detail = CornersDetail(options, c, w, scale);
    return true;
}

}  // namespace gonio
