#include "renderer/scene/unused_parameters.h"

#include <set>

namespace gonio {
namespace {

void ReportAttributes(const Attributes& attributes, std::set<const Attributes*>* seen,
                      Diagnostics& diagnostics) {
    if (!seen->insert(&attributes).second) return;
    for (const auto& [name, params] : attributes.user)
        params.ReportUnused("Attribute \"" + name + "\"", diagnostics);
}

}  // namespace

void ReportUnusedParameters(const Frame& frame, Diagnostics& diagnostics) {
    for (const auto& [name, params] : frame.options.user)
        params.ReportUnused("Option \"" + name + "\"", diagnostics);
    // Many shapes share one attribute state; ParamDict reports each location once anyway.
    std::set<const Attributes*> seen;
    for (const SceneShape& shape : frame.shapes)
        ReportAttributes(*shape.attributes, &seen, diagnostics);
    for (const ObjectInstanceUse& use : frame.instances)
        for (const auto& attributes : use.shapeAttributes)
            ReportAttributes(*attributes, &seen, diagnostics);
}

}  // namespace gonio
