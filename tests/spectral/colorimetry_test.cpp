// Colorimetry against published answers: CIE white points from colord's tables, Sharma et al.'s
// 34 CIEDE2000 pairs, the sRGB and Bradford matrices' defining properties.
#include "spectral/colorimetry.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "spectral/named_spectra.h"

namespace gonio::spectral {
namespace {

Eigen::Vector2d WhitePoint(const std::string& name) {
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), ReferenceGrid());
    return Chromaticity(EmissiveXyz(NamedSpectrum(name), observer));
}

// CIE 15:2004 Table T.3 / T.8 (2° observer); tolerance covers the 5 nm abridged sums.
TEST(WhitePoint, MatchesCie15) {
    struct Case {
        const char* name;
        double x, y;
    };
    for (const Case& c : {Case{"D65", 0.3127, 0.3290}, Case{"A", 0.4476, 0.4074},
                          Case{"F2", 0.3721, 0.3751}, Case{"F11", 0.3805, 0.3769}}) {
        const Eigen::Vector2d xy = WhitePoint(c.name);
        EXPECT_NEAR(xy.x(), c.x, 0.002) << c.name;
        EXPECT_NEAR(xy.y(), c.y, 0.002) << c.name;
        ::testing::Test::RecordProperty(std::string("xy_") + c.name,
                                        std::to_string(xy.x()) + " " + std::to_string(xy.y()));
        std::printf("white point %-4s x %.5f y %.5f (CIE 15: %.4f %.4f)\n", c.name, xy.x(), xy.y(),
                    c.x, c.y);
    }
}

TEST(Emissive, IsNormalisedToY100) {
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), ReferenceGrid());
    EXPECT_NEAR(EmissiveXyz(NamedSpectrum("F11"), observer).y(), 100, 1e-9);
}

TEST(Reflectance, PerfectWhiteIsTheIlluminant) {
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), ReferenceGrid());
    const Spectrum d65 = NamedSpectrum("D65");
    const Spectrum white = Spectrum::Regular(300, 530, {1, 1});
    const Xyz xyz = ReflectanceXyz(white, d65, observer);
    const Xyz expected = EmissiveXyz(d65, observer);
    EXPECT_NEAR((xyz - expected).norm(), 0, 1e-9);
}

TEST(Ciede2000, SharmaWuDalal2005Pairs) {
    const std::string path = std::string(GONIO_SHARED_DATA_DIR) + "/ciede2000_pairs.tsv";
    std::ifstream file(path);
    if (!file) GTEST_SKIP() << "no " << path;
    std::string line;
    int pairs = 0;
    double worst = 0;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        int pair = 0;
        Lab lab1, lab2;
        double expected = 0;
        fields >> pair >> lab1[0] >> lab1[1] >> lab1[2] >> lab2[0] >> lab2[1] >> lab2[2] >>
            expected;
        ASSERT_TRUE(fields) << "bad line: " << line;
        const double de = Ciede2000(lab1, lab2);
        EXPECT_NEAR(de, expected, 1e-4) << "pair " << pair;
        EXPECT_NEAR(Ciede2000(lab2, lab1), de, 1e-12) << "pair " << pair << " is symmetric";
        worst = std::max(worst, std::abs(de - expected));
        ++pairs;
    }
    EXPECT_EQ(pairs, 34);
    RecordProperty("max_error", std::to_string(worst));
    std::printf("CIEDE2000: %d pairs, max |error| %.2e\n", pairs, worst);
}

TEST(Lab, WhiteIsL100AndNeutral) {
    const Xyz white(95.047, 100, 108.883);
    const Lab lab = XyzToLab(white, white);
    EXPECT_NEAR(lab[0], 100, 1e-12);
    EXPECT_NEAR(lab[1], 0, 1e-12);
    EXPECT_NEAR(lab[2], 0, 1e-12);
    // CIE 15:2004 eq. 8.1: Y/Yn = 0.18 gives L* = 49.496.
    EXPECT_NEAR(XyzToLab(white * 0.18, white)[0], 49.496, 1e-3);
}

TEST(Srgb, D65WhiteIsOneOneOne) {
    const Rgb rgb = XyzToLinearSrgb(SrgbWhite());
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 1, 2e-3);  // the matrix has 4 decimals
    const Xyz back = LinearSrgbToXyz(rgb);
    EXPECT_NEAR((back - SrgbWhite()).norm(), 0, 1e-12);
}

TEST(Bradford, MapsSourceWhiteToDestinationWhite) {
    const SampledObserver observer = SampleObserver(NamedObserver("CIE1931"), ReferenceGrid());
    const Xyz a = EmissiveXyz(NamedSpectrum("A"), observer) / 100;
    const Xyz adapted = BradfordAdapt(a, a, SrgbWhite());
    EXPECT_NEAR((adapted - SrgbWhite()).norm(), 0, 1e-12);
    const Rgb display = XyzToDisplaySrgb(a, a);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(display[c], 1, 2e-3);
}

}  // namespace
}  // namespace gonio::spectral
