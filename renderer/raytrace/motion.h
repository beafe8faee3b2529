#pragma once
// Transformation motion blur: a transform known at a few times, read at any time in between.

#include <Imath/ImathMatrix.h>

#include <vector>

namespace gonio {

// The transform at `time`, linearly interpolated between the samples around it (held at the
// ends). Linear interpolation of the matrices is exact for translations and close for the
// small rotations of one shutter interval.
inline Imath::M44f TransformAt(const std::vector<float>& times,
                               const std::vector<Imath::M44f>& samples, float time) {
    if (samples.size() == 1 || time <= times.front()) return samples.front();
    if (time >= times.back()) return samples.back();
    size_t i = 1;
    while (times[i] < time) ++i;
    const float w = (time - times[i - 1]) / (times[i] - times[i - 1]);
    Imath::M44f m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[r][c] = (1 - w) * samples[i - 1][r][c] + w * samples[i][r][c];
    return m;
}

}  // namespace gonio
