// Procedural and TrimCurve in the scene builder: a DelayedReadArchive whose bound lies outside the
// viewing frustum is not read but recorded, by a key that names its place and its world bound,
// and read when a later reading expands that key, one inside is read; a RunProgram procedural's
// primitives join the frame inside an attribute block of their own; the program is told the bound's
// raster area; TrimCurve reaches the NuPatches of its attribute block and nothing else.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "renderer/rib/rib_parser.h"
#include "renderer/scene/scene_builder.h"
#include "tests/support/captured_diagnostics.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

struct Built {
    std::string messages;
    std::vector<Frame> frames;
};

Built BuildFile(const fs::path& path, const SceneBuilder::LazyExpansion* expansion = nullptr) {
    Built result;
    test::CapturedDiagnostics captured;
    {
        Diagnostics& diagnostics = captured.Get();
        SceneBuilder builder(path.string(), diagnostics,
                             [&](const Frame& frame) { result.frames.push_back(frame); });
        if (expansion) builder.SetLazyExpansion(0, *expansion);
        ParseRibFile(path.string(), builder, diagnostics);
        builder.Finish(FileLoc{std::make_shared<const std::string>(path.string()), 0, 0});
    }
    result.messages = captured.Text();
    return result;
}

fs::path Folder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("gonio_scene_procedural_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

void Write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// An orthographic camera over [-2,2]² at 128x128 pixels (32 per unit), 5 units from the origin.
const char* kCamera =
    "Format 128 128 1\nProjection \"orthographic\"\nScreenWindow -2 2 -2 2\nTranslate 0 0 5\n";

TEST(ProceduralBuild, DelayedReadArchiveIsReadOnlyWhenItsBoundIsInView) {
    const fs::path dir = Folder("frustum");
    Write(dir / "broken.rib", "Sphere 1 -1\n");
    Write(dir / "good.rib", "Sphere 0.5 -0.5 0.5 360\n");
    const std::string beside = "[2.5 3 -0.5 0.5 -0.5 0.5]", behind = "[-1 1 -1 1 -9 -6]",
                      far = "[-1 1 -1 1 50 60]", inView = "[1.5 2.5 -0.5 0.5 -0.5 0.5]";
    Write(dir / "scene.rib",
          std::string(kCamera) + "Clipping 0.1 20\nWorldBegin\n" +
              "Procedural \"DelayedReadArchive\" [\"broken.rib\"] " + beside + "\n" +
              "Procedural \"DelayedReadArchive\" [\"broken.rib\"] " + behind + "\n" +
              "Procedural \"DelayedReadArchive\" [\"broken.rib\"] " + far + "\n" +
              "Procedural \"DelayedReadArchive\" [\"good.rib\"] " + inView + "\n" +
              "Procedural \"DelayedReadArchive\" [\"broken.rib\"] " + inView + "\nWorldEnd\n");
    const Built built = BuildFile(dir / "scene.rib");
    // Only the last broken archive, in view, was read.
    EXPECT_EQ(
        built.messages.rfind((dir / "broken.rib").string() + ":1:1: error: Sphere expects", 0), 0u)
        << built.messages;
    EXPECT_EQ(std::count(built.messages.begin(), built.messages.end(), '\n'), 1) << built.messages;
    ASSERT_EQ(built.frames.size(), 1u);
    EXPECT_EQ(built.frames[0].shapes.size(), 1u);
}

TEST(ProceduralBuild, ArchivesOutOfViewAreRecordedByKeyAndReadWhenExpanded) {
    const fs::path dir = Folder("lazy");
    Write(dir / "outer.rib",
          "Procedural \"DelayedReadArchive\" [\"inner.rib\"] [10 11 -1 1 -1 1]\n"
          "Sphere 0.5 -0.5 0.5 360\n");
    Write(dir / "inner.rib", "Sphere 1 -1\n");
    Write(dir / "scene.rib", std::string(kCamera) +
                                 "WorldBegin\nSphere 0.5 -0.5 0.5 360\nTranslate 3.5 0 0\n"
                                 "Procedural \"DelayedReadArchive\" [\"outer.rib\"] "
                                 "[-1 1 -1 1 -1 1]\nWorldEnd\n");
    auto lazyOf = [](const Built& built) {
        EXPECT_EQ(built.frames.size(), 1u);
        return built.frames.empty() ? std::vector<LazyProcedural>{}
                                    : built.frames[0].lazyProcedurals.All();
    };
    // Beside the view (x in [2.5, 4.5] against [-2, 2]): recorded with its bound in world space.
    const Built first = BuildFile(dir / "scene.rib");
    EXPECT_EQ(first.messages, "");
    std::vector<LazyProcedural> lazy = lazyOf(first);
    ASSERT_EQ(lazy.size(), 1u);
    EXPECT_EQ(lazy[0].key, "0");
    EXPECT_EQ(lazy[0].worldBound, Box3f(V3f(2.5f, -1, -1), V3f(4.5f, 1, 1)));
    // Expanded: its sphere joins the frame, and its own archive, also out of view, is "0/0".
    SceneBuilder::LazyExpansion expansion;
    expansion.keys = {"0"};
    const Built second = BuildFile(dir / "scene.rib", &expansion);
    EXPECT_EQ(second.frames[0].shapes.size(), 2u);
    lazy = lazyOf(second);
    ASSERT_EQ(lazy.size(), 1u);
    EXPECT_EQ(lazy[0].key, "0/0");
    EXPECT_EQ(lazy[0].worldBound, Box3f(V3f(13.5f, -1, -1), V3f(14.5f, 1, 1)));
    // Both expanded, "0/0" for the first time: its error goes to `report` as well.
    test::CapturedDiagnostics report;
    expansion.keys = {"0", "0/0"};
    expansion.firstRead = {"0/0"};
    expansion.report = &report.Get();
    const Built third = BuildFile(dir / "scene.rib", &expansion);
    EXPECT_TRUE(lazyOf(third).empty());
    const std::string reported = report.Text();
    EXPECT_EQ(reported.rfind((dir / "inner.rib").string() + ":1:1: error: Sphere expects", 0), 0u)
        << reported;
    EXPECT_EQ(std::count(reported.begin(), reported.end(), '\n'), 1) << reported;
}

TEST(ProceduralBuild, RunProgramPrimitivesComeInAnAttributeBlockOfTheirOwn) {
    const fs::path dir = Folder("runprogram");
    Write(dir / "gen.sh",
          "#!/bin/sh\nread detail data\necho \"$detail\" > \"$(dirname \"$0\")/detail.txt\"\n"
          "printf 'Translate %s 0 0\\nSphere 0.5 -0.5 0.5 360\\n\\377' \"$data\"\n");
    fs::permissions(dir / "gen.sh", fs::perms::owner_all);
    Write(dir / "scene.rib", std::string(kCamera) +
                                 "WorldBegin\nProcedural \"RunProgram\" [\"gen.sh\" \"1.25\"] "
                                 "[0.5 1.5 -0.5 0.5 -0.5 0.5]\nSphere 1 -1 1 360\nWorldEnd\n");
    const Built built = BuildFile(dir / "scene.rib");
    EXPECT_EQ(built.messages, "");
    ASSERT_EQ(built.frames.size(), 1u);
    const std::vector<SceneShape>& shapes = built.frames[0].shapes;
    ASSERT_EQ(shapes.size(), 2u);
    // The program's Translate moved its own sphere only.
    EXPECT_EQ(shapes[0].worldFromObject.translation(), Imath::V3f(1.25f, 0, 0));
    EXPECT_EQ(shapes[1].worldFromObject.translation(), Imath::V3f(0, 0, 0));
    // The bound spans 1 x 1 units: 32 x 32 raster pixels.
    std::ifstream detail(dir / "detail.txt");
    float told = 0;
    detail >> told;
    EXPECT_FLOAT_EQ(told, 1024);
}

TEST(ProceduralBuild, TrimCurveReachesTheNuPatchesOfItsBlockOnly) {
    const fs::path dir = Folder("trim");
    const std::string square =
        "NuPatch 2 2 [0 0 1 1] 0 1 2 2 [0 0 1 1] 0 1 \"P\" [-1 -1 0 1 -1 0 -1 1 0 1 1 0]\n";
    Write(dir / "scene.rib", std::string(kCamera) +
                                 "WorldBegin\nAttributeBegin\nTrimCurve [1] [2] [0 0 1 2 3 3] "
                                 "[0] [3] [4] [0.2 0.8 0.2 0.2] [0.2 0.2 0.8 0.2] [1 1 1 1]\n" +
                                 square + "Polygon \"P\" [0 0 0 1 0 0 1 1 0]\nAttributeEnd\n" +
                                 square + "WorldEnd\n");
    const Built built = BuildFile(dir / "scene.rib");
    EXPECT_EQ(built.messages, "");
    ASSERT_EQ(built.frames.size(), 1u);
    const std::vector<SceneShape>& shapes = built.frames[0].shapes;
    ASSERT_EQ(shapes.size(), 3u);
    ASSERT_TRUE(shapes[0].trim);
    EXPECT_TRUE(shapes[0].trim->Contains(Imath::V2f(0.4f, 0.3f)));   // inside the triangle
    EXPECT_FALSE(shapes[0].trim->Contains(Imath::V2f(0.7f, 0.7f)));  // beyond its hypotenuse
    EXPECT_FALSE(shapes[1].trim) << "a Polygon is not trimmed";
    EXPECT_FALSE(shapes[2].trim) << "TrimCurve is an attribute: it ends with AttributeEnd";
}

}  // namespace
}  // namespace gonio
