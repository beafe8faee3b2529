#pragma once
// What the camera of a frame can see, for decisions made while the scene is built: whether a
// Procedural's bound lies inside the viewing frustum (a DelayedReadArchive outside it is never
// read) and how large it appears (the detail a RunProgram program is told, RISpec 3.2 §5.7, and
// the level of detail of Detail and DetailRange).

#include <Imath/ImathMatrix.h>

#include "renderer/scene/options.h"

namespace gonio {

// RISpec 3.2 §4.1.1: the screen window used, ScreenWindow's or by default [-1,1] along the
// frame's shorter side (left right bottom top).
void EffectiveScreenWindow(const Options& options, float window[4]);

// Whether the box `bound6` (xmin xmax ymin ymax zmin zmax in object space, placed by
// cameraFromObject, RIB row vectors) may be seen by the camera of `options`: false only when all
// its corners lie outside one plane of the frustum (the screen window's sides, the clipping
// planes). `detail` receives the area in raster pixels of the box's projection, or infinity when
// the box reaches behind the eye.
bool BoxInViewFrustum(const Options& options, const Imath::M44f& cameraFromObject,
                      const float bound6[6], float* detail);
// That area alone, whether or not the camera sees the box (the detail of RISpec's Detail).
float BoxDetail(const Options& options, const Imath::M44f& cameraFromObject, const float bound6[6]);

}  // namespace gonio
