// brdf(file, N, O, I, D): the value of a measured BRDF (a .grd from `gonio brdf iopt`) for light
// arriving from I and leaving towards O, at a surface with normal N whose direction of
// anisotropy is D (thesis Appendix C.4). The shader multiplies by Cl and N·L itself, so that
// brdf() composes with illuminance like any other term.
//
// The local frame is the one the BRDF was measured in (brdfsim/brdf.h): z along N, x along D
// projected onto the tangent plane. Isotropic BRDFs ignore x, and so does a D parallel to N.
// Directions at or below the surface give 0. A file that cannot be read is reported once per
// shader line and shades black.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "brdfsim/grd_cache.h"
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

// The loaded BRDF for the call's file name, or null after reporting why there is none.
std::shared_ptr<const GrdFile> LoadBrdf(const BuiltinCall& call) {
    const std::string& name = call.strings[0].data[0];
    std::string error;
    std::shared_ptr<const GrdFile> file =
        GrdCache::Shared().Get(call.context->FindTexture(name), &error);
    if (!file) call.context->RuntimeWarning("brdf " + name, "brdf(\"" + name + "\"): " + error);
    return file;
}

// How the BRDF's components become the shader's colour: copied when the counts agree, a
// single (grey) component broadcast, otherwise the mean of the BRDF's components (reported).
class ComponentMap {
  public:
    ComponentMap(const BuiltinCall& call, int brdfComponents)
        : brdfComponents_(brdfComponents), colorComponents_(call.colorComponents) {
        if (brdfComponents_ != 1 && brdfComponents_ != colorComponents_) {
            call.context->RuntimeWarning(
                "brdf components " + call.strings[0].data[0],
                "brdf(\"" + call.strings[0].data[0] + "\") has " + std::to_string(brdfComponents_) +
                    " colour components, the scene " + std::to_string(colorComponents_) +
                    "; shading with their mean");
        }
    }

    float Component(const float* f, int c) const {
        if (brdfComponents_ == colorComponents_) return f[c];
        if (brdfComponents_ == 1) return f[0];
        float sum = 0.0f;
        for (int k = 0; k < brdfComponents_; ++k) sum += f[k];
        return sum / static_cast<float>(brdfComponents_);
    }

  private:
    int brdfComponents_, colorComponents_;
};

void ZeroResult(const BuiltinCall& call) {
    ForEachPoint(call, [&](int p) {
        for (int c = 0; c < call.colorComponents; ++c) call.result.At(c, p) = 0.0f;
    });
}

void BrdfKernel(const BuiltinCall& call) {
    const std::shared_ptr<const GrdFile> file = LoadBrdf(call);
    if (!file) {
        ZeroResult(call);
        return;
    }
    const Brdf& brdf = file->Fastest();
    const ComponentMap components(call, brdf.NumComponents());
    std::vector<float> f(brdf.NumComponents());
    ForEachPoint(call, [&](int p) {
        const LocalFrame frame = FrameFrom(Triple(call.args[1], p), Triple(call.args[4], p));
        const V3 wOut = Normalized(frame.ToLocal(Triple(call.args[2], p)));
        const V3 wIn = Normalized(frame.ToLocal(Triple(call.args[3], p)));
        if (wIn.z > 0.0f && wOut.z > 0.0f)
            brdf.Eval(wIn, wOut, f.data());
        else
            std::fill(f.begin(), f.end(), 0.0f);
        for (int c = 0; c < call.colorComponents; ++c)
            call.result.At(c, p) = components.Component(f.data(), c);
    });
}

}  // namespace

void AddBrdfBuiltins(BuiltinList* list) {
    list->Add("brdf", "c", "snvvv", BrdfKernel, kReadsFiles);
}

}  // namespace gonio::sl::builtins
