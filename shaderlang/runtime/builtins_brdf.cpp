// brdf(file, N, O, I, D): the value of a measured BRDF (a .grd from `gonio brdf iopt`) for light
// arriving from I and leaving towards O, at a surface with normal N whose direction of
// anisotropy is D (thesis Appendix C.4). The shader multiplies by Cl and N·L itself, so that
// brdf() composes with illuminance like any other term.
//
// The local frame is the one the BRDF was measured in (brdfsim/brdf.h): z along N, x along D
// projected onto the tangent plane. Isotropic BRDFs ignore x, and so does a D parallel to N.
// The renderer owns the .grd files (ShadingContext::MeasuredBrdf): directions at or below the
// surface give 0, and a file that cannot be read is reported once per shader line and shades
// black.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

struct LocalFrame {
    V3 x, y, z;
    V3 ToLocal(const V3& w) const { return V3(Dot(w, x), Dot(w, y), Dot(w, z)); }
};

// Any unit vector perpendicular to z, for a D that gives no tangent direction.
V3 AnyPerpendicular(const V3& z) {
    const V3 helper = std::fabs(z.x) < 0.9f ? V3(1, 0, 0) : V3(0, 1, 0);
    return Normalized(helper - z * Dot(helper, z));
}

LocalFrame FrameFrom(const V3& normal, const V3& direction) {
    LocalFrame f;
    f.z = Normalized(normal);
    const V3 tangent = direction - f.z * Dot(direction, f.z);
    const float length = tangent.length();
    f.x = length > 1e-6f ? tangent / length : AnyPerpendicular(f.z);
    f.y = f.z.cross(f.x);
    return f;
}

void BrdfKernel(const BuiltinCall& call) {
    const std::string& name = call.strings[0].data[0];
    // A uniform call computes point 0 only (builtins_util.h): the context sees one point.
    const bool varying = IsVaryingCall(call);
    const int count = varying ? call.n : 1;
    const uint8_t* active = varying ? call.active : nullptr;
    std::vector<float> wIn(3 * size_t(count)), wOut(3 * size_t(count));
    ForEachPoint(call, [&](int p) {
        const LocalFrame frame = FrameFrom(Triple(call.args[1], p), Triple(call.args[4], p));
        const V3 out = Normalized(frame.ToLocal(Triple(call.args[2], p)));
        const V3 in = Normalized(frame.ToLocal(Triple(call.args[3], p)));
        for (int k = 0; k < 3; ++k) {
            wOut[size_t(k) * count + p] = out[k];
            wIn[size_t(k) * count + p] = in[k];
        }
    });
    std::vector<float> f(size_t(call.colorComponents) * count, 0.0f);
    call.context->MeasuredBrdf(name, count, wIn.data(), wOut.data(), active, f.data());
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < call.colorComponents; ++c)
            call.result.At(c, p) = f[size_t(c) * count + p];
    });
}

}  // namespace

void AddBrdfBuiltins(BuiltinList* list) {
    list->Add("brdf", "c", "snvvv", BrdfKernel, kReadsFiles);
}

}  // namespace gonio::sl::builtins
