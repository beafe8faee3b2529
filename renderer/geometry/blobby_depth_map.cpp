#include "renderer/geometry/blobby_depth_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gonio {

BlobbyDepthMap::BlobbyDepthMap(int width, int height, std::vector<float> depth,
                               const Imath::M44f& cameraFromObject,
                               const Imath::M44f& screenFromObject)
    : width_(width),
      height_(height),
      depth_(std::move(depth)),
      cameraFromObject_(cameraFromObject),
      screenFromObject_(screenFromObject) {}

float BlobbyDepthMap::Texel(int x, int y) const {
    x = std::clamp(x, 0, width_ - 1);
    y = std::clamp(y, 0, height_ - 1);
    return depth_[size_t(y) * width_ + x];
}

bool BlobbyDepthMap::Interpolate(float x, float y, float* depth, float* slopeX,
                                 float* slopeY) const {
    const float fx = x - 0.5f, fy = y - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float ax = fx - x0, ay = fy - y0;
    const int ix = int(x0), iy = int(y0);
    const float d00 = Texel(ix, iy), d10 = Texel(ix + 1, iy);
    const float d01 = Texel(ix, iy + 1), d11 = Texel(ix + 1, iy + 1);
    if (!std::isfinite(d00 + d10 + d01 + d11)) return false;
    const float top = d00 + ax * (d10 - d00), bottom = d01 + ax * (d11 - d01);
    *depth = top + ay * (bottom - top);
    *slopeX = (d10 - d00) * (1 - ay) + (d11 - d01) * ay;
    *slopeY = bottom - top;
    return true;
}

BlobbyDepthMap::Height BlobbyDepthMap::HeightAt(const Imath::V3f& p) const {
    const Imath::M44f& c = cameraFromObject_;
    const Imath::M44f& s = screenFromObject_;
    // Homogeneous screen position (row vector times the matrix) and the point's depth; the
    // camera matrix is affine, so its z needs no division.
    float h[4];
    for (int j = 0; j < 4; ++j) h[j] = p.x * s[0][j] + p.y * s[1][j] + p.z * s[2][j] + s[3][j];
    const float zc = p.x * c[0][2] + p.y * c[1][2] + p.z * c[2][2] + c[3][2];
    Height out;
    if (!(h[3] > 0)) {  // behind a perspective map's camera: it saw nothing there
        out.value = std::numeric_limits<float>::infinity();
        return out;
    }
    // Texel coordinates: x right from the left edge, y down from the top.
    const float sx = h[0] / h[3], sy = h[1] / h[3];
    const float x = (sx + 1) / 2 * width_, y = (1 - sy) / 2 * height_;
    float depth, slopeX, slopeY;
    if (!Interpolate(x, y, &depth, &slopeX, &slopeY)) {
        out.value = std::numeric_limits<float>::infinity();
        return out;
    }
    out.value = depth - zc;
    // ∂(h_j / h_3)/∂p_i = (S[i][j]·h_3 − h_j·S[i][3]) / h_3², scaled to texels.
    const float kx = 0.5f * width_ / (h[3] * h[3]), ky = -0.5f * height_ / (h[3] * h[3]);
    for (int i = 0; i < 3; ++i) {
        const float dx = kx * (s[i][0] * h[3] - h[0] * s[i][3]);
        const float dy = ky * (s[i][1] * h[3] - h[1] * s[i][3]);
        out.gradient[i] = slopeX * dx + slopeY * dy - c[i][2];
    }
    return out;
}

}  // namespace gonio
