#pragma once
// Decoding the C escapes of an ASCII RIB string constant, for the lexer and for the binary
// decoder's unencoded string operands.

#include <string>

namespace gonio {

// Decodes the body of a string constant (without its quotes) into `out`.
void DecodeEscapes(const char* text, int length, std::string* out);

}  // namespace gonio
