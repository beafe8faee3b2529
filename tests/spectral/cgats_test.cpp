// CGATS spectral files: colord's own tables read, a round trip, bad files located.
#include "spectral/cgats.h"

#include <gtest/gtest.h>

#include "spectral/named_spectra.h"
#include "spectral/spectral_error.h"
#include "test_util.h"

namespace gonio::spectral {
namespace {

const char* kSmall =
    "SPECT\nDESCRIPTOR\t\"two samples\"\nSPECTRAL_START_NM\t400\nSPECTRAL_END_NM\t420\n"
    "SPECTRAL_BANDS\t3\nNUMBER_OF_FIELDS\t4\nNUMBER_OF_SETS\t2\nBEGIN_DATA_FORMAT\n"
    "SAMPLE_ID\tSPEC_400\tSPEC_410\tSPEC_420\nEND_DATA_FORMAT\nBEGIN_DATA\n"
    "S1\t0.1\t0.2\t0.3\nS2\t0.4\t0.5\t0.6\nEND_DATA\n";

std::string ErrorOf(const std::string& text) {
    try {
        ParseCgats(
            [&] {
                std::vector<std::string> lines;
                std::string line;
                for (char c : text) {
                    if (c == '\n')
                        lines.push_back(line), line.clear();
                    else
                        line += c;
                }
                if (!line.empty()) lines.push_back(line);
                return lines;
            }(),
            "bad.sp");
        return "";
    } catch (const SpectralError& e) {
        return e.what();
    }
}

TEST(Cgats, ReadsColordsTestColourSamples) {
    const CgatsFile file = ReadCgats(ColordDirectory() + "/ref/CIE-TCS.sp");
    ASSERT_EQ(file.sets.size(), 15u);
    const CgatsSet* tcs09 = file.Find("TCS09");
    ASSERT_NE(tcs09, nullptr);
    EXPECT_EQ(tcs09->spectrum.MinWavelength(), 360);
    EXPECT_EQ(tcs09->spectrum.MaxWavelength(), 830);
    EXPECT_EQ(tcs09->spectrum.Size(), 95u);
    EXPECT_DOUBLE_EQ(tcs09->spectrum.Evaluate(360), 0.069);
    EXPECT_DOUBLE_EQ(tcs09->spectrum.Evaluate(830), 0.836);
}

TEST(Cgats, ReadsColordsObserver) {
    const CgatsFile file = ReadCgats(ColordDirectory() + "/cmf/CIE1931-2deg-XYZ.cmf");
    ASSERT_EQ(file.sets.size(), 3u);
    EXPECT_EQ(file.fileType, "CMF");
    EXPECT_DOUBLE_EQ(file.sets[1].spectrum.Evaluate(555), 1.0);  // ȳ peaks at 555 nm
}

TEST(Cgats, RoundTrip) {
    const std::string path = (test::ScratchDir() / "two.sp").string();
    test::WriteFile(path, kSmall);
    const CgatsFile file = ReadCgats(path);
    ASSERT_EQ(file.sets.size(), 2u);
    const std::string copy = (test::ScratchDir() / "copy.sp").string();
    WriteCgats(copy, file);
    const CgatsFile back = ReadCgats(copy);
    ASSERT_EQ(back.sets.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(back.sets[i].sampleId, file.sets[i].sampleId);
        EXPECT_EQ(back.sets[i].spectrum.Values(), file.sets[i].spectrum.Values());
        EXPECT_EQ(back.sets[i].spectrum.Wavelengths(), file.sets[i].spectrum.Wavelengths());
    }
    EXPECT_EQ(back.keywords, file.keywords);
    // And colord's D65, 107 bands, through our writer and back.
    CgatsFile d65 = ReadCgats(ColordDirectory() + "/illuminant/CIE-D65.sp");
    WriteCgats(copy, d65);
    EXPECT_EQ(ReadCgats(copy).sets[0].spectrum.Values(), d65.sets[0].spectrum.Values());
}

TEST(Cgats, BadFilesGiveLocatedErrors) {
    auto replace = [](std::string text, const std::string& from, const std::string& to) {
        return text.replace(text.find(from), from.size(), to);
    };
    struct Case {
        std::string text;
        std::string where;
        std::string words;
    };
    const std::string s(kSmall);
    for (const Case& c : {
             Case{replace(s, "0.5", "0.5x"), "bad.sp:13: error: ", "expected a number"},
             Case{replace(s, "S2\t0.4\t0.5\t0.6\n", "S2\t0.4\t0.5\n"),
                  "bad.sp:13: error: ", "not a whole number of sets"},
             Case{replace(s, "SPECTRAL_BANDS\t3", "SPECTRAL_BANDS\t4"),
                  "bad.sp:5: error: ", "SPECTRAL_BANDS says 4"},
             Case{replace(s, "NUMBER_OF_SETS\t2", "NUMBER_OF_SETS\t3"),
                  "bad.sp:7: error: ", "NUMBER_OF_SETS says 3"},
             Case{replace(s, "SPECTRAL_END_NM\t420", "SPECTRAL_END_NM\t380"),
                  "bad.sp:4: error: ", "SPECTRAL_END_NM must exceed"},
             Case{s.substr(0, s.find("END_DATA\n")), "bad.sp:13: error: ", "truncated"},
             Case{s.substr(0, s.find("END_DATA_FORMAT")), "bad.sp:9: error: ", "truncated"},
             Case{replace(s, "SPEC_410", "SPEC_4x0"), "bad.sp:9: error: ", "wavelength"},
             Case{"SPECT\nDESCRIPTOR x\n", "bad.sp:2: error: ", "no BEGIN_DATA_FORMAT"},
         }) {
        const std::string error = ErrorOf(c.text);
        EXPECT_NE(error.find(c.where), std::string::npos)
            << "want " << c.where << "\ngot " << error;
        EXPECT_NE(error.find(c.words), std::string::npos)
            << "want " << c.words << "\ngot " << error;
    }
}

}  // namespace
}  // namespace gonio::spectral
