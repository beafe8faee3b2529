#include "shaderlang/shading_context.h"

#include <cctype>
#include <cstdlib>

namespace gonio::sl {

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
