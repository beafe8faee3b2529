#pragma once
// The surface a Blobby repelling plane (opcode 1003, RISpec 3.2 §5.6, PRMan Application Note
// #31) is given by: a depth map, the depths a camera saw, with that camera. The plane's field is
// a function of the height of a point above this surface, measured along the map camera's view
// direction: the depth the map holds where the point projects, minus the point's own depth. So a
// point between the camera and what it saw has a positive height, one behind it a negative one.
//
// Depths are interpolated bilinearly between texel centres (the height and its gradient are
// then continuous, which the tessellation's Newton steps need); beyond the map's edge the edge
// texels hold. Where a texel saw nothing (+inf) there is no surface: the height is +inf.

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gonio {

class BlobbyDepthMap {
  public:
    // The height of a point above the map's surface and its gradient in object space.
    struct Height {
        float value = 0;
        Imath::V3f gradient{0, 0, 0};
    };

    // `depth`: width × height camera-space depths, rows from the top. The matrices take the
    // Blobby's object space to the map's camera and to its screen ([-1, 1]², x right, y up),
    // for row vectors as RenderMan writes them.
    BlobbyDepthMap(int width, int height, std::vector<float> depth,
                   const Imath::M44f& cameraFromObject, const Imath::M44f& screenFromObject);

    Height HeightAt(const Imath::V3f& p) const;

  private:
    // The depth at continuous texel coordinates (x, y) (texel centres at integers + 0.5) and
    // its slopes ∂/∂x, ∂/∂y; false where a texel involved saw nothing.
    bool Interpolate(float x, float y, float* depth, float* slopeX, float* slopeY) const;
    float Texel(int x, int y) const;

    int width_, height_;
    std::vector<float> depth_;
    Imath::M44f cameraFromObject_, screenFromObject_;
};

// How a Blobby finds the depth map its plane names: the map, or null with the reason in `why`.
using BlobbyDepthMapLookup =
    std::function<std::shared_ptr<const BlobbyDepthMap>(const std::string& name, std::string* why)>;

}  // namespace gonio
