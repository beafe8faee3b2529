#pragma once
// The shortest decimal text that reads back as the same double, for the writers: a file written
// and read again holds exactly the values it was written from.

#include <charconv>
#include <string>

namespace gonio::spectral {

inline std::string ShortestDecimal(double value) {
    char text[64];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

}  // namespace gonio::spectral
