#pragma once
// The globals of an ambient light (a light shader without illuminate or solar): it lights the
// surface points themselves, so it runs there with their P, N and I, as Pixie runs it (its
// ambientocclusion and ambientindirect lights call occlusion(P, faceforward(N, I), ...)).

#include <Imath/ImathMatrix.h>

#include <vector>

#include "renderer/shading/surface_shading.h"
#include "shaderlang/shading_system.h"

namespace gonio {

struct AmbientLightGlobals {
    std::vector<float> N, I;  // 3 × count, current space

    // Fills N and I for the batch's first `count` points (the surface's normal, facing out,
    // and the direction it is seen along) and points `globals` at them and at P (3 × count,
    // current space).
    void Set(const ShadingBatch& batch, const Imath::M44f& worldFromCurrent, int count,
             const float* P, sl::ShaderGlobals* globals);
};

}  // namespace gonio
