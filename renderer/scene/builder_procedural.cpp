// Procedural (RISpec 3.2 §5.7): the RIB a procedural stands for is read in an attribute block of
// its own, at once when its bound lies in the viewing frustum. Outside it, a RunProgram or
// DynamicLoad procedural is never run, and a DelayedReadArchive is read only if a ray reaches
// its bound: it is recorded in the frame (lazy_procedurals.h), and when the rendered frame's rays
// reached it, BuildScene reads the scene again with it expanded (SetLazyExpansion). A ray tracer
// sees archives out of view in mirrors and shadows that way, and one no ray reaches is never
// opened.

#include <Imath/ImathBoxAlgo.h>

#include <limits>

#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/view_frustum.h"

namespace gonio {
namespace {

// Option "limits" "proceduraltimeout": how long a RunProgram program may take.
constexpr float kDefaultProceduralTimeout = 60;

Box3f BoundOf(const std::vector<float>& bound6) {
    return Box3f(V3f(bound6[0], bound6[2], bound6[4]), V3f(bound6[1], bound6[3], bound6[5]));
}

}  // namespace

void SceneBuilder::SetLazyExpansion(int ordinal, LazyExpansion expansion) {
    state_->lazyExpansions[ordinal] = std::move(expansion);
}

void SceneBuilder::Procedural(const std::string& name, const std::vector<std::string>&,
                              const std::vector<float>& bound6, ProceduralReader& reader,
                              const FileLoc& loc) {
    if (!StartPrimitive("Procedural", loc)) return;
    if (bound6.size() != 6) {
        diagnostics_.Error(loc, "Procedural \"" + name +
                                    "\": the bound must have 6 numbers (xmin xmax ymin ymax zmin "
                                    "zmax), got " +
                                    std::to_string(bound6.size()));
        return;
    }
    State& s = *state_;
    const std::string key = (s.proceduralKeys.empty() ? "" : s.proceduralKeys.back() + "/") +
                            std::to_string(s.proceduralCounts.back()++);
    const Options& options = s.options;
    float detail = std::numeric_limits<float>::infinity();
    // Inside an object definition the camera is not where instances will be; the photon
    // tracer (BRDFLight) has no camera at all.
    const bool cull = !s.openObject && s.motionTimes.empty() && !options.user.count("BRDFLight");
    bool forward = false;  // this archive's messages go on to LazyExpansion::report
    if (cull &&
        !BoxInViewFrustum(options, s.transform * options.cameraFromWorld, bound6.data(), &detail)) {
        if (name != "DelayedReadArchive") return;
        const auto expansion = s.lazyExpansions.find(s.frame.ordinal);
        if (expansion == s.lazyExpansions.end() || !expansion->second.keys.count(key)) {
            s.frame.lazyProcedurals.Add({Imath::transform(BoundOf(bound6), s.transform), key});
            return;
        }
        forward = !s.forwardingMessages && expansion->second.firstRead.count(key);
        if (forward) diagnostics_.ForwardTo(expansion->second.report);
    }
    const auto limits = options.user.find("limits");
    const double timeout =
        limits == options.user.end()
            ? kDefaultProceduralTimeout
            : limits->second.GetFloat("proceduraltimeout", kDefaultProceduralTimeout);
    AttributeBegin(loc);
    s.proceduralKeys.push_back(key);
    s.proceduralCounts.push_back(0);
    s.forwardingMessages |= forward;
    reader.Read(detail, timeout);
    if (forward) {
        diagnostics_.ForwardTo(nullptr);
        s.forwardingMessages = false;
    }
    s.proceduralKeys.pop_back();
    s.proceduralCounts.pop_back();
    AttributeEnd(loc);
}

}  // namespace gonio
