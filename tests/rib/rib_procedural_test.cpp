// Procedural (RISpec 3.2 §5.7) as the parser offers it: the target's reader reads
// DelayedReadArchive's archive and RunProgram's answer in place; errors are located at the
// Procedural request; a program that hangs is killed; nesting is bounded.

#include <gtest/gtest.h>

#include <chrono>

#include "rib_test_util.h"

namespace gonio {
namespace {

namespace fs = std::filesystem;

// Parses `path` with a recording target that reads every procedural.
ParseResult ParseReading(const fs::path& path, double timeout = 10) {
    return Capture([&](RecordingTarget& target, Diagnostics& diagnostics) {
        target.readProcedurals = true;
        target.proceduralDetail = 1234.5f;
        target.proceduralTimeout = timeout;
        return ParseRibFile(path.string(), target, diagnostics);
    });
}

// A shell script (executable) in `dir`.
void WriteScript(const fs::path& path, const std::string& body) {
    WriteText(path, "#!/bin/sh\n" + body);
    fs::permissions(path, fs::perms::owner_all);
}

TEST(Procedurals, DelayedReadArchiveIsReadWhereTheTargetAsks) {
    const fs::path dir = ScratchFolder("delayed");
    WriteText(dir / "part.rib", "Sphere 1 -1 1 360\n");
    WriteText(dir / "main.rib",
              "Procedural \"DelayedReadArchive\" [\"part.rib\"] [-1 1 -1 1 -1 1]\nDisk 0 1 360\n");
    const ParseResult result = ParseReading(dir / "main.rib");
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.target.Text(),
              "Procedural \"DelayedReadArchive\" [\"part.rib\"] [-1 1 -1 1 -1 1]\n"
              "Sphere 1 -1 1 360 {}\nDisk 0 1 360 {}\n");
    // A target that does not read it (catrib) sees the request alone.
    EXPECT_EQ(ParseFile((dir / "main.rib").string()).target.calls.size(), 2u);
}

TEST(Procedurals, RunProgramReadsDetailAndDataAndAnswersWithRib) {
    const fs::path dir = ScratchFolder("runprogram");
    // The answer ends with 0377; what follows it is not read.
    WriteScript(dir / "gen.sh",
                "read detail data\n"
                "printf 'Attribute \"user\" \"string got\" \"%s|%s\"\\n\\377Sphere' \"$detail\" "
                "\"$data\"\n");
    WriteText(dir / "main.rib", "Procedural \"RunProgram\" [\"gen.sh\" \"a b\"] [0 1 0 1 0 1]\n");
    const ParseResult result = ParseReading(dir / "main.rib");
    EXPECT_TRUE(result.ok) << result.messages;
    ASSERT_EQ(result.target.calls.size(), 2u);
    EXPECT_EQ(result.target.calls[1], "Attribute \"user\" {\"string got\"=[\"1234.5|a b\"]}");
}

TEST(Procedurals, RunProgramAnswerMayBeBinaryAndEndWithoutTheMark) {
    const fs::path dir = ScratchFolder("runbinary");
    // 0314 0 "Disk" defines request 0; 0246 0 calls it with 0, 1, 360.
    WriteScript(dir / "gen.sh",
                "cat > /dev/null\nprintf '\\314\\000\\224Disk\\246\\000\\200\\000\\200\\001"
                "\\201\\001\\150'\n");
    WriteText(dir / "main.rib", "Procedural \"RunProgram\" [\"gen.sh\" \"\"] [0 1 0 1 0 1]\n");
    const ParseResult result = ParseReading(dir / "main.rib");
    EXPECT_TRUE(result.ok) << result.messages;
    ASSERT_EQ(result.target.calls.size(), 2u);
    EXPECT_EQ(result.target.calls[1], "Disk 0 1 360 {}");
}

TEST(Procedurals, ErrorsAreLocatedAtTheProceduralRequest) {
    const fs::path dir = ScratchFolder("procerrors");
    WriteScript(dir / "fail.sh", "echo 'Sphere 1 -1 1 360'\nexit 3\n");
    WriteScript(dir / "bad.sh", "printf 'Sphere 1 -1\\n  Bogus 2\\n'\n");
    WriteText(dir / "main.rib",
              "Procedural \"DelayedReadArchive\" [\"missing.rib\"] [0 1 0 1 0 1]\n"
              "Procedural \"RunProgram\" [\"fail.sh\" \"\"] [0 1 0 1 0 1]\n"
              "Procedural \"RunProgram\" [\"bad.sh\" \"\"] [0 1 0 1 0 1]\n"
              "Procedural \"DynamicLoad\" [\"plugin.so\" \"\"] [0 1 0 1 0 1]\n"
              "Procedural \"Teapots\" [] [0 1 0 1 0 1]\n"
              "Procedural \"RunProgram\" [\"bad.sh\"] [0 1 0 1 0 1]\n");
    const std::string main = (dir / "main.rib").string();
    const ParseResult result = ParseReading(dir / "main.rib");
    EXPECT_FALSE(result.ok);
    const auto has = [&](const std::string& text) {
        return result.messages.find(text) != std::string::npos;
    };
    EXPECT_TRUE(has(main + ":1:1: error: cannot find archive \"missing.rib\"")) << result.messages;
    EXPECT_TRUE(has(main + ":2:1: error: Procedural RunProgram \"fail.sh\" exited with status 3"))
        << result.messages;
    // The failed program's output is not read.
    EXPECT_FALSE(has("Sphere 1 -1 1 360 {}")) << result.target.Text();
    EXPECT_TRUE(has("<RunProgram \"bad.sh\" output>:1:1: error: Sphere expects"))
        << result.messages;
    EXPECT_TRUE(has("<RunProgram \"bad.sh\" output>:2:3: error: unknown request 'Bogus'"))
        << result.messages;
    EXPECT_TRUE(has(main + ":3:1: error: Procedural RunProgram \"bad.sh\" wrote bad RIB"))
        << result.messages;
    EXPECT_TRUE(has(main + ":4:1: error: Procedural \"DynamicLoad\" is not supported: gonio has "
                           "no C RenderMan Interface"))
        << result.messages;
    EXPECT_TRUE(has(main + ":5:1: error: unknown procedural \"Teapots\"")) << result.messages;
    EXPECT_TRUE(has(main + ":6:1: error: Procedural \"RunProgram\" takes two arguments"))
        << result.messages;
}

TEST(Procedurals, AProgramThatHangsIsKilledAfterTheTimeOut) {
    const fs::path dir = ScratchFolder("prochang");
    // It reads its request, then neither answers nor exits (nor lets its child go).
    WriteScript(dir / "hang.sh", "read line\nsleep 30 &\nsleep 30\n");
    WriteText(dir / "main.rib", "Procedural \"RunProgram\" [\"hang.sh\" \"\"] [0 1 0 1 0 1]\n");
    const auto start = std::chrono::steady_clock::now();
    const ParseResult result = ParseReading(dir / "main.rib", 0.5);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_FALSE(result.ok);
    EXPECT_NE(result.messages.find("error: Procedural RunProgram \"hang.sh\" did not finish "
                                   "within 0.5 s"),
              std::string::npos)
        << result.messages;
    EXPECT_LT(seconds, 5);
}

TEST(Procedurals, NestingIsBoundedEvenForAProgramThatRunsItself) {
    const fs::path dir = ScratchFolder("procnest");
    WriteScript(dir / "self.sh",
                "cat > /dev/null\n"
                "echo 'Procedural \"RunProgram\" [\"" +
                    (dir / "self.sh").string() + "\" \"\"] [0 1 0 1 0 1]'\n");
    WriteText(dir / "a.rib", "Procedural \"RunProgram\" [\"self.sh\" \"\"] [0 1 0 1 0 1]\n");
    WriteText(dir / "main.rib",
              "Procedural \"DelayedReadArchive\" [\"a.rib\"] [0 1 0 1 0 1]\n"
              "Procedural \"DelayedReadArchive\" [\"main.rib\"] [0 1 0 1 0 1]\n");
    const ParseResult result = ParseReading(dir / "main.rib");
    EXPECT_FALSE(result.ok);
    EXPECT_NE(result.messages.find("error: ReadArchive and procedurals nested more than 64 inputs "
                                   "deep"),
              std::string::npos)
        << result.messages;
    EXPECT_NE(result.messages.find("main.rib:2:1: error: ReadArchive cycle"), std::string::npos)
        << result.messages;
}

}  // namespace
}  // namespace gonio
