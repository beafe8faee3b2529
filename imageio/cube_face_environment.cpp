#include "imageio/cube_face_environment.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gonio {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Axis {
    float x, y, z;
};

float Dot(const Axis& a, float x, float y, float z) { return a.x * x + a.y * y + a.z * z; }

// RISpec §7.1, RiMakeCubeFaceEnvironment: each face is the view from the origin along its axis
// (forward) with this up direction, in RenderMan's left-handed space, where right = up × forward.
struct FaceView {
    Axis forward, up, right;
};
constexpr FaceView kFaces[6] = {
    {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}},   // px
    {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   // nx
    {{0, 1, 0}, {0, 0, -1}, {1, 0, 0}},   // py
    {{0, -1, 0}, {0, 0, 1}, {1, 0, 0}},   // ny
    {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}},    // pz
    {{0, 0, -1}, {0, 1, 0}, {-1, 0, 0}},  // nz
};

// The face whose axis is the direction's largest component.
int MajorFace(float dx, float dy, float dz) {
    const float ax = std::fabs(dx), ay = std::fabs(dy), az = std::fabs(dz);
    if (ax >= ay && ax >= az) return dx >= 0 ? 0 : 1;
    if (ay >= az) return dy >= 0 ? 2 : 3;
    return dz >= 0 ? 4 : 5;
}

// Bilinear lookup of channel-interleaved float samples at (x, y) in [0, 1]² (pixel centres at
// (i + 1/2) / width), the edges extended.
void Bilinear(const ImageFileContents& face, float x, float y, float* out) {
    const int w = face.spec.width, h = face.spec.height, channels = face.spec.Channels();
    const float px = std::clamp(x * w - 0.5f, 0.0f, float(w - 1));
    const float py = std::clamp(y * h - 0.5f, 0.0f, float(h - 1));
    const int x0 = int(px), y0 = int(py);
    const int x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
    const float fx = px - x0, fy = py - y0;
    auto at = [&](int i, int j, int c) { return face.pixels[(size_t(j) * w + i) * channels + c]; };
    for (int c = 0; c < channels; ++c) {
        const float top = at(x0, y0, c) * (1 - fx) + at(x1, y0, c) * fx;
        const float bottom = at(x0, y1, c) * (1 - fx) + at(x1, y1, c) * fx;
        out[c] = top * (1 - fy) + bottom * fy;
    }
}

}  // namespace

CubeFacePoint CubeFacePointOf(float dx, float dy, float dz, float fovDegrees) {
    CubeFacePoint point;
    point.face = MajorFace(dx, dy, dz);
    const FaceView& view = kFaces[point.face];
    const float depth = Dot(view.forward, dx, dy, dz);
    // A face of full field of view fov spans ±tan(fov/2) at unit distance along its axis.
    const float halfWidth = float(std::tan(fovDegrees * kPi / 360.0));
    point.x = 0.5f + 0.5f * Dot(view.right, dx, dy, dz) / (depth * halfWidth);
    point.y = 0.5f - 0.5f * Dot(view.up, dx, dy, dz) / (depth * halfWidth);
    return point;
}

ImageFileContents LatLongFromCubeFaces(const CubeFaces& faces, float fovDegrees) {
    int n = 1;
    for (const ImageFileContents& face : faces) n = std::max(n, face.spec.width);
    ImageFileContents out;
    out.spec = faces[0].spec;
    out.spec.width = 4 * n, out.spec.height = 2 * n;
    out.spec.x = out.spec.y = out.spec.fullWidth = out.spec.fullHeight = 0;
    const int channels = out.spec.Channels();
    out.pixels.assign(size_t(out.spec.width) * out.spec.height * channels, 0.0f);
    std::vector<float> sample(channels);
    constexpr int kSub = 2;
    for (int j = 0; j < out.spec.height; ++j) {
        for (int i = 0; i < out.spec.width; ++i) {
            float* pixel = &out.pixels[(size_t(j) * out.spec.width + i) * channels];
            for (int sj = 0; sj < kSub; ++sj) {
                for (int si = 0; si < kSub; ++si) {
                    // OpenImageIO's lat-long map (z up): s = 1/2 + φ/2π, t = θ/π from +z.
                    const double s = (i + (si + 0.5) / kSub) / out.spec.width;
                    const double t = (j + (sj + 0.5) / kSub) / out.spec.height;
                    const double phi = 2 * kPi * (s - 0.5), theta = kPi * t;
                    const CubeFacePoint p = CubeFacePointOf(float(std::sin(theta) * std::cos(phi)),
                                                            float(std::sin(theta) * std::sin(phi)),
                                                            float(std::cos(theta)), fovDegrees);
                    Bilinear(faces[p.face], p.x, p.y, sample.data());
                    for (int c = 0; c < channels; ++c) pixel[c] += sample[c] / (kSub * kSub);
                }
            }
        }
    }
    return out;
}

}  // namespace gonio
