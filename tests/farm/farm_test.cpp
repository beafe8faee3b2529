// The farm library without a cluster: shard ranges, planning, the manifest's round trip and its
// errors, output checks, and tile joining (exact, with gaps and overlaps named).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "base/shard_range.h"
#include "brdfsim/photon_map.h"
#include "farm/assemble.h"
#include "farm/manifest.h"
#include "farm/planner.h"
#include "farm/task_output.h"
#include "farm/tile_join.h"
#include "imageio/image_formats.h"
#include "imageio/oiio_plugin.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

std::string TempDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("gonio_farm_test_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

void WriteText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(ShardRange, ShardsCoverTheRangeExactlyAndEvenly) {
    for (uint64_t total : {0ull, 1ull, 15ull, 16ull, 100000ull, 999999937ull}) {
        for (uint64_t shards : {1ull, 2ull, 3ull, 16ull, 1000ull}) {
            uint64_t next = 0, least = UINT64_MAX, most = 0;
            for (uint64_t s = 0; s < shards; ++s) {
                const ShardRange r = ShardOf(total, s, shards);
                EXPECT_EQ(r.first, next) << total << " in " << shards;
                next = r.first + r.count;
                least = std::min(least, r.count), most = std::max(most, r.count);
            }
            EXPECT_EQ(next, total);
            EXPECT_LE(most - least, 1u);
        }
    }
    // 10^18 paths in 16 shards: total·s does not fit 64 bits, the split must still be exact.
    const uint64_t huge = 1000000000000000000ull;
    EXPECT_EQ(ShardOf(huge, 15, 16).first + ShardOf(huge, 15, 16).count, huge);
    EXPECT_EQ(ShardOf(huge, 8, 16).first, huge / 2);
}

PlanRequest Request() {
    PlanRequest r;
    r.scene = "/scenes/x.rib";
    r.gonio = "/bin/gonio";
    return r;
}

TEST(Planner, ShardsCountEveryPathOnceAndMergeInOrder) {
    PlanRequest r = Request();
    r.photonShards = 16;
    r.brdf = {"iopt", "8", "24", "0.5", "0"};
    const FarmManifest m = PlanJob(r, {{0, true, 100003, "x.pm"}});
    ASSERT_EQ(m.tasks.size(), 16u);
    ASSERT_EQ(m.merges.size(), 1u);
    uint64_t paths = 0;
    for (size_t i = 0; i < m.tasks.size(); ++i) {
        EXPECT_EQ(m.tasks[i].kind, TaskKind::kShard);
        EXPECT_EQ(m.merges[0].shards[i], int(i));
        paths += m.tasks[i].paths;
        const std::vector<std::string>& a = m.tasks[i].args;
        EXPECT_EQ(a[a.size() - 1], std::to_string(i) + "/16");
    }
    EXPECT_EQ(paths, 100003u);
    EXPECT_EQ(m.merges[0].brdfOutput, "photons/frame_0000.grd");
}

TEST(Planner, TilesShareTheirEdgesExactly) {
    PlanRequest r = Request();
    r.tileColumns = 3, r.tileRows = 2;
    const FarmManifest m = PlanJob(r, {{1, false, 0, "out.exr"}});
    ASSERT_EQ(m.tasks.size(), 6u);
    ASSERT_EQ(m.images.size(), 1u);
    EXPECT_EQ(m.images[0].output, "images/frame_0001.exr");
    // --crop X0 X1 Y0 Y1 are the last four arguments; a tile's right edge is the text of its
    // right neighbour's left edge, so both parse to the same float.
    auto crop = [&](int i, int k) { return m.tasks[i].args[m.tasks[i].args.size() - 4 + k]; };
    EXPECT_EQ(crop(0, 0), "0");
    EXPECT_EQ(crop(2, 1), "1");
    EXPECT_EQ(crop(0, 1), crop(1, 0));
    EXPECT_EQ(crop(1, 1), crop(2, 0));
    EXPECT_EQ(crop(0, 3), crop(3, 2));
    EXPECT_EQ(std::stof(crop(0, 1)), 1.0f / 3.0f);
}

TEST(Planner, RefusesWhatCannotBeDone) {
    PlanRequest r = Request();
    r.tileColumns = 2;
    EXPECT_THROW(PlanJob(r, {{1, false, 0, "out.png"}}), FarmError);  // no data window
    r = Request();
    r.photonShards = 4;
    EXPECT_THROW(PlanJob(r, {{1, false, 0, "out.tif"}}), FarmError);  // no BRDFLight frame
    EXPECT_THROW(PlanJob(Request(), {}), FarmError);
}

TEST(Manifest, RoundTripsEveryField) {
    PlanRequest r = Request();
    r.photonShards = 3;
    r.chunk = 2;
    r.retries = 5;
    r.slurm.partition = "long";
    r.slurm.throttle = 7;
    FarmManifest m = PlanJob(r, {{0, true, 900, "a.pm"}, {2, false, 0, "b.tif"}});
    const std::string dir = TempDir("roundtrip");
    WriteManifest(dir, m);
    const FarmManifest back = ReadManifest(dir);
    ASSERT_EQ(back.tasks.size(), 4u);
    EXPECT_EQ(back.ArrayTasks(), 2);
    EXPECT_EQ(back.slurm.partition, "long");
    EXPECT_EQ(back.slurm.throttle, 7);
    for (size_t i = 0; i < m.tasks.size(); ++i) {
        EXPECT_EQ(back.tasks[i].args, m.tasks[i].args);
        EXPECT_EQ(back.tasks[i].output, m.tasks[i].output);
        EXPECT_EQ(back.tasks[i].paths, m.tasks[i].paths);
        EXPECT_EQ(back.tasks[i].kind, m.tasks[i].kind);
        EXPECT_EQ(back.tasks[i].retries, 5);
    }
    EXPECT_EQ(back.tasks[3].kind, TaskKind::kFrame);
    EXPECT_EQ(back.merges[0].shards, m.merges[0].shards);
}

// The error of reading `text` as a manifest ("" when it is read).
std::string ManifestError(const std::string& text) {
    const std::string dir = TempDir("bad");
    WriteText(ManifestPath(dir), text);
    try {
        ReadManifest(dir);
        return "";
    } catch (const FarmError& e) {
        return e.what();
    }
}

TEST(Manifest, BadManifestsGiveErrorsNamingTheFile) {
    const std::string name = ManifestPath(TempDir("bad"));
    EXPECT_EQ(ManifestError("{ not json").rfind(name + ": error: not valid JSON", 0), 0u);
    const std::string noTasks = ManifestError(R"({"version": 1})");
    EXPECT_NE(noTasks.find(name + ": error: the manifest: missing \"scene\""), std::string::npos)
        << noTasks;
    // A valid manifest with one field broken in each way.
    const std::string dir = TempDir("good");
    PlanRequest r = Request();
    r.photonShards = 2;
    WriteManifest(dir, PlanJob(r, {{0, true, 10, "a.pm"}}));
    std::ifstream in(ManifestPath(dir));
    const std::string good((std::istreambuf_iterator<char>(in)), {});
    auto broken = [&](const std::string& from, const std::string& to) {
        std::string text = good;
        const size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return ManifestError(text.replace(at, from.size(), to));
    };
    EXPECT_NE(broken("\"kind\": \"shard\"", "\"kind\": \"slice\"").find("unknown task kind"),
              std::string::npos);
    EXPECT_NE(broken("\"paths\": 5", "\"paths\": \"five\"").find("task 0: \"paths\""),
              std::string::npos);
    EXPECT_NE(broken("\"version\": 1", "\"version\": 9").find("version 9"), std::string::npos);
    EXPECT_NE(ManifestError(good.substr(0, good.size() / 2)).find("not valid JSON"),
              std::string::npos);
    try {
        ReadManifest(TempDir("empty"));
        ADD_FAILURE() << "a folder without a manifest was read";
    } catch (const FarmError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot read the manifest"), std::string::npos);
    }
}

TEST(TaskOutput, ShardMapsAreCheckedWhole) {
    const std::string dir = TempDir("shards");
    FarmTask task;
    task.kind = TaskKind::kShard;
    task.paths = 4;
    const std::string path = dir + "/s.pm";
    EXPECT_EQ(CheckTaskOutput(task, path), "missing");
    WriteText(path, "2 4\n0.1 0 0.2 0 0.15 1 1 1\n0.3 0 0.4 1 0.15 1 1 1\n");
    EXPECT_EQ(CheckTaskOutput(task, path), "");
    task.paths = 5;
    EXPECT_NE(CheckTaskOutput(task, path).find("counts 4 paths, the shard traces 5"),
              std::string::npos);
    task.paths = 4;
    WriteText(path, "2 4\n0.1 0 0.2 0 0.15 1 1 1\n0.3 0 0.4");  // cut mid-line
    EXPECT_NE(CheckTaskOutput(task, path), "");
    WriteText(path, "3 4\n0.1 0 0.2 0 0.15 1 1 1\n0.3 0 0.4 1 0.15 1 1 1\n");  // a line short
    EXPECT_NE(CheckTaskOutput(task, path), "");
}

TEST(Assemble, NamesEveryMissingTask) {
    const std::string dir = TempDir("missing");
    PlanRequest r = Request();
    r.photonShards = 3;
    const FarmManifest m = PlanJob(r, {{0, true, 30, "a.pm"}});
    fs::create_directories(dir + "/shards");
    WriteText(JobPath(dir, m.tasks[1].output), "0 10\n");
    const std::vector<std::string> lines = IncompleteTasks(dir, m);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "task 0 (frame 0 shard 0/3): shards/frame_0000_shard_0000.pm: missing");
    EXPECT_EQ(lines[1].rfind("task 2 (frame 0 shard 2/3): ", 0), 0u);
}

// A frame of random float pixels (4 channels), and the tile of it at [x0, x1) × [y0, y1)
// written as OpenEXR with its data window.
struct TestFrame {
    int width = 13, height = 9;
    std::vector<float> pixels;
    ImageFileSpec spec;

    TestFrame() {
        std::mt19937 random(7);
        std::uniform_real_distribution<float> value(0, 1);
        pixels.resize(size_t(width) * height * 4);
        for (float& p : pixels) p = value(random);
        spec.channelNames = {"R", "G", "B", "A"};
        spec.alphaChannel = 3;
        spec.fileType = PixelType::Float;
        spec.fullWidth = width, spec.fullHeight = height;
    }

    void WriteTile(const std::string& path, int x0, int x1, int y0, int y1) const {
        ImageFileSpec s = spec;
        s.x = x0, s.y = y0, s.width = x1 - x0, s.height = y1 - y0;
        std::vector<float> tile;
        for (int y = y0; y < y1; ++y)
            tile.insert(tile.end(), pixels.begin() + (size_t(y) * width + x0) * 4,
                        pixels.begin() + (size_t(y) * width + x1) * 4);
        ASSERT_EQ(WriteImageFile("openexr", path, s, {PixelType::Float, tile.data()}), "");
    }
};

TEST(TileJoin, UnevenTilesJoinIntoTheExactFrame) {
    const std::string dir = TempDir("join");
    const TestFrame frame;
    const int xs[] = {0, 4, 5, 13}, ys[] = {0, 6, 9};
    std::vector<std::string> tiles;
    for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < 3; ++c) {
            tiles.push_back(dir + "/t" + std::to_string(r) + std::to_string(c) + ".exr");
            frame.WriteTile(tiles.back(), xs[c], xs[c + 1], ys[r], ys[r + 1]);
        }
    }
    ASSERT_EQ(JoinTiles(tiles, dir + "/joined.exr"), "");
    std::string error;
    const ImageFileContents joined =
        LoadOiioPlugin("the test").ReadImage(dir + "/joined.exr", &error);
    ASSERT_EQ(error, "");
    EXPECT_EQ(joined.spec.width, frame.width);
    EXPECT_EQ(joined.spec.height, frame.height);
    EXPECT_EQ(joined.spec.channelNames, frame.spec.channelNames);
    EXPECT_EQ(joined.pixels, frame.pixels);  // bit for bit
}

TEST(TileJoin, GapsOverlapsAndBadTilesAreNamed) {
    const std::string dir = TempDir("gaps");
    const TestFrame frame;
    frame.WriteTile(dir + "/left.exr", 0, 7, 0, 9);
    frame.WriteTile(dir + "/right.exr", 8, 13, 0, 9);
    frame.WriteTile(dir + "/wide.exr", 6, 13, 0, 9);
    EXPECT_EQ(JoinTiles({dir + "/left.exr", dir + "/right.exr"}, dir + "/o.exr"),
              "pixel 7,0 is in no tile of " + dir + "/o.exr");
    EXPECT_EQ(JoinTiles({dir + "/left.exr", dir + "/wide.exr"}, dir + "/o.exr"),
              "pixel 6,0 is in more than one tile of " + dir + "/o.exr");
    WriteText(dir + "/junk.exr", "not an image");
    const std::string bad = JoinTiles({dir + "/left.exr", dir + "/junk.exr"}, dir + "/o.exr");
    EXPECT_EQ(bad.rfind("tile \"" + dir + "/junk.exr\": ", 0), 0u) << bad;
    EXPECT_FALSE(fs::exists(dir + "/o.exr"));
}

}  // namespace
}  // namespace gonio
