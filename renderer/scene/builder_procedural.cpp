// Procedural (RISpec 3.2 §5.7): the RIB a procedural stands for is read at once, in an attribute
// block of its own, unless its bound lies outside the viewing frustum: then it is never read.
// That is the scene-build form of the lazy expansion the RISpec describes (a renderer calls a
// procedural when its bound first matters); a ray tracer could also need geometry outside the
// frustum in reflections and shadows, which this gives up for scenes that rely on the bound.

#include <limits>

#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/view_frustum.h"

namespace gonio {
namespace {

// Option "limits" "proceduraltimeout": how long a RunProgram program may take.
constexpr float kDefaultProceduralTimeout = 60;

}  // namespace

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
    const Options& options = state_->options;
    float detail = std::numeric_limits<float>::infinity();
    // Inside an object definition the camera is not where instances will be; the photon
    // tracer (BRDFLight) has no camera at all.
    const bool cull =
        !state_->openObject && state_->motionTimes.empty() && !options.user.count("BRDFLight");
    if (cull && !BoxInViewFrustum(options, state_->transform * options.cameraFromWorld,
                                  bound6.data(), &detail))
        return;
    const auto limits = options.user.find("limits");
    const double timeout =
        limits == options.user.end()
            ? kDefaultProceduralTimeout
            : limits->second.GetFloat("proceduraltimeout", kDefaultProceduralTimeout);
    AttributeBegin(loc);
    reader.Read(detail, timeout);
    AttributeEnd(loc);
}

}  // namespace gonio
