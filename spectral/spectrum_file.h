#pragma once
// The thesis's light-source files (Appendix D.2.3, Figure D.3). Lines beginning with `#` are
// comments. A file holds one of
//
//   cspec START END STEP        point samples at START, START+STEP, ..., END nm,
//   30.0                        one value per line
//   ...
//
//   curve N START END           N Catmull-Rom control points `t value`, t in [0, 1] mapping to
//   0.0 0.5                     START..END nm; the first and last are repeated as the phantom
//   0.0 0.5                     points that fix the end tangents
//   ...
//
// Every bad input (a malformed number, the wrong count, knots that do not cover START..END, a
// negative value, an unknown keyword, a truncated file) is a SpectralError `file:line: error:`.

#include <string>
#include <vector>

#include "spectral/spectrum.h"

namespace gonio::spectral {

// A `cspec` file gives a regular, piecewise-linear spectrum; a `curve` file a Catmull-Rom one
// (knots at START + t·(END − START), phantom values set).
Spectrum ParseSpectrumFile(const std::vector<std::string>& lines, const std::string& name);
Spectrum ReadSpectrumFile(const std::string& path);

// A Catmull-Rom spectrum is written as `curve`, a regular sampled one as `cspec`; an unevenly
// sampled linear one cannot be written (SpectralError). `comment` (may be empty, may hold
// several lines) is written as `#` lines first.
std::string FormatSpectrumFile(const Spectrum& spectrum, const std::string& comment = "");
void WriteSpectrumFile(const std::string& path, const Spectrum& spectrum,
                       const std::string& comment = "");

}  // namespace gonio::spectral
