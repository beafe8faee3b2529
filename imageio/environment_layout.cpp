#include "imageio/environment_layout.h"

#include <algorithm>
#include <cmath>
#include <functional>
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
// (i + 1/2) / width), the edges extended, or in x wrapped around when `periodicX`.
void Bilinear(const ImageFileContents& picture, float x, float y, bool periodicX, float* out) {
    const int w = picture.spec.width, h = picture.spec.height;
    const int channels = picture.spec.Channels();
    const float px = periodicX ? x * w - 0.5f : std::clamp(x * w - 0.5f, 0.0f, float(w - 1));
    const float py = std::clamp(y * h - 0.5f, 0.0f, float(h - 1));
    const int left = int(std::floor(px)), y0 = int(py);
    const int x0 = periodicX ? ((left % w) + w) % w : left;
    const int x1 = periodicX ? (x0 + 1) % w : std::min(x0 + 1, w - 1);
    const int y1 = std::min(y0 + 1, h - 1);
    const float fx = px - left, fy = py - y0;
    auto at = [&](int i, int j, int c) {
        return picture.pixels[(size_t(j) * w + i) * channels + c];
    };
    for (int c = 0; c < channels; ++c) {
        const float top = at(x0, y0, c) * (1 - fx) + at(x1, y0, c) * fx;
        const float bottom = at(x0, y1, c) * (1 - fx) + at(x1, y1, c) * fx;
        out[c] = top * (1 - fy) + bottom * fy;
    }
}

// A picture of width × height in OpenImageIO's lat-long layout (+y up) with the spec of `like`,
// each pixel the mean of `lookup` along 2 × 2 directions inside it.
ImageFileContents OiioLatLong(
    const ImageFileSpec& like, int width, int height,
    const std::function<void(double x, double y, double z, float* out)>& lookup) {
    ImageFileContents out;
    out.spec = like;
    out.spec.width = width, out.spec.height = height;
    out.spec.x = out.spec.y = out.spec.fullWidth = out.spec.fullHeight = 0;
    const int channels = out.spec.Channels();
    out.pixels.assign(size_t(width) * height * channels, 0.0f);
    std::vector<float> sample(channels);
    constexpr int kSub = 2;
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            float* pixel = &out.pixels[(size_t(j) * width + i) * channels];
            for (int sj = 0; sj < kSub; ++sj) {
                for (int si = 0; si < kSub; ++si) {
                    // OpenImageIO's layout: longitude φ = 2π(s - 1/2) from +z towards -x,
                    // latitude π(1/2 - t) towards +y.
                    const double phi = 2 * kPi * ((i + (si + 0.5) / kSub) / width - 0.5);
                    const double lat = kPi * (0.5 - (j + (sj + 0.5) / kSub) / height);
                    lookup(-std::sin(phi) * std::cos(lat), std::sin(lat),
                           std::cos(phi) * std::cos(lat), sample.data());
                    for (int c = 0; c < channels; ++c) pixel[c] += sample[c] / (kSub * kSub);
                }
            }
        }
    }
    return out;
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
    return OiioLatLong(faces[0].spec, 4 * n, 2 * n, [&](double x, double y, double z, float* out) {
        const CubeFacePoint p = CubeFacePointOf(float(x), float(y), float(z), fovDegrees);
        Bilinear(faces[p.face], p.x, p.y, /*periodicX=*/false, out);
    });
}

ImageFileContents LatLongFromRenderManLatLong(const ImageFileContents& picture) {
    const int w = picture.spec.width, h = picture.spec.height;
    return OiioLatLong(picture.spec, w, h, [&](double x, double y, double z, float* out) {
        // RenderMan's layout: s = 1/2 + atan2(y, x)/2π (periodic), t = acos(z)/π.
        const double s = 0.5 + std::atan2(y, x) / (2 * kPi);
        const double t = std::acos(std::clamp(z, -1.0, 1.0)) / kPi;
        Bilinear(picture, float(s), float(t), /*periodicX=*/true, out);
    });
}

}  // namespace gonio
