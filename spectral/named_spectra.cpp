#include "spectral/named_spectra.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "spectral/cgats.h"
#include "spectral/spectral_error.h"
#include "spectral/spectrum_file.h"

namespace gonio::spectral {

namespace {

const char* const kIlluminants[] = {"A",  "B",  "C",  "D50", "D55", "D65", "D93",
                                    "E",  "F1", "F2", "F3",  "F4",  "F5",  "F6",
                                    "F7", "F8", "F9", "F10", "F11", "F12"};

std::string Upper(std::string text) {
    for (char& c : text) c = char(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

bool IsIlluminant(const std::string& upper) {
    return std::find(std::begin(kIlluminants), std::end(kIlluminants), upper) !=
           std::end(kIlluminants);
}

bool IsTestColour(const std::string& upper) {
    if (upper.size() != 5 || upper.rfind("TCS", 0) != 0) return false;
    if (!std::isdigit(static_cast<unsigned char>(upper[3])) ||
        !std::isdigit(static_cast<unsigned char>(upper[4])))
        return false;
    const int number = std::stoi(upper.substr(3));
    return number >= 1 && number <= 15;
}

// The observer file and the function (0 x̄, 1 ȳ, 2 z̄) a name asks for, or false.
bool ObserverName(const std::string& upper, std::string* file, int* component) {
    const std::string base = upper.substr(0, upper.find(':'));
    if (base == "CIE1931")
        *file = "cmf/CIE1931-2deg-XYZ.cmf";
    else if (base == "CIE1964")
        *file = "cmf/CIE1964-10deg-XYZ.cmf";
    else
        return false;
    const std::string suffix = upper.size() > base.size() ? upper.substr(base.size()) : "";
    if (suffix.empty() || suffix == ":Y")
        *component = 1;
    else if (suffix == ":X")
        *component = 0;
    else if (suffix == ":Z")
        *component = 2;
    else
        return false;
    return true;
}

bool BlackbodyName(const std::string& upper, double* kelvin) {
    if (upper.rfind("BLACKBODY:", 0) != 0) return false;
    std::string number = upper.substr(10);
    if (!number.empty() && number.back() == 'K') number.pop_back();
    return ParseNumber(number, kelvin);
}

// Reads a colord table, turning a missing file into the advice to install the package.
CgatsFile ReadColordTable(const std::string& relative, const std::string& name) {
    const std::string directory = ColordDirectory();
    const std::string path = directory + "/" + relative;
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        const bool overridden = std::getenv("GONIO_COLORD_DIR") != nullptr;
        throw SpectralError(
            path + ": error: the named spectrum \"" + name + "\" comes from this file, which is " +
            "missing: " +
            (overridden ? std::string("GONIO_COLORD_DIR points at ") + directory +
                              ", which lacks it (it should hold a copy of the Debian package "
                              "colord-data's /usr/share/colord)"
                        : std::string("install the Debian package colord-data "
                                      "(apt-get install colord-data), or set GONIO_COLORD_DIR "
                                      "to a copy of its data")));
    }
    return ReadCgats(path);
}

const CgatsSet& SetAt(const CgatsFile& file, size_t index, const std::string& path) {
    if (index >= file.sets.size())
        throw SpectralError(path + ": error: expected at least " + std::to_string(index + 1) +
                            " sets, the file has " + std::to_string(file.sets.size()));
    return file.sets[index];
}

}  // namespace

std::string ColordDirectory() {
    const char* overridden = std::getenv("GONIO_COLORD_DIR");
    return overridden && *overridden ? std::string(overridden) : std::string("/usr/share/colord");
}

std::vector<std::string> NamedSpectrumNames() {
    std::vector<std::string> names(std::begin(kIlluminants), std::end(kIlluminants));
    for (int i = 1; i <= 15; ++i) names.push_back((i < 10 ? "TCS0" : "TCS") + std::to_string(i));
    names.push_back("CIE1931");
    names.push_back("CIE1964");
    return names;
}

bool IsNamedSpectrum(const std::string& name) {
    const std::string upper = Upper(name);
    std::string file;
    int component = 0;
    double kelvin = 0;
    return IsIlluminant(upper) || IsTestColour(upper) || ObserverName(upper, &file, &component) ||
           BlackbodyName(upper, &kelvin);
}

Spectrum NamedSpectrum(const std::string& name) {
    const std::string upper = Upper(name);
    if (IsIlluminant(upper)) {
        const std::string relative = "illuminant/CIE-" + upper + ".sp";
        return SetAt(ReadColordTable(relative, name), 0, relative).spectrum;
    }
    if (IsTestColour(upper)) {
        const CgatsFile file = ReadColordTable("ref/CIE-TCS.sp", name);
        if (const CgatsSet* set = file.Find(upper)) return set->spectrum;
        throw SpectralError(ColordDirectory() + "/ref/CIE-TCS.sp: error: no set with SAMPLE_ID " +
                            upper);
    }
    std::string relative;
    int component = 0;
    if (ObserverName(upper, &relative, &component))
        return SetAt(ReadColordTable(relative, name), size_t(component), relative).spectrum;
    double kelvin = 0;
    if (BlackbodyName(upper, &kelvin)) return Blackbody(kelvin);
    throw SpectralError("unknown named spectrum \"" + name +
                        "\" (known: D65, D50, D55, D93, A, B, C, E, F1..F12, TCS01..TCS15, "
                        "CIE1931, CIE1964, blackbody:T)");
}

Observer NamedObserver(const std::string& name) {
    const std::string upper = Upper(name);
    std::string relative;
    int component = 0;
    if (upper.find(':') != std::string::npos || !ObserverName(upper, &relative, &component))
        throw SpectralError("unknown observer \"" + name + "\" (known: CIE1931, CIE1964)");
    const CgatsFile file = ReadColordTable(relative, name);
    return Observer{upper, SetAt(file, 0, relative).spectrum, SetAt(file, 1, relative).spectrum,
                    SetAt(file, 2, relative).spectrum};
}

Spectrum LookupSpectrum(const std::string& nameOrPath) {
    if (IsNamedSpectrum(nameOrPath)) return NamedSpectrum(nameOrPath);
    std::string path = nameOrPath, sampleId;
    std::error_code error;
    const size_t hash = nameOrPath.rfind('#');
    if (!std::filesystem::exists(path, error) && hash != std::string::npos) {
        path = nameOrPath.substr(0, hash);
        sampleId = nameOrPath.substr(hash + 1);
    }
    if (!std::filesystem::exists(path, error))
        throw SpectralError("\"" + nameOrPath +
                            "\" is neither a named spectrum (D65, A, F1..F12, TCS01..TCS15, "
                            "CIE1931, blackbody:T, ...) nor an existing file");
    const std::string extension = Upper(std::filesystem::path(path).extension().string());
    if (extension == ".SP" || extension == ".CMF") {
        const CgatsFile file = ReadCgats(path);
        if (!sampleId.empty()) {
            if (const CgatsSet* set = file.Find(sampleId)) return set->spectrum;
            throw SpectralError(path + ": error: no set with SAMPLE_ID " + sampleId);
        }
        if (file.sets.size() != 1)
            throw SpectralError(path + ": error: the file holds " +
                                std::to_string(file.sets.size()) + " spectra; name one as " + path +
                                "#SAMPLE_ID");
        return file.sets.front().spectrum;
    }
    if (!sampleId.empty())
        throw SpectralError(path + ": error: only CGATS files (.sp, .cmf) hold named sets");
    return ReadSpectrumFile(path);
}

}  // namespace gonio::spectral
