#pragma once
// The types of the RenderMan Shading Language (RISpec §11): the compiler, the interpreter and
// the built-in library all speak in these.

#include <cstdint>
#include <string>

namespace gonio::sl {

enum class BaseType : uint8_t { Void, Float, String, Color, Point, Vector, Normal, Matrix };

// Uniform: one value for the whole batch of shading points; varying: one value per point.
enum class Detail : uint8_t { Uniform, Varying };

struct TypeSpec {
    BaseType base = BaseType::Void;
    // 0: not an array; RSL arrays are 1-D with a fixed length. kUnsized: a user function's
    // `float a[]` formal, which takes an array of any length (its argument's); a shader
    // parameter's `float a[]` takes its default's length when it is checked.
    int arrayLength = 0;
    static constexpr int kUnsized = -1;

    bool IsArray() const { return arrayLength != 0; }
    bool IsUnsized() const { return arrayLength == kUnsized; }
    bool IsPointLike() const {
        return base == BaseType::Point || base == BaseType::Vector || base == BaseType::Normal;
    }
    bool IsTriple() const { return IsPointLike() || base == BaseType::Color; }
    // Floats one element occupies: colours have `colorComponents` (ColorSamples, 3 by default).
    int Width(int colorComponents) const {
        switch (base) {
            case BaseType::Float:
                return 1;
            case BaseType::Color:
                return colorComponents;
            case BaseType::Point:
            case BaseType::Vector:
            case BaseType::Normal:
                return 3;
            case BaseType::Matrix:
                return 16;
            default:
                return 0;
        }
    }
    bool operator==(const TypeSpec& o) const {
        return base == o.base && arrayLength == o.arrayLength;
    }
    bool operator!=(const TypeSpec& o) const { return !(*this == o); }
};

const char* ToString(BaseType base);
std::string ToString(const TypeSpec& type);

}  // namespace gonio::sl
