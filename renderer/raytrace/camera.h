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
                          float time = 0) const;

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
};

}  // namespace gonio
