// The conformance scenes of ../shared/conformance (Aqsis regression RIBs) parse without errors.

#include <gtest/gtest.h>

#include "rib_test_util.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

// The scenes and their top-level RIB files, from the suite's index.tsv (scene, rib, ...).
std::vector<std::pair<std::string, std::string>> Scenes(const fs::path& index) {
    std::vector<std::pair<std::string, std::string>> scenes;
    std::ifstream in(index);
    std::string line;
    std::getline(in, line);  // the header
    while (std::getline(in, line)) {
        const std::size_t tab1 = line.find('\t'), tab2 = line.find('\t', tab1 + 1);
        if (tab2 != std::string::npos)
            scenes.emplace_back(line.substr(0, tab1), line.substr(tab1 + 1, tab2 - tab1 - 1));
    }
    return scenes;
}

TEST(Conformance, EverySceneParses) {
    const fs::path root = GONIO_CONFORMANCE_DIR;
    if (!fs::exists(root / "index.tsv")) GTEST_SKIP() << "no " << root;
    const auto scenes = Scenes(root / "index.tsv");
    // The index names every scene the suite ships, and nothing else.
    std::size_t folders = 0;
    for (const auto& entry : fs::directory_iterator(root / "scenes"))
        folders += entry.is_directory();
    EXPECT_EQ(scenes.size(), folders);
    EXPECT_GE(scenes.size(), 40u) << "the index lost most of its scenes";
    for (const auto& [scene, rib] : scenes) {
        const fs::path path = root / "scenes" / scene / rib;
        const ParseResult result = ParseFile(path.string());
        EXPECT_FALSE(result.target.calls.empty()) << path;
        if (scene.rfind("Camera_", 0) == 0) {
            // These two scenes read camera and scene archives that the suite does not ship
            // (Aqsis rendered them without); those two errors are the only ones.
            EXPECT_EQ(result.errors, 2) << result.messages;
            EXPECT_EQ(result.messages.find("error: cannot find archive \"cameras/"),
                      result.messages.find("error:"))
                << result.messages;
        } else {
            EXPECT_TRUE(result.ok) << path << "\n" << result.messages;
        }
    }
}

}  // namespace
}  // namespace gonio
