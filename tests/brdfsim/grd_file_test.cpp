// .grd files: bit-exact round trips, the baked table, and clear rejection of truncated, corrupt
// and foreign files.
#include "brdfsim/grd_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "brdfsim/baked_table.h"
#include "test_util.h"

namespace gonio {
namespace {

using test::TempPath;

std::string Slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void Spit(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

struct Written {
    std::string path;
    std::shared_ptr<SplatSet> splats;
};

// An isotropic grid with a baked table, written once for all tests here.
const Written& IsoFile() {
    static const Written written = [] {
        Written w{TempPath("iso.grd"), test::SyntheticSplats("phong:0.3,0.7,10", 20000, true, false,
                                                             0.3, Norm::kL2, Horizon::kReflect, 3)};
        const BrdfIsoGrid grid(w.splats, 4, 9);
        const BakedTable baked(grid, 12);
        WriteGrd(w.path, *w.splats, 4, 9, grid.Lists(), &baked);
        return w;
    }();
    return written;
}

std::string GrdErrorOf(const std::string& bytes) {
    const std::string path = TempPath("bad.grd");
    Spit(path, bytes);
    try {
        ReadGrd(path);
    } catch (const GrdError& e) {
        return e.what();
    }
    return "";
}

TEST(GrdFile, RoundTripIsBitExact) {
    const GrdFile file = ReadGrd(IsoFile().path);
    const std::string again = TempPath("iso-again.grd");
    WriteGrd(again, *file.splats, file.rings, file.rects, file.Lists(), file.baked.get());
    EXPECT_EQ(Slurp(again), Slurp(IsoFile().path));

    const BrdfIsoGrid original(IsoFile().splats, 4, 9);
    for (double ti : {0.0, 20.0, 50.0, 85.0}) {
        for (double to : {0.0, 35.0, 80.0}) {
            float a[3], b[3];
            original.EvalAngles(ti * kDegree, 0.4, to * kDegree, 2.0, a);
            file.grid->EvalAngles(ti * kDegree, 0.4, to * kDegree, 2.0, b);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(a[c], b[c]);
        }
    }
}

TEST(GrdFile, AnisotropicRoundTrip) {
    auto splats = test::SyntheticSplats("lambert:0.5", 5000, false, false, 0.5, Norm::kL1);
    const BrdfGrid grid(splats, 3, 7);
    const std::string path = TempPath("aniso.grd");
    WriteGrd(path, *splats, 3, 7, grid.Lists(), nullptr);
    const GrdFile file = ReadGrd(path);
    EXPECT_FALSE(file.IsIsotropic());
    EXPECT_EQ(file.baked, nullptr);
    EXPECT_EQ(file.splats->Params().norm, Norm::kL1);
    EXPECT_EQ(file.Lists().entries, grid.Lists().entries);
    float a[1], b[1];
    grid.EvalAngles(0.3, 1.0, 0.7, 4.0, a);
    file.grid->EvalAngles(0.3, 1.0, 0.7, 4.0, b);
    EXPECT_EQ(a[0], b[0]);
}

TEST(GrdFile, BakedTableInterpolatesTheGrid) {
    const GrdFile file = ReadGrd(IsoFile().path);
    ASSERT_NE(file.baked, nullptr);
    EXPECT_EQ(&file.Fastest(), file.baked.get());
    // At a node the table holds the grid's value; between nodes it interpolates.
    float grid[3], baked[3];
    const double node = 0.5 * kPi * 4 / 11;  // θ node 4 of 12
    file.grid->EvalAngles(node, 0, node, kPi, grid);
    file.baked->EvalAngles(node, 0, node, kPi, baked);
    EXPECT_NEAR(baked[0], grid[0], 1e-5 * grid[0]);
    double worst = 0;
    for (double ti = 5; ti < 80; ti += 7) {
        for (double to = 5; to < 80; to += 7) {
            file.grid->EvalAngles(ti * kDegree, 0, to * kDegree, 1.0, grid);
            file.baked->EvalAngles(ti * kDegree, 0, to * kDegree, 1.0, baked);
            worst = std::max<double>(worst, std::abs(baked[0] - grid[0]) / grid[0]);
        }
    }
    EXPECT_LT(worst, 0.15);  // a 12-node table on a lobe of exponent 10 smoothed with R = 0.3
}

TEST(GrdFile, RejectsForeignFiles) {
    EXPECT_NE(GrdErrorOf("100\n0.5 0 0.7 3.1 0.159 1 1 1\n").find("not a .grd file"),
              std::string::npos);
    EXPECT_NE(GrdErrorOf("").find("truncated"), std::string::npos);
    std::string bytes = Slurp(IsoFile().path);
    bytes[8] = 99;  // version
    EXPECT_NE(GrdErrorOf(bytes).find("unsupported .grd version 99"), std::string::npos);
    EXPECT_THROW(ReadGrd(TempPath("missing.grd")), GrdIoError);
}

TEST(GrdFile, RejectsTruncatedFilesAtAnyLength) {
    const std::string bytes = Slurp(IsoFile().path);
    for (std::size_t length :
         {std::size_t(4), std::size_t(12), std::size_t(40), std::size_t(80), bytes.size() / 3,
          bytes.size() / 2, bytes.size() - 20, bytes.size() - 1}) {
        const std::string message = GrdErrorOf(bytes.substr(0, length));
        EXPECT_FALSE(message.empty()) << length;
        EXPECT_TRUE(message.find("truncated") != std::string::npos ||
                    message.find("checksum") != std::string::npos ||
                    message.find("count") != std::string::npos)
            << length << ": " << message;
    }
    EXPECT_NE(GrdErrorOf(bytes + "x").find("trailing"), std::string::npos);
}

TEST(GrdFile, RejectsCorruptFiles) {
    std::string bytes = Slurp(IsoFile().path);
    bytes[bytes.size() / 2] ^= 0x40;  // inside the splats or lists
    const std::string message = GrdErrorOf(bytes);
    EXPECT_FALSE(message.empty());
    std::string huge = Slurp(IsoFile().path);
    huge[80] = static_cast<char>(0xff);  // the splat count: more than the file can hold
    EXPECT_FALSE(GrdErrorOf(huge).empty());
}

}  // namespace
}  // namespace gonio
