#pragma once
// Named spectra, read at run time from the CIE tables Debian's colord-data package installs
// (/usr/share/colord; see docs/spectral.md for which file each name comes from):
//
//   D65 D50 D55 D93 A B C E F1..F12   CIE illuminants       illuminant/CIE-<name>.sp
//   TCS01..TCS15                      CIE 13.3 test colours ref/CIE-TCS.sp, by SAMPLE_ID
//   CIE1931, CIE1964                  the 2° and 10° observers (as a spectrum: ȳ; CIE1931:x,
//                                     CIE1931:y, CIE1931:z name one function)
//                                     cmf/CIE1931-2deg-XYZ.cmf, cmf/CIE1964-10deg-XYZ.cmf
//   blackbody:T (e.g. blackbody:6500) Planck's law at T kelvin, computed (300-830 nm at 1 nm)
//
// Names are case-insensitive. The data folder is GONIO_COLORD_DIR when that is set (tests point
// it at bad data), else /usr/share/colord.

#include <string>
#include <vector>

#include "spectral/spectrum.h"

namespace gonio::spectral {

// CIE colour matching functions x̄, ȳ, z̄.
struct Observer {
    std::string name;
    Spectrum x, y, z;
};

std::string ColordDirectory();
// Every fixed name (blackbody:T aside), for help texts and tests.
std::vector<std::string> NamedSpectrumNames();
bool IsNamedSpectrum(const std::string& name);

// Throws SpectralError for an unknown name, or, naming the file, when colord-data is missing
// (saying to install it) or its table is bad.
Spectrum NamedSpectrum(const std::string& name);
// "CIE1931" (2°) or "CIE1964" (10°).
Observer NamedObserver(const std::string& name = "CIE1931");

// A named spectrum, or a file: `.sp` / `.cmf` are CGATS (the file's only set, or the set
// `FILE#SAMPLE_ID`), anything else the thesis's `cspec` / `curve` format. So a named spectrum
// can be used wherever a file can.
Spectrum LookupSpectrum(const std::string& nameOrPath);

}  // namespace gonio::spectral
