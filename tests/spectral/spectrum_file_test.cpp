// The thesis's light-source files (Appendix D.2.3): round trips, and every bad input a located
// error `file:line: error: ...`.
#include "spectral/spectrum_file.h"

#include <gtest/gtest.h>

#include "spectral/spectral_error.h"
#include "test_util.h"

namespace gonio::spectral {
namespace {

// The error text of reading `text` as a file, or "" if it reads.
std::string ErrorOf(const std::string& text) {
    const std::string path = test::WriteFile(test::ScratchDir() / "light.spd", text);
    try {
        ReadSpectrumFile(path);
        return "";
    } catch (const SpectralError& e) {
        return e.what();
    }
}

void ExpectErrorAt(const std::string& text, int line, const std::string& words) {
    const std::string error = ErrorOf(text);
    const std::string where = "light.spd:" + std::to_string(line) + ": error: ";
    EXPECT_NE(error.find(where), std::string::npos) << "want " << where << "\ngot " << error;
    EXPECT_NE(error.find(words), std::string::npos) << "want " << words << "\ngot " << error;
}

TEST(SpectrumFile, ReadsTheThesisExamples) {
    const std::string dir = test::ScratchDir().string();
    const Spectrum samples =
        ReadSpectrumFile(test::WriteFile(dir + "/f.spd",
                                         "# fluorescent, point samples\ncspec 400 404 1\n"
                                         "30.000000\n31.000000\n32.000000\n33.000000\n34.0\n"));
    EXPECT_EQ(samples.Size(), 5u);
    EXPECT_DOUBLE_EQ(samples.Evaluate(402.5), 32.5);
    const Spectrum curve = ReadSpectrumFile(test::WriteFile(
        dir + "/c.spd",
        "# riv illumination Catmull Rom parameters\ncurve 6 400 700\n0.000000 0.500000\n"
        "0.000000 0.500000\n0.203333 0.916667\n0.713333 0.100000\n1.000000 0.500000\n"
        "1.000000 0.500000\n"));
    EXPECT_EQ(curve.GetInterpolation(), Interpolation::CatmullRom);
    ASSERT_EQ(curve.Size(), 4u);
    EXPECT_NEAR(curve.Evaluate(400 + 0.203333 * 300), 0.916667, 1e-12);
    EXPECT_NEAR(curve.Evaluate(400 + 0.713333 * 300), 0.1, 1e-12);
    EXPECT_NEAR(curve.Evaluate(700), 0.5, 1e-12);
}

TEST(SpectrumFile, CspecRoundTrip) {
    const Spectrum s = Spectrum::Regular(380, 5, {0.1, 1.0 / 3, 2.5e-7, 42, 0});
    const std::string path = (test::ScratchDir() / "s.spd").string();
    WriteSpectrumFile(path, s, "a test\nof two lines");
    const Spectrum back = ReadSpectrumFile(path);
    EXPECT_EQ(back.Values(), s.Values());
    EXPECT_EQ(back.Wavelengths(), s.Wavelengths());
}

TEST(SpectrumFile, CurveRoundTrip) {
    Spectrum s({400, 455.5, 610, 700}, {0.2, 0.9, 1.0 / 7, 0.4}, Interpolation::CatmullRom);
    s.SetPhantoms(0.3, 0.45);
    const std::string path = (test::ScratchDir() / "c.spd").string();
    WriteSpectrumFile(path, s);
    const Spectrum back = ReadSpectrumFile(path);
    ASSERT_EQ(back.Size(), s.Size());
    EXPECT_EQ(back.GetInterpolation(), Interpolation::CatmullRom);
    EXPECT_EQ(back.Values(), s.Values());
    EXPECT_EQ(back.PhantomBefore(), 0.3);
    EXPECT_EQ(back.PhantomAfter(), 0.45);
    for (size_t i = 0; i < s.Size(); ++i)
        EXPECT_NEAR(back.Wavelengths()[i], s.Wavelengths()[i], 1e-10);
    for (double nm = 400; nm <= 700; nm += 7) EXPECT_NEAR(back.Evaluate(nm), s.Evaluate(nm), 1e-9);
}

TEST(SpectrumFile, WriteReplacesAtomically) {
    const std::string dir = test::ScratchDir().string();
    const std::string path = dir + "/s.spd";
    WriteSpectrumFile(path, Spectrum::Regular(400, 1, {1, 2}));
    WriteSpectrumFile(path, Spectrum::Regular(400, 1, {3, 4}));
    EXPECT_EQ(ReadSpectrumFile(path).Values(), (std::vector<double>{3, 4}));
    size_t files = 0;
    for (auto it = std::filesystem::directory_iterator(dir);
         it != std::filesystem::directory_iterator(); ++it)
        ++files;
    EXPECT_EQ(files, 1u) << "a temporary file was left behind";
    try {
        WriteSpectrumFile(dir + "/no/such/folder/s.spd", Spectrum::Regular(400, 1, {1, 2}));
        FAIL() << "no error";
    } catch (const SpectralError& e) {
        EXPECT_NE(std::string(e.what()).find("s.spd: error: cannot write"), std::string::npos)
            << e.what();
    }
}

TEST(SpectrumFile, BadInputsGiveLocatedErrors) {
    ExpectErrorAt("# c\ncspec 400 402 1\n1\nx2\n3\n", 4, "expected a number");
    ExpectErrorAt("cspec 400 402 1\n1\n2\n", 3, "truncated");
    ExpectErrorAt("cspec 400 402 1\n1\n2\n3\n4\n", 5, "more values");
    ExpectErrorAt("cspec 400 402 1\n1\n-2\n3\n", 3, "negative");
    ExpectErrorAt("cspec 400 402 1\n1 2\n3\n", 2, "one value per line");
    ExpectErrorAt("cspec 400 402.5 1\n", 1, "whole number");
    ExpectErrorAt("cspec 400 402\n", 1, "cspec START END STEP");
    ExpectErrorAt("# c\nspectrum 400 700 1\n", 2, "unknown keyword");
    ExpectErrorAt("# only a comment\n", 1, "empty");
    ExpectErrorAt("curve 5 400 700\n0 1\n0 1\n0.5 1\n1 1\n", 5, "truncated");
    ExpectErrorAt("curve 4 400 700\n0 1\n0 1\n0.9 1\n0.9 1\n", 4, "does not cover");
    ExpectErrorAt("curve 4 400 700\n0 1\n0 1\n1 -1\n1 1\n", 4, "negative");
    ExpectErrorAt("curve 4 400 700\n0 1\n0 1\n1 1e999\n1 1\n", 4, "expected a number");
    ExpectErrorAt("curve 5 400 700\n0 1\n0 1\n0.7 1\n0.5 1\n1 1\n", 5, "smaller");
    ExpectErrorAt("curve 3 400 700\n", 1, "at least 4");
    ExpectErrorAt("curve 4 400 700\n0 1\n0.1 1\n1 1\n1 1\n", 2, "");
    EXPECT_EQ(ErrorOf("cspec 400 402 1\n1\n# a comment among the values\n2\n\n3\n"), "");
}

TEST(SpectrumFile, MissingFileIsAnError) {
    try {
        ReadSpectrumFile("/nonexistent/light.spd");
        FAIL() << "no error";
    } catch (const SpectralError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/light.spd: error: cannot read"),
                  std::string::npos);
    }
}

}  // namespace
}  // namespace gonio::spectral
