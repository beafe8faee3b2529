#pragma once
// How much light passes a shadow ray: Attribute "visibility" "transmission", as Pixie spells
// it, per primitive:
//   "opaque"       the primitive blocks light;
//   "transparent"  it casts no shadow;
//   "Os" (and "shader", the same here: surface shaders are not run for shadow rays)  light
//                  passes each crossing of the surface attenuated by 1 − Os, per colour
//                  component, with Os the primitive's opacity (Opacity, or its "Os"
//                  primitive variable at the crossing).
// Unset means "Os", which for the default opacity 1 is opaque, as before this attribute.

#include <Imath/ImathVec.h>

#include "renderer/raytrace/ray_scene.h"
#include "renderer/scene/frame.h"

namespace gonio {

enum class Transmission { Opaque, Transparent, Opacity };

// The mode of an attribute state ("Os" for an unknown word, which the builder reports).
Transmission TransmissionOf(const Attributes& attributes);

// Whether every primitive of the frame blocks light completely, so that one any-hit query
// answers a shadow ray.
bool AllShadowsOpaque(const Frame& frame);

// The fraction of light, per colour component (ncomps floats into `out`), that passes along
// org + t·dir for tnear < t < tfar at `time`: the product of 1 − Os over the surfaces crossed.
// Returns how many rays it traced: one per surface crossed, and one that finds no more.
int ShadowTransmission(const RayScene& scene, const Imath::V3f& org, const Imath::V3f& dir,
                       float tnear, float tfar, float time, int ncomps, float* out);

}  // namespace gonio
