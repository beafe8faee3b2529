// ReadArchive (relative to the including file, the archive search path, cycles, missing files),
// gzip-compressed input and standard input.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include "rib_test_util.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

void WriteGzip(const fs::path& path, const std::string& text) {
    gzFile file = gzopen(path.c_str(), "wb");
    ASSERT_NE(file, nullptr);
    ASSERT_EQ(gzwrite(file, text.data(), static_cast<unsigned>(text.size())),
              static_cast<int>(text.size()));
    gzclose(file);
}

TEST(Archives, ResolvedRelativeToTheIncludingFile) {
    const fs::path dir = ScratchFolder("relative");
    WriteText(dir / "main.rib", "WorldBegin\nReadArchive \"sub/a.rib\"\nWorldEnd\n");
    WriteText(dir / "sub/a.rib", "Sphere 1 -1 1 360\n  ReadArchive \"b.rib\"\n");
    WriteText(dir / "sub/b.rib", "\n Disk 0 1 360\n");
    const ParseResult result = ParseFile((dir / "main.rib").string());
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.target.Text(),
              "WorldBegin\nSphere 1 -1 1 360 {}\nDisk 0 1 360 {}\nWorldEnd\n");
    EXPECT_EQ(result.target.locs[2].ToString(), (dir / "sub/b.rib").string() + ":2:2");
    EXPECT_EQ(result.target.locs[3].ToString(), (dir / "main.rib").string() + ":3:1");
}

TEST(Archives, FoundOnTheSearchPathWithPreviousValue) {
    const fs::path dir = ScratchFolder("searchpath");
    WriteText(dir / "lib1/one.rib", "Sphere 1 -1 1 360\n");
    WriteText(dir / "lib2/two.rib", "Disk 0 1 360\n");
    WriteText(dir / "main.rib", "Option \"searchpath\" \"archive\" [\"" + (dir / "lib1").string() +
                                    "\"]\nOption \"searchpath\" \"string archive\" \"" +
                                    (dir / "lib2").string() +
                                    ":&\"\nReadArchive \"one.rib\"\nReadArchive \"two.rib\"\n");
    const ParseResult result = ParseFile((dir / "main.rib").string());
    EXPECT_TRUE(result.ok) << result.messages;
    ASSERT_EQ(result.target.calls.size(), 4u);  // the two Options are passed on too
    EXPECT_EQ(result.target.calls[2], "Sphere 1 -1 1 360 {}");
    EXPECT_EQ(result.target.calls[3], "Disk 0 1 360 {}");
}

TEST(Archives, CycleIsAnErrorNamingTheChain) {
    const fs::path dir = ScratchFolder("cycle");
    WriteText(dir / "a.rib", "WorldBegin\nReadArchive \"b.rib\"\nWorldEnd\n");
    WriteText(dir / "b.rib", "ReadArchive \"./a.rib\"\nSphere 1 -1 1 360\n");
    const std::string a = (dir / "a.rib").string(), b = (dir / "b.rib").string();
    const ParseResult result = ParseFile(a);
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.messages,
              b + ":1:1: error: ReadArchive cycle: " + a + " -> " + b + " -> " + a + "\n");
    EXPECT_EQ(result.target.Text(), "WorldBegin\nSphere 1 -1 1 360 {}\nWorldEnd\n");
}

TEST(Archives, MissingArchiveIsAnErrorAndParsingGoesOn) {
    const fs::path dir = ScratchFolder("missing");
    WriteText(dir / "main.rib", "WorldBegin\n  ReadArchive \"nope.rib\"\nWorldEnd\n");
    const ParseResult result = ParseFile((dir / "main.rib").string());
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.messages, (dir / "main.rib").string() +
                                   ":2:3: error: cannot find archive \"nope.rib\" (looked for " +
                                   (dir / "nope.rib").string() + ")\n");
    EXPECT_EQ(result.target.Text(), "WorldBegin\nWorldEnd\n");
}

TEST(Archives, ErrorsInsideAnArchiveNameTheArchive) {
    const fs::path dir = ScratchFolder("archive_error");
    WriteText(dir / "main.rib", "ReadArchive \"part.rib\"\nWorldEnd\n");
    WriteText(dir / "part.rib", "WorldBegin\n\nSphere 1 2\n");
    const ParseResult result = ParseFile((dir / "main.rib").string());
    EXPECT_EQ(result.messages,
              (dir / "part.rib").string() + ":3:1: error: Sphere expects 4 numbers, got 2\n");
    EXPECT_EQ(result.target.Text(), "WorldBegin\nWorldEnd\n");
}

TEST(Archives, ArchiveRequestEndsAtTheNextRequestName) {
    // The archive's requests arrive between the requests around ReadArchive, in order.
    const ParseResult result =
        ParseText("Translate 1 2 3 ReadArchive \"/nonexistent.rib\" Scale 1 1 1");
    EXPECT_EQ(result.errors, 1);
    EXPECT_EQ(result.target.Text(), "Translate 1 2 3\nScale 1 1 1\n");
}

TEST(Gzip, CompressedFilesAndArchivesReadTransparently) {
    const fs::path dir = ScratchFolder("gzip");
    WriteGzip(dir / "main.rib.gz", "WorldBegin\nReadArchive \"part.rib.gz\"\nWorldEnd\n");
    WriteGzip(dir / "part.rib.gz", "Sphere 1 -1 1 360 \"Cs\" [1 0 0]\n");
    const ParseResult result = ParseFile((dir / "main.rib.gz").string());
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.target.Text(), "WorldBegin\nSphere 1 -1 1 360 {\"Cs\"=[1 0 0]}\nWorldEnd\n");
}

TEST(Gzip, LargeCompressedFileCrossesBufferBoundaries) {
    const fs::path dir = ScratchFolder("gzip_large");
    std::string rib = "PointsPolygons [";
    const int triangles = 50000;
    for (int i = 0; i < triangles; ++i) rib += "3 ";
    rib += "] [";
    for (int i = 0; i < 3 * triangles; ++i) rib += std::to_string(i) + " ";
    rib += "] \"P\" [";
    for (int i = 0; i < 9 * triangles; ++i) rib += std::to_string(i * 0.125) + " ";
    rib += "]\nWorldEnd\n";
    WriteGzip(dir / "mesh.rib.gz", rib);
    struct MeshTarget : RecordingTarget {
        std::size_t faces = 0, indices = 0, points = 0;
        double lastPoint = 0;
        void PointsPolygons(const std::vector<int>& nverts, const std::vector<int>& verts,
                            const ParamList& params, const FileLoc&) override {
            faces = nverts.size();
            indices = verts.size();
            points = params.at(0).numbers.size();
            lastPoint = params.at(0).numbers.back();
        }
    };
    MeshTarget target;
    Diagnostics diagnostics(nullptr);
    EXPECT_TRUE(ParseRibFile((dir / "mesh.rib.gz").string(), target, diagnostics));
    EXPECT_EQ(target.faces, static_cast<std::size_t>(triangles));
    EXPECT_EQ(target.indices, static_cast<std::size_t>(3 * triangles));
    EXPECT_EQ(target.points, static_cast<std::size_t>(9 * triangles));
    EXPECT_EQ(target.lastPoint, (9 * triangles - 1) * 0.125);
    EXPECT_EQ(target.Text(), "WorldEnd\n");
}

TEST(Stdin, DashReadsStandardInput) {
    const fs::path dir = ScratchFolder("stdin");
    WriteText(dir / "in.rib",
              "WorldBegin\nReadArchive \"" + (dir / "part.rib").string() + "\"\nWorldEnd\n");
    WriteText(dir / "part.rib", "Sphere 1 -1 1 360\n");
    const int savedStdin = dup(0);
    const int file = open((dir / "in.rib").c_str(), O_RDONLY);
    ASSERT_GE(file, 0);
    dup2(file, 0);
    close(file);
    const ParseResult result = ParseFile("-");
    dup2(savedStdin, 0);
    close(savedStdin);
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.target.Text(), "WorldBegin\nSphere 1 -1 1 360 {}\nWorldEnd\n");
    EXPECT_EQ(result.target.locs[0].ToString(), "<stdin>:1:1");
}

}  // namespace
}  // namespace gonio
