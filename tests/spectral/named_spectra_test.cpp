// Named spectra from colord-data, the lookup by name or file, and the errors for missing or bad
// data (GONIO_COLORD_DIR pointed at a scratch folder).
#include "spectral/named_spectra.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "spectral/cgats.h"
#include "spectral/spectral_error.h"
#include "spectral/spectrum_file.h"
#include "test_util.h"

namespace gonio::spectral {
namespace {

// Sets GONIO_COLORD_DIR for one test.
class ColordDir {
  public:
    explicit ColordDir(const std::string& dir) { setenv("GONIO_COLORD_DIR", dir.c_str(), 1); }
    ~ColordDir() { unsetenv("GONIO_COLORD_DIR"); }
};

std::string ErrorOf(const std::string& name) {
    try {
        LookupSpectrum(name);
        return "";
    } catch (const SpectralError& e) {
        return e.what();
    }
}

TEST(NamedSpectra, EveryNameLoads) {
    for (const std::string& name : NamedSpectrumNames()) {
        const Spectrum s = NamedSpectrum(name);
        EXPECT_LE(s.MinWavelength(), 380) << name;
        EXPECT_GE(s.MaxWavelength(), 770) << name;  // CIE B's table stops at 770 nm
    }
    EXPECT_EQ(NamedSpectrum("d65").Values(), NamedSpectrum("D65").Values());
    EXPECT_DOUBLE_EQ(NamedSpectrum("D65").Evaluate(560), 1.0);  // colord scales D65 to 1 at 560 nm
    EXPECT_DOUBLE_EQ(NamedSpectrum("CIE1931:x").Evaluate(600), 1.0622);
    EXPECT_DOUBLE_EQ(NamedSpectrum("CIE1931").Evaluate(555), 1.0);
    const Spectrum bb = NamedSpectrum("blackbody:3000");
    EXPECT_DOUBLE_EQ(bb.Evaluate(560), 100);
    EXPECT_EQ(NamedSpectrum("blackbody:3000K").Values(), bb.Values());
}

TEST(NamedSpectra, UnknownNameSaysWhatIsKnown) {
    EXPECT_NE(ErrorOf("D66").find("neither a named spectrum"), std::string::npos);
    EXPECT_THROW(NamedSpectrum("F13"), SpectralError);
    EXPECT_THROW(NamedSpectrum("TCS16"), SpectralError);
    EXPECT_THROW(NamedSpectrum("blackbody:-5"), SpectralError);
}

TEST(NamedSpectra, MissingPackageSaysToInstallColordData) {
    unsetenv("GONIO_COLORD_DIR");
    const ColordDir dir(test::ScratchDir().string());
    const std::string error = ErrorOf("D65");
    EXPECT_NE(error.find("illuminant/CIE-D65.sp"), std::string::npos) << error;
    EXPECT_NE(error.find("GONIO_COLORD_DIR"), std::string::npos) << error;
    EXPECT_NE(error.find("colord-data"), std::string::npos) << error;
}

TEST(NamedSpectra, BadTableIsALocatedError) {
    const std::filesystem::path dir = test::ScratchDir();
    std::filesystem::create_directories(dir / "illuminant");
    test::WriteFile(dir / "illuminant/CIE-D65.sp",
                    "SPECT\nSPECTRAL_BANDS\t2\nBEGIN_DATA_FORMAT\nSPEC_400\tSPEC_410\n"
                    "END_DATA_FORMAT\nBEGIN_DATA\n1.0\toops\nEND_DATA\n");
    const ColordDir env(dir.string());
    const std::string error = ErrorOf("D65");
    EXPECT_NE(error.find("CIE-D65.sp:7: error: expected a number"), std::string::npos) << error;
}

TEST(Lookup, AcceptsFilesOfEitherFormat) {
    const std::filesystem::path dir = test::ScratchDir();
    const std::string spd = (dir / "light.spd").string();
    WriteSpectrumFile(spd, Spectrum::Regular(380, 200, {1, 2, 3}));
    EXPECT_EQ(LookupSpectrum(spd).Values(), (std::vector<double>{1, 2, 3}));
    const std::string sp = (dir / "light.sp").string();
    CgatsFile file;
    file.sets.push_back({"", Spectrum::Regular(380, 200, {4, 5, 6})});
    WriteCgats(sp, file);
    EXPECT_EQ(LookupSpectrum(sp).Values(), (std::vector<double>{4, 5, 6}));
    const std::string tcs = ColordDirectory() + "/ref/CIE-TCS.sp";
    EXPECT_EQ(LookupSpectrum(tcs + "#TCS03").Values(), NamedSpectrum("TCS03").Values());
    EXPECT_NE(ErrorOf(tcs).find("15 spectra"), std::string::npos);
}

}  // namespace
}  // namespace gonio::spectral
