#pragma once
// A position in a scene file, carried by every request and parameter so that any later stage can
// report errors the way a compiler does: `scene.rib:12:5: error: ...`.

#include <memory>
#include <string>

namespace gonio {

struct FileLoc {
    // Shared so that the millions of locations of a large file do not each copy its name.
    std::shared_ptr<const std::string> file;
    int line = 0;
    int column = 0;

    std::string ToString() const;
};

}  // namespace gonio
