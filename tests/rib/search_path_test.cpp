// Search paths (base/search_path.h): '&' and '@' expansion, and finding a file on the path.

#include "base/search_path.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace gonio {
namespace {

using Folders = std::vector<std::string>;

TEST(SearchPath, SplitsOnColonsAndDropsEmptyEntries) {
    EXPECT_EQ(ExpandSearchPath("a:b::c", {}, {}), (Folders{"a", "b", "c"}));
}

TEST(SearchPath, AmpersandIsThePreviousPathAndAtTheDefault) {
    EXPECT_EQ(ExpandSearchPath("x:&:@", {"p1", "p2"}, {"d"}), (Folders{"x", "p1", "p2", "d"}));
    EXPECT_EQ(ExpandSearchPath("@", {"p"}, {}), Folders{});
}

// Each Option "searchpath" replaces its '&' by the path before it, so a chain of them keeps
// every earlier folder ('&' once meant the default path whatever came before).
TEST(SearchPath, AmpersandChainsThroughSuccessiveRequests) {
    const std::string first = SubstitutePreviousPath("a:&", "@");
    EXPECT_EQ(first, "a:@");
    const std::string second = SubstitutePreviousPath("b:&:c", first);
    EXPECT_EQ(second, "b:a:@:c");
    EXPECT_EQ(ExpandSearchPath(second, {}, {"d"}), (Folders{"b", "a", "d", "c"}));
    EXPECT_EQ(SubstitutePreviousPath("x::y", "p"), "x::y");
}

class FindOnSearchPathTest : public ::testing::Test {
  protected:
    void SetUp() override {
        root_ = std::filesystem::temp_directory_path() /
                ("gonio_search_path_" +
                 std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::create_directories(root_ / "first");
        std::filesystem::create_directories(root_ / "second");
        std::ofstream(root_ / "second" / "x.grd") << "x";
        std::ofstream(root_ / "first" / "both.grd") << "1";
        std::ofstream(root_ / "second" / "both.grd") << "2";
    }
    void TearDown() override { std::filesystem::remove_all(root_); }
    std::string Dir(const char* name) const { return (root_ / name).string(); }

    std::filesystem::path root_;
};

TEST_F(FindOnSearchPathTest, FindsTheFirstFolderThatHasTheFile) {
    EXPECT_EQ(FindOnSearchPath("x.grd", {Dir("first"), Dir("second")}), Dir("second") + "/x.grd");
    EXPECT_EQ(FindOnSearchPath("both.grd", {Dir("first"), Dir("second")}),
              Dir("first") + "/both.grd");
}

TEST_F(FindOnSearchPathTest, MissingFilesAndFoldersGiveNothing) {
    EXPECT_EQ(FindOnSearchPath("none.grd", {Dir("first"), Dir("second")}), "");
    EXPECT_EQ(FindOnSearchPath("x.grd", {Dir("first")}), "");
    EXPECT_EQ(FindOnSearchPath("first", {root_.string()}), "") << "a folder is not a file";
    EXPECT_EQ(FindOnSearchPath("", {Dir("second")}), "");
}

TEST_F(FindOnSearchPathTest, AbsoluteNamesIgnoreThePath) {
    const std::string absolute = Dir("second") + "/x.grd";
    EXPECT_EQ(FindOnSearchPath(absolute, {Dir("first")}), absolute);
    EXPECT_EQ(FindOnSearchPath(Dir("first") + "/x.grd", {Dir("second")}), "");
}

}  // namespace
}  // namespace gonio
