#pragma once
// The parts of the OpenImageIO plugin, each in its own file; plugin.cpp puts them together.

#include <memory>

#include "imageio/oiio_plugin.h"

namespace gonio {

std::unique_ptr<TextureSystem> NewOiioTextureSystem();
std::unique_ptr<PlotCanvas> NewOiioPlotCanvas(int width, int height);

}  // namespace gonio
