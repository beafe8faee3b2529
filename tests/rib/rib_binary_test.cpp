// Binary RIB (RISpec 3.2 App. C.2): every encoded token kind parses to the same RiTarget calls
// as its ASCII equivalent, ASCII and binary mix, and cut or bad binary input gives an error at a
// byte offset instead of a crash.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "rib_test_util.h"

namespace gonio {
namespace {

// A small encoder following Table C.1 of RISpec App. C.2 (multi-byte values MSB first).
struct Encoder {
    std::string bytes;

    Encoder& Raw(std::initializer_list<int> values) {
        for (int v : values) bytes.push_back(static_cast<char>(v));
        return *this;
    }
    void BigEndian(std::uint64_t value, int count) {
        for (int i = count - 1; i >= 0; --i) bytes.push_back(static_cast<char>(value >> (8 * i)));
    }
    // 0200 + 4d + w: a signed value of w+1 bytes, d of them after the binary point.
    Encoder& Fixed(double value, int size, int fraction) {
        bytes.push_back(static_cast<char>(0200 + 4 * fraction + size - 1));
        const auto scaled = static_cast<std::int64_t>(value * (1 << (8 * fraction)));
        BigEndian(static_cast<std::uint64_t>(scaled), size);
        return *this;
    }
    Encoder& Int(std::int64_t value, int size) {
        return Fixed(static_cast<double>(value), size, 0);
    }
    Encoder& Float(float value) {
        std::uint32_t raw;
        std::memcpy(&raw, &value, 4);
        bytes.push_back('\244');
        BigEndian(raw, 4);
        return *this;
    }
    Encoder& Double(double value) {
        std::uint64_t raw;
        std::memcpy(&raw, &value, 8);
        bytes.push_back('\245');
        BigEndian(raw, 8);
        return *this;
    }
    // Strings: 0220 + w (w < 16) or 0240 + l | length (l+1 bytes) | string.
    Encoder& String(const std::string& text, int lengthBytes = 0) {
        if (lengthBytes == 0 && text.size() < 16) {
            bytes.push_back(static_cast<char>(0220 + text.size()));
        } else {
            bytes.push_back(static_cast<char>(0240 + std::max(lengthBytes, 1) - 1));
            BigEndian(text.size(), std::max(lengthBytes, 1));
        }
        bytes += text;
        return *this;
    }
    Encoder& DefineRequest(int code, const std::string& name) {
        bytes.push_back('\314');
        bytes.push_back(static_cast<char>(code));
        return String(name);
    }
    Encoder& Request(int code) { return Raw({0246, code}); }
    Encoder& DefineString(int id, int idBytes, const std::string& text) {
        bytes.push_back(static_cast<char>(0315 + idBytes - 1));
        BigEndian(static_cast<std::uint64_t>(id), idBytes);
        return String(text);
    }
    Encoder& StringRef(int id, int idBytes) {
        bytes.push_back(static_cast<char>(0317 + idBytes - 1));
        BigEndian(static_cast<std::uint64_t>(id), idBytes);
        return *this;
    }
    Encoder& FloatArray(const std::vector<float>& values, int lengthBytes = 1) {
        bytes.push_back(static_cast<char>(0310 + lengthBytes - 1));
        BigEndian(values.size(), lengthBytes);
        for (float v : values) {
            std::uint32_t raw;
            std::memcpy(&raw, &v, 4);
            BigEndian(raw, 4);
        }
        return *this;
    }
    Encoder& Ascii(const std::string& text) {
        bytes += text;
        return *this;
    }
};

// The same scene in binary, every token kind at least once, and in ASCII.
std::string BinaryScene() {
    Encoder e;
    e.DefineRequest(0, "Format").DefineRequest(1, "Sphere").DefineRequest(200, "Surface");
    e.DefineRequest(3, "ConcatTransform").DefineRequest(4, "Color").DefineRequest(5, "Attribute");
    e.Request(0).Int(640, 2).Int(-480, 3).Fixed(1.5, 2, 1);              // 0201, 0202, 0205
    e.Request(1).Int(1, 1).Int(-1, 1).Fixed(0.25, 1, 1).Int(300000, 4);  // 0200, 0204, 0203
    e.Request(1).Float(0.5f).Double(-0.125).Fixed(2.75, 4, 3).Fixed(-1.0 / 256, 3, 2);
    e.DefineString(7, 1, "plastic").DefineString(513, 2, "Kd");
    e.Request(200).StringRef(7, 1).StringRef(513, 2).FloatArray({0.75f});
    e.Request(3).FloatArray({1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 3, 0, 0.5f, 0, 0, 1}, 2);  // 0311
    e.Request(4).FloatArray({0.1f, 0.2f, 0.3f}, 3);                                   // 0312
    const std::string longName(300, 'n');
    e.Request(5).String("identifier").String("string name").String(longName, 2).Request(5);
    e.String("user").String("uniform string long").Raw({0241, 0, 17}).Ascii("0123456789abcdefg");
    e.Request(5).String("a").String("string b").Raw({0243, 0, 0, 0, 1}).Ascii("c");
    return e.bytes;
}

std::string AsciiScene() {
    return "Format 640 -480 1.5\nSphere 1 -1 0.25 300000\nSphere 0.5 -0.125 2.75 -0.00390625\n"
           "Surface \"plastic\" \"Kd\" [0.75]\n"
           "ConcatTransform [1 0 0 0 0 2 0 0 0 0 3 0 0.5 0 0 1]\n"
           "Color [0.1 0.2 0.3]\n"
           "Attribute \"identifier\" \"string name\" \"" +
           std::string(300, 'n') +
           "\"\nAttribute \"user\" \"uniform string long\" \"0123456789abcdefg\"\n"
           "Attribute \"a\" \"string b\" \"c\"\n";
}

TEST(BinaryRib, EveryTokenKindParsesLikeItsAsciiEquivalent) {
    const ParseResult ascii = ParseText(AsciiScene());
    ASSERT_TRUE(ascii.ok) << ascii.messages;
    const ParseResult binary = ParseText(BinaryScene(), "binary.rib");
    EXPECT_TRUE(binary.ok) << binary.messages;
    EXPECT_EQ(binary.target.Text(), ascii.target.Text());
    EXPECT_EQ(binary.target.calls.size(), 9u);
}

// Hand-made bytes checked against Table C.1: 0314 <code> <string> defines a request; 0246 <code>
// refers to it; 0200 + w carries a w+1 byte signed integer.
TEST(BinaryRib, HandMadeBytesFromTheSpecTable) {
    const char bytes[] =
        "\314\021\226Sphere"        // define request 021 as "Sphere" (0220 + 6 byte string)
        "\246\021"                  // Sphere
        "\200\002\200\376\200\002"  // 2 -2 2 (one-byte integers; 0376 is -2)
        "\201\001\150"              // 360 (two bytes: 0x0168)
        "\246\021\204\200\205\377\000\207\000\001\000\000\244\103\264\000\000";
    const ParseResult result = ParseText(std::string(bytes, sizeof bytes - 1));
    EXPECT_TRUE(result.ok) << result.messages;
    // 0204 0200: 0x80/256 = -0.5 (signed); 0205 0377 0000: -256/256; 0207: 65536/256 = 256; 0244
    // 0x43b40000 = 360.0f.
    EXPECT_EQ(result.target.Text(), "Sphere 2 -2 2 360 {}\nSphere -0.5 -1 256 360 {}\n");
}

TEST(BinaryRib, MixesWithAsciiInOneFile) {
    Encoder e;
    e.Ascii("WorldBegin\n# a comment\n").DefineRequest(9, "Translate");
    e.Request(9).Int(1, 1).Ascii(" 2 ").Float(3).Ascii("\nSphere 1 ").Int(-1, 1).Ascii(" 1 360\n");
    e.Ascii("Surface ").String("matte").Ascii(" \"Kd\" ").FloatArray({0.5f}).Ascii("\nWorldEnd\n");
    const ParseResult result = ParseText(e.bytes);
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.target.Text(),
              "WorldBegin\nTranslate 1 2 3\nSphere 1 -1 1 360 {}\nSurface \"matte\" "
              "{\"Kd\"=[0.5]}\nWorldEnd\n");
}

TEST(BinaryRib, DefinedStringMayBeAnAsciiConstant) {
    Encoder e;
    e.Raw({0315, 4}).Ascii(" \"tab\\there\"").Ascii("Attribute ").StringRef(4, 1);
    e.Ascii(" \"string x\" ").StringRef(4, 1);
    const ParseResult result = ParseText(e.bytes);
    EXPECT_TRUE(result.ok) << result.messages;
    EXPECT_EQ(result.target.Text(), "Attribute \"tab\there\" {\"string x\"=[\"tab\there\"]}\n");
}

// A binary string is not unescaped and may hold any byte, including quotes and NUL.
TEST(BinaryRib, EncodedStringsHoldAnyByte) {
    Encoder e;
    e.Ascii("Surface ").String(std::string("a\"\\n\0b", 6));
    const ParseResult result = ParseText(e.bytes);
    EXPECT_TRUE(result.ok) << result.messages;
    ASSERT_EQ(result.target.calls.size(), 1u);
    EXPECT_EQ(result.target.calls[0], std::string("Surface \"a\"\\n\0b\" {}", 19));
}

// Every way of cutting the binary scene short ends in an error at a byte offset that names the
// truncation, never in a crash or a silently shorter scene.
TEST(BinaryRib, TruncatedInputIsAnErrorAtAByteOffset) {
    const std::string full = BinaryScene();
    int cutInsideTokens = 0;
    for (std::size_t length = 1; length < full.size(); ++length) {
        const ParseResult result = ParseText(full.substr(0, length), "cut.rib");
        if (result.messages.find("truncated") == std::string::npos) continue;
        ++cutInsideTokens;
        EXPECT_FALSE(result.ok);
        EXPECT_NE(result.messages.find("cut.rib:1:"), std::string::npos) << result.messages;
        EXPECT_NE(result.messages.find("byte offset"), std::string::npos) << result.messages;
    }
    // Only a cut just after a complete token can pass for a complete file; the scene has far
    // fewer token boundaries than bytes.
    EXPECT_GT(cutInsideTokens, static_cast<int>(full.size()) * 3 / 4);
}

TEST(BinaryRib, TruncatedFloatArrayNamesItsOffset) {
    Encoder e;
    e.Ascii("Color ").FloatArray({0.1f, 0.2f, 0.3f});
    const ParseResult result = ParseText(e.bytes.substr(0, e.bytes.size() - 2), "c.rib");
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.messages,
              "c.rib:1:17: error: binary RIB at byte offset 16: the input ends inside a binary "
              "float array (the file is truncated)\n");
    EXPECT_TRUE(result.target.calls.empty());
}

TEST(BinaryRib, UndefinedReferencesAndReservedBytesAreErrors) {
    Encoder e;
    e.Ascii("WorldBegin\n").Request(42).Ascii("\nSurface ").StringRef(3, 1);
    e.Ascii("\nWorldEnd\n").Raw({0250}).Ascii("\nWorldEnd\n");
    const ParseResult result = ParseText(e.bytes, "bad.rib");
    EXPECT_FALSE(result.ok);
    EXPECT_NE(result.messages.find("bad.rib:2:1: error: binary RIB at byte offset 11: reference "
                                   "to request code 42, which was not defined (0314)"),
              std::string::npos)
        << result.messages;
    EXPECT_NE(result.messages.find("bad.rib:3:9: error: binary RIB at byte offset 22: reference "
                                   "to string 3, which was not defined (0315/0316)"),
              std::string::npos)
        << result.messages;
    EXPECT_NE(result.messages.find(
                  "bad.rib:5:1: error: binary RIB at byte offset 34: reserved byte 0250"),
              std::string::npos)
        << result.messages;
    EXPECT_EQ(result.errors, 3);
}

}  // namespace
}  // namespace gonio
