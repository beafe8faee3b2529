#pragma once
// The parts of the OpenImageIO plugin, each in its own file; plugin.cpp puts them together.

#include <memory>
#include <string>

#include "imageio/oiio_plugin.h"

namespace gonio {

std::unique_ptr<TextureSystem> NewOiioTextureSystem();
std::unique_ptr<PlotCanvas> NewOiioPlotCanvas(int width, int height);
std::string MakeOiioTexture(const ImageFileContents& picture, const std::string& path,
                            const TextureMakeOptions& options);

}  // namespace gonio
