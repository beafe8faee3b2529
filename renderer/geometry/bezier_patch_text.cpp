#include "renderer/geometry/bezier_patch_text.h"

#include <sstream>

namespace gonio {
namespace {

// The text's lines without the comments and blank lines, each with its 1-based line number.
class LineReader {
  public:
    explicit LineReader(std::string_view text) : text_(text) {}

    // The next line that carries data, or false at the end of the text.
    bool Next(std::istringstream* line) {
        while (position_ < text_.size()) {
            const size_t end = std::min(text_.find('\n', position_), text_.size());
            const std::string_view content = text_.substr(position_, end - position_);
            position_ = end + 1;
            ++number_;
            const size_t first = content.find_first_not_of(" \t\r");
            if (first == std::string_view::npos || content[first] == '#') continue;
            line->clear();
            line->str(std::string(content));
            return true;
        }
        ended_ = true;
        return false;
    }

    // Where the last line read was, for a message.
    std::string Where() const {
        return ended_ ? "at the end of the text: " : "line " + std::to_string(number_) + ": ";
    }

  private:
    std::string_view text_;
    size_t position_ = 0;
    int number_ = 0;
    bool ended_ = false;
};

// True when nothing but white space is left on the line.
bool AtEnd(std::istringstream& line) {
    std::string rest;
    return !(line >> rest);
}

// Reads a line 'keyword N'.
bool ReadCount(LineReader& reader, const char* keyword, int* count, std::string* error) {
    std::istringstream line;
    std::string word;
    if (!reader.Next(&line) || !(line >> word >> *count) || word != keyword || *count < 0 ||
        !AtEnd(line)) {
        *error = reader.Where() + "expected '" + keyword + " N'";
        return false;
    }
    return true;
}

bool ReadVertices(LineReader& reader, std::vector<V3f>* vertices, std::string* error) {
    int count = 0;
    if (!ReadCount(reader, "vertices", &count, error)) return false;
    for (int i = 0; i < count; ++i) {
        std::istringstream line;
        V3f p;
        if (!reader.Next(&line) || !(line >> p.x >> p.y >> p.z) || !AtEnd(line)) {
            *error = reader.Where() + "expected vertex " + std::to_string(i) + " as 'x y z'";
            return false;
        }
        vertices->push_back(p);
    }
    return true;
}

bool ReadPatch(LineReader& reader, const std::vector<V3f>& vertices, BezierPatch* patch,
               std::string* error) {
    std::istringstream line;
    if (!reader.Next(&line) || !(line >> patch->name)) {
        *error = reader.Where() + "expected a patch 'name i0 ... i15'";
        return false;
    }
    for (V3f& point : patch->controlPoints) {
        int index = -1;
        if (!(line >> index) || index < 0 || index >= static_cast<int>(vertices.size())) {
            *error = reader.Where() + "patch '" + patch->name +
                     "' needs 16 vertex indices in [0, " + std::to_string(vertices.size()) + ")";
            return false;
        }
        point = vertices[index];
    }
    if (!AtEnd(line)) {
        *error = reader.Where() + "patch '" + patch->name + "' has more than 16 indices";
        return false;
    }
    return true;
}

}  // namespace

GeometryResult<std::vector<BezierPatch>> ParseBezierPatchText(std::string_view text) {
    LineReader reader(text);
    std::string error;
    std::vector<V3f> vertices;
    int count = 0;
    if (!ReadVertices(reader, &vertices, &error) || !ReadCount(reader, "patches", &count, &error))
        return GeometryResult<std::vector<BezierPatch>>::Error(error);
    std::vector<BezierPatch> patches(count);
    for (BezierPatch& patch : patches)
        if (!ReadPatch(reader, vertices, &patch, &error))
            return GeometryResult<std::vector<BezierPatch>>::Error(error);
    std::istringstream extra;
    if (reader.Next(&extra))
        return GeometryResult<std::vector<BezierPatch>>::Error(reader.Where() +
                                                               "unexpected text after the patches");
    return patches;
}

}  // namespace gonio
