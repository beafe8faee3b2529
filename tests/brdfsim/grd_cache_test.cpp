// GrdCache: one load per file shared by every caller and thread, and a remembered error for a
// file that cannot be used.
#include "brdfsim/grd_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "test_util.h"

namespace gonio {
namespace {

std::string WriteSmallGrid() {
    const std::string path = test::TempPath("cached.grd");
    auto splats = test::SyntheticSplats("lambert:0.5", 2000, true, false, 0.5, Norm::kL2,
                                        Horizon::kReflect, 1);
    const BrdfIsoGrid grid(splats, 2, 4);
    WriteGrd(path, *splats, 2, 4, grid.Lists(), nullptr);
    return path;
}

TEST(GrdCache, LoadsAFileOnceForAllThreads) {
    const std::string path = WriteSmallGrid();
    GrdCache cache;
    std::vector<std::shared_ptr<const GrdFile>> got(4);
    std::vector<std::thread> threads;
    for (size_t t = 0; t < got.size(); ++t) {
        threads.emplace_back([&, t] {
            std::string error;
            got[t] = cache.Get(path, &error);
        });
    }
    for (std::thread& t : threads) t.join();
    ASSERT_NE(got[0], nullptr);
    for (const auto& file : got) EXPECT_EQ(file.get(), got[0].get());
    // Still served from memory after the file is gone.
    std::remove(path.c_str());
    std::string error;
    EXPECT_EQ(cache.Get(path, &error).get(), got[0].get());
    EXPECT_EQ(error, "");
}

TEST(GrdCache, RemembersWhyAFileCannotBeUsed) {
    const std::string path = test::TempPath("foreign.grd");
    std::ofstream(path) << "not a grid";
    GrdCache cache;
    std::string error;
    EXPECT_EQ(cache.Get(path, &error), nullptr);
    EXPECT_NE(error.find(path), std::string::npos) << error;
    // A later fix of the file does not matter within the run: the answer is the same.
    std::filesystem::copy_file(WriteSmallGrid(), path,
                               std::filesystem::copy_options::overwrite_existing);
    std::string again;
    EXPECT_EQ(cache.Get(path, &again), nullptr);
    EXPECT_EQ(again, error);
}

TEST(GrdCache, MissingFileIsAnError) {
    GrdCache cache;
    std::string error;
    EXPECT_EQ(cache.Get(test::TempPath("missing.grd"), &error), nullptr);
    EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
}

}  // namespace
}  // namespace gonio
