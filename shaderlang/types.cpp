#include "shaderlang/types.h"

namespace gonio::sl {

const char* ToString(BaseType base) {
    switch (base) {
        case BaseType::Void:
            return "void";
        case BaseType::Float:
            return "float";
        case BaseType::String:
            return "string";
        case BaseType::Color:
            return "color";
        case BaseType::Point:
            return "point";
        case BaseType::Vector:
            return "vector";
        case BaseType::Normal:
            return "normal";
        case BaseType::Matrix:
            return "matrix";
    }
    return "?";
}

std::string ToString(const TypeSpec& type) {
    std::string s = ToString(type.base);
    if (type.IsUnsized()) s += "[]";
    if (type.IsArray() && !type.IsUnsized()) s += "[" + std::to_string(type.arrayLength) + "]";
    return s;
}

}  // namespace gonio::sl
