// Photon-map files: round trip, streaming, the header's traced paths, and clear rejection of
// malformed input with file and line; synthetic maps are deterministic whatever the threads.
#include "brdfsim/photon_map.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "brdfsim/synth.h"
#include "test_util.h"

namespace gonio {
namespace {

using test::TempPath;

void WriteText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string ErrorOf(const std::string& text) {
    const std::string path = TempPath("bad.pm");
    WriteText(path, text);
    try {
        ReadPhotonMap(path);
    } catch (const PhotonMapError& e) {
        return e.what();
    }
    return "";
}

TEST(PhotonMap, ReadsTheThesisFormat) {
    const std::string path = TempPath("thesis.pm");
    WriteText(path, "2\n0.5 0 0.7 3.1 0.159 0.2 0.3 0.4\n1.0 1.5 0.2 0.1 0.159 1 1 1\n");
    const PhotonMap map = ReadPhotonMap(path);
    ASSERT_EQ(map.Size(), 2u);
    EXPECT_EQ(map.ncomps, 3);
    EXPECT_EQ(map.paths, 2u);
    EXPECT_FLOAT_EQ(map.Row(0)[kPhiOut], 3.1f);
    EXPECT_FLOAT_EQ(map.Row(1)[kFirstColour + 2], 1.0f);
}

TEST(PhotonMap, HeaderMayCountTracedPaths) {
    const std::string path = TempPath("paths.pm");
    WriteText(path, "1 10\n0.5 0 0.7 3.1 0.159 0.2\n");
    EXPECT_EQ(ReadPhotonMap(path).paths, 10u);
}

TEST(PhotonMap, WriteReadRoundTripIsExact) {
    SynthOptions options;
    options.paths = 5000;
    const PhotonMap map = SynthesizePhotonMap(AnalyticBrdf::Parse("phong:0.2,0.8,10"), options);
    const std::string path = TempPath("roundtrip.pm");
    WritePhotonMap(path, map);
    const PhotonMap back = ReadPhotonMap(path);
    EXPECT_EQ(back.paths, map.paths);
    EXPECT_EQ(back.ncomps, map.ncomps);
    EXPECT_EQ(back.rows, map.rows);  // shortest round-trip float text
}

TEST(PhotonMap, StreamsInBatches) {
    SynthOptions options;
    options.paths = 300000;
    options.ncomps = 1;
    const std::string path = TempPath("stream.pm");
    const PhotonMapHeader header =
        WriteSyntheticPhotonMap(AnalyticBrdf::Parse("lambert:0.5"), options, path);
    PhotonMapReader reader(path);
    std::vector<float> rows;
    std::size_t photons = 0;
    int batches = 0;
    while (true) {
        rows.clear();
        const bool more = reader.ReadBatch(50000, rows);
        photons += rows.size() / 6;
        ++batches;
        EXPECT_LE(rows.size() / 6, 50000u + 200000u);  // about one 8 MB chunk at most beyond
        if (!more) break;
    }
    EXPECT_EQ(photons, header.count);
    EXPECT_GT(batches, 1);
}

TEST(PhotonMap, RejectsMalformedFilesWithLineNumbers) {
    EXPECT_NE(ErrorOf("").find("first line"), std::string::npos);
    EXPECT_NE(ErrorOf("Declare \"x\"\n").find(":1: expected the photon count"), std::string::npos);
    EXPECT_NE(ErrorOf("3\n0.5 0 0.7 3.1 0.1 1\n0.5 0 0.7 3.1 0.1 1\n").find("truncated"),
              std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 3.1 0.1 1\n0.5 0 0.7 3.1 0.1 1\n").find("more photon lines"),
              std::string::npos);
    const std::string wrongCount = ErrorOf("2\n0.5 0 0.7 3.1 0.1 1 1\n0.5 0 0.7 3.1 0.1 1\n");
    EXPECT_NE(wrongCount.find(":3: expected 7 values"), std::string::npos) << wrongCount;
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 x 0.1 1\n").find(":2: expected numbers"), std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 3 0 1\n").find("probability density in [1e-12, 1e12]"),
              std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 3 1e-38 1\n").find("probability density"), std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 1e30 0.1 1\n").find("phi_in and phi_out"), std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 3 0.1 -1e30\n").find("energies within"), std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 2.0 3 0.1 1\n").find("theta_out"), std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 3 0.1 nan\n").find("finite"), std::string::npos);
    EXPECT_NE(ErrorOf("1\n0.5 0 0.7 3 0.1\n").find("at least one colour"), std::string::npos);
    EXPECT_NE(ErrorOf("1 0\n").find("traced paths"), std::string::npos);
}

// The bounce tag (docs/formats.md): the word on line 1, one more integer per line, kept apart
// from the rows; untagged maps read as before, and a tag that is no count is located.
TEST(PhotonMap, BounceTagsRoundTripApartFromTheRows) {
    const std::string path = TempPath("tagged.pm");
    WriteText(path,
              "2 5 bounces\n0.5 0 0.7 3.1 0.159 0.2 0.3 0.4 1\n1.0 1.5 0.2 0.1 0.159 1 1 1 7\n");
    const PhotonMap map = ReadPhotonMap(path);
    ASSERT_EQ(map.Size(), 2u);
    EXPECT_EQ(map.ncomps, 3);
    EXPECT_EQ(map.paths, 5u);
    EXPECT_FLOAT_EQ(map.Row(1)[kFirstColour + 2], 1.0f);
    EXPECT_EQ(map.bounces, (std::vector<std::uint16_t>{1, 7}));
    EXPECT_TRUE(ReadPhotonMapHeader(path).bounces);
    const std::string again = TempPath("tagged2.pm");
    WritePhotonMap(again, map);
    std::ifstream in(again);
    std::string first, second;
    std::getline(in, first);
    std::getline(in, second);
    EXPECT_EQ(first, "2 5 bounces");
    EXPECT_EQ(second, "0.5 0 0.7 3.1 0.159 0.2 0.3 0.4 1");
    EXPECT_NE(
        ErrorOf("1 1 bounces\n0.5 0 0.7 3.1 0.159 0.2 1.5\n").find(":2: expected a bounce count"),
        std::string::npos);
    EXPECT_NE(ErrorOf("1 1 bounces\n0.5 0 0.7 3.1 0.159 2\n").find(":2: expected theta_in"),
              std::string::npos);
    EXPECT_NE(ErrorOf("1 1 bouncy\n0.5 0 0.7 3.1 0.159 2\n").find(":1: expected the photon count"),
              std::string::npos);
    // untagged: the last value is a colour
    WriteText(path, "1\n0.5 0 0.7 3.1 0.159 0.2 1\n");
    const PhotonMap plain = ReadPhotonMap(path);
    EXPECT_EQ(plain.ncomps, 2);
    EXPECT_TRUE(plain.bounces.empty());
}

TEST(PhotonMap, MissingFileIsAnIoError) {
    EXPECT_THROW(ReadPhotonMap(TempPath("does-not-exist.pm")), PhotonMapIoError);
}

TEST(PhotonMap, WriterLeavesNoPartialFile) {
    const std::string path = TempPath("partial.pm");
    std::remove(path.c_str());
    {
        PhotonMapWriter writer(path, {2, 2}, 1);
        const float row[6] = {0.1f, 0, 0.2f, 0, 0.1f, 1};
        writer.Append(row);
        EXPECT_THROW(writer.Close(), PhotonMapError);  // announced 2, wrote 1
    }
    EXPECT_FALSE(std::ifstream(path).good());
}

TEST(Synth, SameMapWhateverTheThreadCount) {
    SynthOptions options;
    options.paths = 20000;
    options.seed = 5;
    const AnalyticBrdf phong = AnalyticBrdf::Parse("phong:0.3,0.7,25");
    PhotonMap one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = SynthesizePhotonMap(phong, options);
    }
    two = SynthesizePhotonMap(phong, options);
    EXPECT_EQ(one.rows, two.rows);
    options.seed = 6;
    EXPECT_NE(SynthesizePhotonMap(phong, options).rows, one.rows);
}

TEST(Synth, PhotonsCarryTheAlbedo) {
    // (1/N) Σ β / p_in over the hemisphere of incidence is 2π × the mean albedo.
    SynthOptions options;
    options.paths = 200000;
    options.ncomps = 1;
    const PhotonMap map = SynthesizePhotonMap(AnalyticBrdf::Parse("lambert:0.5"), options);
    double sum = 0;
    for (std::size_t i = 0; i < map.Size(); ++i) sum += map.Row(i)[5] / map.Row(i)[4];
    EXPECT_NEAR(sum / map.paths / (2 * 3.14159265358979), 0.5, 0.005);
}

TEST(AnalyticBrdf, NormalisedPhongAlbedoMatchesDesignTable) {
    const double deg = 3.14159265358979 / 180;
    const AnalyticBrdf n10 = AnalyticBrdf::Parse("phong:0,1,10");
    EXPECT_NEAR(n10.Albedo(0), 1.0, 1e-3);
    EXPECT_NEAR(n10.Albedo(30 * deg), 0.8660, 1e-3);
    EXPECT_NEAR(n10.Albedo(60 * deg), 0.5047, 1e-3);
    EXPECT_NEAR(n10.Albedo(85 * deg), 0.1713, 1e-3);
    const AnalyticBrdf n1 = AnalyticBrdf::Parse("phong:0,1,1");
    EXPECT_NEAR(n1.Albedo(30 * deg), 0.8808, 1e-3);
    EXPECT_NEAR(n1.Albedo(60 * deg), 0.6090, 1e-3);
    EXPECT_NEAR(n1.Albedo(85 * deg), 0.3631, 1e-3);
    EXPECT_THROW(AnalyticBrdf::Parse("phong:1,2"), std::invalid_argument);
    EXPECT_THROW(AnalyticBrdf::Parse("lambert:x"), std::invalid_argument);
}

}  // namespace
}  // namespace gonio
