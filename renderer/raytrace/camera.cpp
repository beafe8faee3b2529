#include "renderer/raytrace/camera.h"

#include <cmath>

#include "base/math.h"
#include "renderer/raytrace/motion.h"
#include "renderer/scene/view_frustum.h"

namespace gonio {
namespace {

// Shirley and Chiu's concentric map from the unit square to the unit disk: it keeps the
// stratification of the lens samples.
Imath::V2f ConcentricDisk(float u, float v) {
    const float a = 2 * u - 1, b = 2 * v - 1;
    if (a == 0 && b == 0) return {0, 0};
    float r, phi;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = kPiF / 4 * (b / a);
    } else {
        r = b;
        phi = kPiF / 2 - kPiF / 4 * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace

Camera::Camera(const Options& options)
    : worldFromCamera_(options.cameraFromWorld.inverse()),
      motionTimes_(options.cameraMotionTimes),
      cameraFromWorldMotion_(options.cameraMotion),
      perspective_(options.projection == "perspective"),
      tanHalfFov_(std::tan(options.fov * kPiF / 360.f)),
      xres_(options.xres),
      yres_(options.yres),
      nearClip_(options.nearClip),
      farClip_(options.farClip) {
    EffectiveScreenWindow(options, screen_);
    screenPerPixel_[0] = (screen_[1] - screen_[0]) / float(xres_);
    screenPerPixel_[1] = (screen_[3] - screen_[2]) / float(yres_);
    if (perspective_ && std::isfinite(options.fstop) && options.fstop > 0 &&
        options.focalLength > 0 && options.focalDistance > 0) {
        lensRadius_ = 0.5f * options.focalLength / options.fstop;
        focalDistance_ = options.focalDistance;
    }
    worldFromCamera_.multVecMatrix(Imath::V3f(0, 0, 0), pinholeOrigin_);
    stillPinhole_ = perspective_ && lensRadius_ == 0 && motionTimes_.empty();
}

Imath::M44f Camera::ScreenFromCamera() const {
    if (!perspective_) return Imath::M44f();
    // x' = x / (z tan(fov/2)), y' likewise, z' = (z - near) far / (z (far - near)).
    const float f = std::isfinite(farClip_) ? farClip_ : 1e30f, n = nearClip_;
    const float k = 1 / tanHalfFov_;
    return Imath::M44f(k, 0, 0, 0, 0, k, 0, 0, 0, 0, f / (f - n), 1, 0, 0, -f * n / (f - n), 0);
}

Imath::M44f Camera::NdcFromScreen() const {
    const float l = screen_[0], r = screen_[1], b = screen_[2], t = screen_[3];
    return Imath::M44f(1 / (r - l), 0, 0, 0, 0, -1 / (t - b), 0, 0, 0, 0, 1, 0, -l / (r - l),
                       t / (t - b), 0, 1);
}

Imath::M44f Camera::RasterFromNdc() const {
    Imath::M44f m;
    m.setScale(Imath::V3f(float(xres_), float(yres_), 1));
    return m;
}

CameraRay Camera::GenerateLensOrMovingRay(float rasterX, float rasterY, float lensU, float lensV,
                                          float time) const {
    const Imath::V2f screen = ScreenPoint(rasterX, rasterY);
    Imath::V3f org(0, 0, 0), dir(0, 0, 1);
    if (perspective_) {
        dir = Imath::V3f(screen.x * tanHalfFov_, screen.y * tanHalfFov_, 1);
    } else {
        org = Imath::V3f(screen.x, screen.y, 0);
    }
    if (lensRadius_ > 0) {
        // Thin lens: every ray through the lens meets the pinhole ray on the focal plane.
        const Imath::V3f focus = org + dir * focalDistance_;
        const Imath::V2f lens = ConcentricDisk(lensU, lensV) * lensRadius_;
        org = Imath::V3f(lens.x, lens.y, 0);
        dir = (focus - org) / focalDistance_;
    }
    CameraRay ray;
    // A still camera's matrix by reference, not copied for every ray.
    const auto toWorld = [&](const Imath::M44f& worldFromCamera) {
        worldFromCamera.multVecMatrix(org, ray.org);
        worldFromCamera.multDirMatrix(dir, ray.dir);
    };
    if (!motionTimes_.empty())
        toWorld(TransformAt(motionTimes_, cameraFromWorldMotion_, time).inverse());
    else
        toWorld(worldFromCamera_);
    ray.time = time;
    ray.tnear = nearClip_;
    ray.tfar = farClip_;
    return ray;
}

}  // namespace gonio
