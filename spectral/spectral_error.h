#pragma once
// The one error type of the spectral library. Every bad input is reported as an exception whose
// text reads like a compiler's diagnostic (`light.spd:12: error: expected a number, got "x"`), so
// a command can print it as it is and a library caller can route it to base's Diagnostics.

#include <stdexcept>
#include <string>
#include <vector>

#include "base/file_loc.h"

namespace gonio::spectral {

class SpectralError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Throws a SpectralError reading `file:line: error: message` (just `file: error: message` when
// line is 0, i.e. the problem is with the whole file).
[[noreturn]] void FailAt(const std::string& file, int line, const std::string& message);
[[noreturn]] void FailAt(const FileLoc& loc, const std::string& message);

// Parses all of `token` as a finite number; false for "", "1.5x", "nan", "inf", overflow.
bool ParseNumber(const std::string& token, double* value);

// Splits a line on blanks (spaces, tabs, a trailing carriage return).
std::vector<std::string> SplitBlanks(const std::string& line);

}  // namespace gonio::spectral
