#pragma once
// A depth map with the camera that rendered it (`Display "x.z" "zfile"`, a shadow map, a float
// TIFF with Pixar's matrix tags; imageio/depth_map_file.h reads them): what shadow() looks up
// and what a Blobby's repelling plane (opcode 1003) is shaped by. One reader for both, so that
// they agree on which files are depth maps and on what their matrices mean.

#include <Imath/ImathMatrix.h>

#include <memory>
#include <string>
#include <vector>

namespace gonio {

struct DepthMapCamera {
    int width = 0, height = 0;
    std::vector<float> depth;  // camera-space depths, rows from the top; +inf where none was seen
    // World space to the map's camera and to its screen ([-1, 1]², x right, y up), for row
    // vectors as RenderMan writes them.
    Imath::M44f cameraFromWorld, screenFromWorld;
};

// The depth map in `path`; null and the reason (naming the file) when it is missing, is not a
// depth map or records no camera.
std::unique_ptr<DepthMapCamera> ReadDepthMapCamera(const std::string& path, std::string* error);

}  // namespace gonio
