#pragma once
// CGATS.17 spectral files as colord-data ships them (`.sp` spectra, `.cmf` colour matching
// functions): a file type line (SPECT, CMF), keyword lines (SPECTRAL_START_NM, SPECTRAL_END_NM,
// SPECTRAL_BANDS, NUMBER_OF_FIELDS, NUMBER_OF_SETS, ...), a BEGIN_DATA_FORMAT ... END_DATA_FORMAT
// field list (optional SAMPLE_ID, then SPEC_<nm> fields) and BEGIN_DATA ... END_DATA with one set
// per row. /usr/share/colord/ref/CIE-TCS.sp is an example with 15 sets named by SAMPLE_ID.

#include <string>
#include <utility>
#include <vector>

#include "spectral/spectrum.h"

namespace gonio::spectral {

struct CgatsSet {
    std::string sampleId;  // empty when the file has no SAMPLE_ID field
    Spectrum spectrum;
};

struct CgatsFile {
    std::string fileType = "SPECT";
    // Keywords other than those the writer derives from the data (SPECTRAL_*, NUMBER_OF_*), in
    // file order, values as written (quotes kept).
    std::vector<std::pair<std::string, std::string>> keywords;
    std::vector<CgatsSet> sets;

    // The set with this SAMPLE_ID, or nullptr.
    const CgatsSet* Find(const std::string& sampleId) const;
};

// Parses `lines` (named `name` in errors). Every problem is a SpectralError `name:line: error:`:
// a field list or data block that never ends, a value that is not a number, a row of the wrong
// length, counts that disagree with SPECTRAL_BANDS / NUMBER_OF_SETS, SPEC_ fields whose
// wavelengths disagree with SPECTRAL_START_NM / END_NM.
CgatsFile ParseCgats(const std::vector<std::string>& lines, const std::string& name);
CgatsFile ReadCgats(const std::string& path);

// All sets must share one regular sampling (throws SpectralError otherwise).
std::string FormatCgats(const CgatsFile& file);
void WriteCgats(const std::string& path, const CgatsFile& file);

}  // namespace gonio::spectral
