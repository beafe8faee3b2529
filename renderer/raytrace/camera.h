#pragma once
// The RenderMan camera (RISpec §4.1.1): raster → screen → camera → world, perspective or
// orthographic, with an optional thin lens for DepthOfField. Camera space is left-handed with
// the eye looking down +z; a ray's parameter t is its camera-space depth z, so Clipping planes
// and depth output need no conversion.

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <vector>

#include "renderer/scene/options.h"

namespace gonio {

struct CameraRay {
    Imath::V3f org, dir;  // world space; dir is not unit length (its camera-space z is 1)
    float tnear = 0, tfar = 0;
    float time = 0;  // within the shutter interval
};

class Camera {
  public:
    explicit Camera(const Options& options);

    // The ray through raster position (x, y) (pixels from the top-left corner of the frame),
    // with (lensU, lensV) in [0,1)² choosing the point on the lens, at `time` (a moving
    // camera: Options::cameraMotion).
    CameraRay GenerateRay(float rasterX, float rasterY, float lensU, float lensV,
                          float time = 0) const {
        if (!stillPinhole_) return GenerateLensOrMovingRay(rasterX, rasterY, lensU, lensV, time);
        // The usual camera inline, as every camera sample comes here: every ray leaves the
        // pinhole.
        const Imath::V2f screen = ScreenPoint(rasterX, rasterY);
        CameraRay ray;
        ray.org = pinholeOrigin_;
        worldFromCamera_.multDirMatrix(
            Imath::V3f(screen.x * tanHalfFov_, screen.y * tanHalfFov_, 1), ray.dir);
        ray.time = time;
        ray.tnear = nearClip_;
        ray.tfar = farClip_;
        return ray;
    }

    // Whether GenerateRay's (lensU, lensV) matter (DepthOfField).
    bool HasLens() const { return lensRadius_ > 0; }
    const Imath::M44f& WorldFromCamera() const { return worldFromCamera_; }
    // RISpec's screen space from camera space (projective for perspective), and raster and NDC
    // from screen, as row-vector matrices: the shading language's "screen", "NDC", "raster".
    Imath::M44f ScreenFromCamera() const;
    Imath::M44f NdcFromScreen() const;
    Imath::M44f RasterFromNdc() const;
    // The screen window actually used (explicit, or derived from the frame aspect ratio).
    const float* ScreenWindow() const { return screen_; }

  private:
    Imath::V2f ScreenPoint(float rasterX, float rasterY) const {
        return Imath::V2f(screen_[0] + rasterX * screenPerPixel_[0],
                          screen_[3] - rasterY * screenPerPixel_[1]);
    }
    // GenerateRay for orthographic, thin-lens and moving cameras.
    CameraRay GenerateLensOrMovingRay(float rasterX, float rasterY, float lensU, float lensV,
                                      float time) const;

    Imath::M44f worldFromCamera_;
    Imath::V3f pinholeOrigin_;  // a still perspective camera's rays' origin, in world space
    std::vector<float> motionTimes_;
    std::vector<Imath::M44f> cameraFromWorldMotion_;
    bool perspective_;
    float tanHalfFov_;
    float screen_[4];  // left right bottom top
    int xres_, yres_;
    float screenPerPixel_[2];  // the screen window's width / xres and height / yres
    float nearClip_, farClip_;
    float lensRadius_ = 0, focalDistance_ = 0;
    bool stillPinhole_ = false;  // perspective, no lens, no motion
};

}  // namespace gonio
