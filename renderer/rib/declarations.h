#pragma once
// The RIB type system for parameter tokens: the standard predeclared names, `Declare`, and inline
// declarations such as "facevarying float[2] st".

#include <optional>
#include <string>
#include <unordered_map>

namespace gonio {

enum class ParamClass { Constant, Uniform, Varying, Vertex, FaceVarying, FaceVertex };
enum class ParamType { Float, Integer, String, Color, Point, Vector, Normal, HPoint, Matrix };

struct ParamDecl {
    std::string name;  // the bare name, "st" for "facevarying float[2] st"
    ParamClass cls = ParamClass::Uniform;
    ParamType type = ParamType::Float;
    int arraySize = 1;

    // Numbers one value of this declaration takes; a colour has `colorComponents` (ColorSamples).
    int ComponentCount(int colorComponents) const;
};

// The name a parameter token gives: its last word ("st" for "facevarying float[2] st").
std::string TokenName(const std::string& token);

const char* ToString(ParamClass cls);
const char* ToString(ParamType type);

class Declarations {
  public:
    Declarations();  // with the standard names of RISpec Table 5.1 and the standard shader tokens

    // Parses a declaration such as "uniform float[2]" for `name`; on failure returns false and
    // says why in `error`.
    bool Declare(const std::string& name, const std::string& declaration, std::string* error);

    // The declaration for a parameter token: an inline declaration if the token carries one,
    // else the one made by Declare or predeclared. nullopt (and `error`) if there is neither.
    std::optional<ParamDecl> Resolve(const std::string& token, std::string* error) const;

  private:
    std::unordered_map<std::string, ParamDecl> table_;
};

}  // namespace gonio
