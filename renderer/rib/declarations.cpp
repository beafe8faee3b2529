// Parameter declarations (RISpec §3): the predeclared standard names, `Declare`, and inline
// declarations such as "facevarying float[2] st".

#include "renderer/rib/declarations.h"

#include <sstream>
#include <vector>

namespace gonio {
namespace {

struct NamedClass {
    const char* name;
    ParamClass cls;
};
struct NamedType {
    const char* name;
    ParamType type;
};

const NamedClass kClasses[] = {
    {"constant", ParamClass::Constant},       {"uniform", ParamClass::Uniform},
    {"varying", ParamClass::Varying},         {"vertex", ParamClass::Vertex},
    {"facevarying", ParamClass::FaceVarying}, {"facevertex", ParamClass::FaceVertex},
};
const NamedType kTypes[] = {
    {"float", ParamType::Float},   {"integer", ParamType::Integer}, {"int", ParamType::Integer},
    {"string", ParamType::String}, {"color", ParamType::Color},     {"point", ParamType::Point},
    {"vector", ParamType::Vector}, {"normal", ParamType::Normal},   {"hpoint", ParamType::HPoint},
    {"matrix", ParamType::Matrix},
};

// RISpec Table 5.1, the standard shader and request tokens (rib_checklist.md §1), and the
// tokens of Option "BRDFLight".
const char* const kPredeclared[][2] = {
    {"P", "vertex point"},
    {"Pz", "vertex float"},
    {"Pw", "vertex hpoint"},
    {"N", "varying normal"},
    {"Np", "uniform normal"},
    {"Cs", "varying color"},
    {"Os", "varying color"},
    {"s", "varying float"},
    {"t", "varying float"},
    {"st", "varying float[2]"},
    {"width", "varying float"},
    {"constantwidth", "constant float"},
    {"Ka", "uniform float"},
    {"Kd", "uniform float"},
    {"Ks", "uniform float"},
    {"Kr", "uniform float"},
    {"Km", "uniform float"},
    {"roughness", "uniform float"},
    {"specularcolor", "uniform color"},
    {"texturename", "uniform string"},
    {"intensity", "uniform float"},
    {"lightcolor", "uniform color"},
    {"from", "uniform point"},
    {"to", "uniform point"},
    {"coneangle", "uniform float"},
    {"conedeltaangle", "uniform float"},
    {"beamdistribution", "uniform float"},
    {"mindistance", "uniform float"},
    {"maxdistance", "uniform float"},
    {"background", "uniform color"},
    {"distance", "uniform float"},
    {"amplitude", "uniform float"},
    {"fov", "uniform float"},
    {"origin", "uniform integer[2]"},
    {"flatness", "uniform float"},
    {"rays", "uniform integer"},
    {"area", "uniform float"},
};

std::vector<std::string> Words(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream stream(text);
    for (std::string word; stream >> word;) words.push_back(word);
    return words;
}

// Parses "[class] [type] ['[' n ']']" (the array size may touch the type: "float[2]").
bool ParseDeclaration(const std::string& text, ParamDecl* decl, std::string* error) {
    std::string spaced;
    for (char c : text) {
        if (c == '[' || c == ']') {
            spaced += ' ';
            spaced += c;
            spaced += ' ';
        } else {
            spaced += c;
        }
    }
    std::vector<std::string> words = Words(spaced);
    std::size_t next = 0;
    bool haveClass = false, haveType = false;
    if (next < words.size()) {
        for (const NamedClass& named : kClasses) {
            if (words[next] == named.name) {
                decl->cls = named.cls;
                haveClass = true;
                ++next;
                break;
            }
        }
    }
    if (next < words.size()) {
        for (const NamedType& named : kTypes) {
            if (words[next] == named.name) {
                decl->type = named.type;
                haveType = true;
                ++next;
                break;
            }
        }
    }
    if (!haveType) {
        *error = next < words.size() ? "unknown type '" + words[next] + "'"
                                     : std::string("the declaration has no type");
        if (!haveClass && next < words.size())
            *error = "unknown class or type '" + words[next] + "'";
        *error += " (expected [class] type ['[' n ']'], e.g. \"varying float[2]\")";
        return false;
    }
    if (next < words.size() && words[next] == "[") {
        const bool complete = next + 2 < words.size() && words[next + 2] == "]";
        int size = 0;
        std::size_t used = 0;
        try {
            if (complete) size = std::stoi(words[next + 1], &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (!complete || used != words[next + 1].size() || size < 1) {
            *error = "bad array size in declaration \"" + text +
                     "\" (expected '[' n ']' with n a positive integer)";
            return false;
        }
        decl->arraySize = size;
        next += 3;
    }
    if (next != words.size()) {
        *error = "unexpected '" + words[next] + "' in declaration \"" + text + "\"";
        return false;
    }
    return true;
}

bool IsValidName(const std::string& name) {
    return !name.empty() && name.find_first_of(" \t[]") == std::string::npos;
}

}  // namespace

int ParamDecl::ComponentCount(int colorComponents) const {
    int perValue = 1;
    switch (type) {
        case ParamType::Float:
        case ParamType::Integer:
        case ParamType::String:
            perValue = 1;
            break;
        case ParamType::Color:
            perValue = colorComponents;
            break;
        case ParamType::Point:
        case ParamType::Vector:
        case ParamType::Normal:
            perValue = 3;
            break;
        case ParamType::HPoint:
            perValue = 4;
            break;
        case ParamType::Matrix:
            perValue = 16;
            break;
    }
    return perValue * arraySize;
}

const char* ToString(ParamClass cls) {
    for (const NamedClass& named : kClasses)
        if (named.cls == cls) return named.name;
    return "?";
}

const char* ToString(ParamType type) {
    for (const NamedType& named : kTypes)
        if (named.type == type) return named.name;
    return "?";
}

Declarations::Declarations() {
    std::string error;
    for (const auto& entry : kPredeclared) Declare(entry[0], entry[1], &error);
}

bool Declarations::Declare(const std::string& name, const std::string& declaration,
                           std::string* error) {
    if (!IsValidName(name)) {
        *error = "cannot declare \"" + name + "\": a parameter name is one word";
        return false;
    }
    ParamDecl decl;
    decl.name = name;
    std::string why;
    if (!ParseDeclaration(declaration, &decl, &why)) {
        *error = "bad declaration of \"" + name + "\": " + why;
        return false;
    }
    table_[name] = decl;
    return true;
}

std::string TokenName(const std::string& token) {
    const std::size_t space = token.find_last_of(" \t");
    return space == std::string::npos ? token : token.substr(space + 1);
}

std::optional<ParamDecl> Declarations::Resolve(const std::string& token, std::string* error) const {
    const std::size_t space = token.find_last_of(" \t");
    if (space != std::string::npos) {
        // An inline declaration: everything before the last word declares the last word.
        ParamDecl decl;
        decl.name = token.substr(space + 1);
        std::string why;
        if (!IsValidName(decl.name) || !ParseDeclaration(token.substr(0, space), &decl, &why)) {
            *error = "bad inline declaration \"" + token +
                     "\": " + (why.empty() ? std::string("no parameter name") : why);
            return std::nullopt;
        }
        return decl;
    }
    const auto found = table_.find(token);
    if (found != table_.end()) return found->second;
    *error = "parameter \"" + token + "\" is not declared (use Declare or an inline type, e.g. " +
             "\"uniform float " + token + "\")";
    return std::nullopt;
}

}  // namespace gonio
