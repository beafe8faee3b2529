#pragma once
// What the geometry builders (polygons.h, patches.h, ...) return: a description, or a message
// saying what was wrong with the input. The scene builder prefixes the RIB file location.

#include <string>
#include <utility>
#include <variant>

namespace gonio {

template <class T>
class GeometryResult {
  public:
    GeometryResult(T value) : state_(std::move(value)) {}
    static GeometryResult Error(std::string message) {
        GeometryResult r;
        r.state_ = ErrorText{std::move(message)};
        return r;
    }

    bool Ok() const { return std::holds_alternative<T>(state_); }
    explicit operator bool() const { return Ok(); }
    const T& Value() const { return std::get<T>(state_); }
    T& Value() { return std::get<T>(state_); }
    T&& Take() { return std::move(std::get<T>(state_)); }
    const std::string& Error() const { return std::get<ErrorText>(state_).text; }

  private:
    struct ErrorText {
        std::string text;
    };
    GeometryResult() = default;
    std::variant<T, ErrorText> state_;
};

}  // namespace gonio
