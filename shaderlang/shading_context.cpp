#include "shaderlang/shading_context.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace gonio::sl {

bool ShadingContext::MeasuredBrdf(const std::string& name, int count, const float*, const float*,
                                  const uint8_t*, float* out) {
    std::fill_n(out, size_t(colorComponents_) * size_t(count), 0.0f);
    RuntimeWarning("brdf " + name,
                   "brdf(\"" + name + "\"): measured BRDFs are read by the renderer only");
    return false;
}

FileLoc StatementLoc(const std::string& statement, const std::string& fallbackFile) {
    FileLoc loc;
    const size_t colon = statement.rfind(':');
    if (colon != std::string::npos && colon + 1 < statement.size() &&
        std::isdigit(static_cast<unsigned char>(statement[colon + 1]))) {
        loc.file = std::make_shared<const std::string>(statement.substr(0, colon));
        loc.line = std::atoi(statement.c_str() + colon + 1);
    } else {
        loc.file = std::make_shared<const std::string>(fallbackFile);
    }
    return loc;
}

}  // namespace gonio::sl
