#pragma once
// Imager shaders (RISpec 3.2 §4.1.2, RiImager): a shader run over every pixel of the finished
// frame. The imaging pipeline of RISpec §4.1.2 (Figure 4.2) is: the hidden-surface samples are
// filtered into pixels by the pixel filter, the pixels pass through the imager, then exposure
// (gain, gamma), then quantization and dithering. So RenderFrame calls ApplyImager on the
// resolved image, before the image writer applies Exposure and Quantize.

#include <cstdint>

#include "base/diagnostics.h"
#include "renderer/image/film.h"
#include "renderer/scene/frame.h"

namespace gonio {

// Runs the frame's Imager shader (Options::imager) over every pixel of `image` (film.h: r g b
// a z then AOVs, colour premultiplied by alpha) and writes its Ci back to r g b and its alpha to
// a; z and the AOVs are left alone. The shader sees, per pixel (RISpec Table 12.5):
//   Ci     the pixel's colour (premultiplied, as the imager "background" expects),
//   Oi     the pixel's alpha on every component,
//   alpha  the pixel's coverage (varying: a batch holds many pixels),
//   P      the pixel centre in full-frame raster space, (x + 0.5, y + 0.5, 0),
//   ncomps, time (shutter open) and dtime (shutter close - open).
// Oi as the shader leaves it is not written anywhere: the image has one alpha, set by `alpha`.
// With ColorSamples, Ci goes to the shader's n components through RGBn, and what the shader
// changed comes back through nRGB (pixels the shader leaves alone stay exactly as they were).
// Pixels run in fixed 16x16 tiles in parallel; Du/Dv are differences to the next pixel along x
// and y in the tile, and random() is seeded per pixel from `seed`, so the result does not depend
// on the number of threads.
// Returns false, with the image unchanged, when the frame has no imager or it cannot be used
// (a missing shader or one that is not an imager: reported at the Imager request's RIB line).
bool ApplyImager(const Frame& frame, uint64_t seed, Image& image, Diagnostics& diagnostics);

}  // namespace gonio
