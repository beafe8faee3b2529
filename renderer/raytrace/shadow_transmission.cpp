#include "renderer/raytrace/shadow_transmission.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "renderer/raytrace/surface_point.h"
#include "renderer/raytrace/transparent_layers.h"

namespace gonio {
namespace {

bool HasOsPrimVar(const ShapeGeometry& geometry) {
    return std::visit(
        [](const auto& g) {
            using T = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<T, TriangleMesh>) {
                return std::any_of(g.vars.begin(), g.vars.end(),
                                   [](const MeshVar& v) { return v.var.decl.name == "Os"; });
            } else {
                return g.vars.Find("Os") != nullptr;
            }
        },
        geometry);
}

bool CastsOpaqueShadow(const SceneShape& shape, const Attributes& attributes) {
    switch (TransmissionOf(attributes)) {
        case Transmission::Opaque:
            return true;
        case Transmission::Transparent:
            return false;
        case Transmission::Opacity:
            break;
    }
    return !HasOsPrimVar(shape.geometry) &&
           std::all_of(attributes.opacity.begin(), attributes.opacity.end(),
                       [](float o) { return o >= 1; });
}

}  // namespace

Transmission TransmissionOf(const Attributes& attributes) {
    auto it = attributes.user.find("visibility");
    if (it == attributes.user.end()) return Transmission::Opacity;
    const std::string mode = it->second.GetString("transmission", "Os");
    if (mode == "opaque") return Transmission::Opaque;
    if (mode == "transparent") return Transmission::Transparent;
    return Transmission::Opacity;
}

bool AllShadowsOpaque(const Frame& frame) {
    for (const SceneShape& shape : frame.shapes)
        if (!CastsOpaqueShadow(shape, *shape.attributes)) return false;
    for (const ObjectInstanceUse& use : frame.instances)
        for (size_t i = 0; i < use.definition->shapes.size(); ++i)
            if (!CastsOpaqueShadow(use.definition->shapes[i], *use.shapeAttributes[i]))
                return false;
    return true;
}

int ShadowTransmission(const RayScene& scene, const Imath::V3f& org, const Imath::V3f& dir,
                       float tnear, float tfar, float time, int ncomps, float* out) {
    std::fill(out, out + ncomps, 1.f);
    SurfacePoint sp;
    float t = tnear;
    // Past kMaxTransparentLayers crossings the shadow ray counts as blocked.
    for (int crossing = 0; crossing < kMaxTransparentLayers; ++crossing) {
        RayHit hit;
        if (!scene.Intersect(org, dir, t, tfar, time, &hit)) return crossing + 1;
        scene.Evaluate(org, dir, hit, &sp);
        const Transmission mode =
            sp.attributes ? TransmissionOf(*sp.attributes) : Transmission::Opaque;
        if (mode == Transmission::Opaque) {
            std::fill(out, out + ncomps, 0.f);
            return crossing + 1;
        }
        if (mode == Transmission::Opacity) {
            bool any = false;
            for (int c = 0; c < ncomps; ++c) {
                const float os = c < int(sp.Os.size()) ? sp.Os[c] : 1.f;
                out[c] *= std::clamp(1 - os, 0.f, 1.f);
                any |= out[c] > 0;
            }
            if (!any) return crossing + 1;
        }
        t = ContinuePast(hit.t);
    }
    std::fill(out, out + ncomps, 0.f);
    return kMaxTransparentLayers;
}

}  // namespace gonio
