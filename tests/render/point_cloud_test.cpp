// PointCloud and PointCloudStore (renderer/shading/point_cloud*.h): the .ptc bytes round-trip
// and foreign or cut files are refused with a reason, Nearest agrees with a brute-force search,
// and the store writes the same file whatever order the threads baked in.

#include "renderer/shading/point_cloud.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "renderer/shading/point_cloud_store.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio {
namespace {

PointCloud Cloud(int count, uint32_t seed) {
    PointCloud cloud;
    cloud.AddChannel("_c", 3);
    cloud.AddChannel("_area", 1);
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(-1, 1);
    for (int i = 0; i < count; ++i) {
        const Imath::V3f P(uniform(random), uniform(random), uniform(random));
        const float values[4] = {float(i), P.x * 2, P.y * 3, 0.5f};
        cloud.Add(P, Imath::V3f(0, 0, 1), values);
    }
    return cloud;
}

TEST(PointCloud, BytesRoundTrip) {
    const PointCloud cloud = Cloud(50, 1);
    PointCloud read;
    std::string why;
    ASSERT_TRUE(read.Parse(cloud.Serialize(), &why)) << why;
    ASSERT_EQ(read.Size(), 50u);
    ASSERT_EQ(read.ValueWidth(), 4);
    EXPECT_EQ(read.FindChannel("_area")->offset, 3);
    for (size_t i = 0; i < read.Size(); ++i) {
        EXPECT_EQ(read.Position(i), cloud.Position(i));
        for (int k = 0; k < 4; ++k) EXPECT_EQ(read.Values(i)[k], cloud.Values(i)[k]);
    }
    EXPECT_EQ(read.Serialize(), cloud.Serialize());
}

TEST(PointCloud, ForeignAndCutFilesAreRefused) {
    const std::string bytes = Cloud(10, 2).Serialize();
    PointCloud read;
    std::string why;
    EXPECT_FALSE(read.Parse("GONIOGRD" + bytes.substr(8), &why));
    EXPECT_EQ(why, "not a gonio point cloud (no GONIOPTC magic)");
    EXPECT_FALSE(read.Parse(bytes.substr(0, bytes.size() - 3), &why));
    EXPECT_NE(why.find("bytes of points, not 10 points of 40"), std::string::npos) << why;
    EXPECT_FALSE(read.Parse(bytes.substr(0, 20), &why));
    EXPECT_EQ(read.Size(), 0u) << "a refused file leaves an empty cloud";
}

TEST(PointCloud, NearestAgreesWithBruteForce) {
    PointCloud cloud = Cloud(2000, 3);
    cloud.BuildIndex();
    std::mt19937 random(4);
    std::uniform_real_distribution<float> uniform(-1.2f, 1.2f);
    for (int q = 0; q < 500; ++q) {
        const Imath::V3f P(uniform(random), uniform(random), uniform(random));
        long best = -1;
        float bestDistance2 = INFINITY;
        for (size_t i = 0; i < cloud.Size(); ++i) {
            const float d2 = (cloud.Position(i) - P).length2();
            if (d2 < bestDistance2) bestDistance2 = d2, best = long(i);
        }
        EXPECT_EQ(cloud.Nearest(P), best) << q;
    }
    EXPECT_EQ(cloud.Nearest(cloud.Position(17)), 17) << "a baked point finds itself";
    PointCloud empty;
    empty.BuildIndex();
    EXPECT_EQ(empty.Nearest(Imath::V3f(0)), -1);
}

std::string ReadAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// Two "threads" bake halves of the same points in either order: the files are identical.
TEST(PointCloudStore, WrittenFileDoesNotDependOnBakeOrder) {
    const PointCloud all = Cloud(40, 5);
    auto half = [&](int which) {
        PointCloud part;
        for (const auto& c : all.Channels()) part.AddChannel(c.name, c.width);
        for (size_t i = 0; i < all.Size(); ++i)
            if (int(i % 2) == which) part.Add(all.Position(i), all.Normal(i), all.Values(i));
        return part;
    };
    const std::string dir =
        std::filesystem::temp_directory_path() / ("gonio_ptc_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string a = dir + "/a.ptc", b = dir + "/b.ptc";
    test::CapturedDiagnostics d;
    PointCloudStore store;
    std::string why;
    ASSERT_TRUE(store.Bake(a, half(0), &why)) << why;
    ASSERT_TRUE(store.Bake(a, half(1), &why)) << why;
    ASSERT_TRUE(store.Bake(b, half(1), &why)) << why;
    ASSERT_TRUE(store.Bake(b, half(0), &why)) << why;
    ASSERT_TRUE(store.WriteBaked(d.Get())) << d.Text();
    const std::string bytesA = ReadAll(a);
    EXPECT_EQ(bytesA, ReadAll(b));
    PointCloud read;
    ASSERT_TRUE(read.Parse(bytesA, &why)) << why;
    EXPECT_EQ(read.Size(), 40u);

    PointCloud other;
    other.AddChannel("_c", 1);
    EXPECT_FALSE(store.Bake(a, half(0), &why) && store.Bake(a, other, &why));
    EXPECT_EQ(why, "its channels were _c[3], _area[1] at its first bake, here _c[1]");

    const PointCloud* loaded = store.Load(a, &why);
    ASSERT_TRUE(loaded) << why;
    EXPECT_EQ(loaded->Nearest(all.Position(3)) >= 0, true);
    EXPECT_FALSE(store.Load(dir + "/missing.ptc", &why));
    EXPECT_EQ(why, "cannot be read");
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace gonio
