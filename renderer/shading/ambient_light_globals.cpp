#include "renderer/shading/ambient_light_globals.h"

namespace gonio {

void AmbientLightGlobals::Set(const ShadingBatch& batch, const Imath::M44f& worldFromCurrent,
                              int count, const float* P, sl::ShaderGlobals* globals) {
    N.assign(3 * size_t(count), 0.f);
    I.assign(3 * size_t(count), 0.f);
    // Normals go by the inverse transpose of currentFromWorld: n · (worldFromCurrent)ᵀ.
    const Imath::M44f normalToCurrent = worldFromCurrent.transposed();
    const Imath::M44f currentFromWorld = worldFromCurrent.inverse();
    for (int i = 0; i < count && size_t(i) < batch.points.size(); ++i) {
        Imath::V3f n, view(0);  // I is 0 where the batch has no incident rays
        normalToCurrent.multDirMatrix(batch.points[i]->N, n);
        if (size_t(i) < batch.incident.size())
            currentFromWorld.multDirMatrix(batch.incident[i], view);
        for (int c = 0; c < 3; ++c)
            N[size_t(c) * count + i] = n[c], I[size_t(c) * count + i] = view[c];
    }
    globals->P = P;
    globals->N = N.data();
    globals->I = I.data();
}

}  // namespace gonio
