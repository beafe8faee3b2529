// Decoding the binary RIB tokens of RISpec 3.2 App. C.2, Table C.1 (codes in octal, multi-byte
// values most significant byte first).

#include "renderer/rib/rib_binary.h"

#include <algorithm>
#include <cstring>

#include "renderer/rib/string_escapes.h"

namespace gonio {
namespace {

// Strings are read in pieces of at most this much before the length is trusted, so that a
// corrupt length field does not allocate gigabytes for a few bytes of input.
constexpr std::uint32_t kStringReserve = 1 << 20;

BinaryToken Error(const std::string& message, bool truncated = false) {
    BinaryToken token;
    token.kind = BinaryToken::Kind::Error;
    token.text = message;
    token.truncated = truncated;
    return token;
}

BinaryToken Truncated(const char* what) {
    return Error(std::string("the input ends inside ") + what + " (the file is truncated)", true);
}

BinaryToken NumberToken(double value) {
    BinaryToken token;
    token.kind = BinaryToken::Kind::Number;
    token.number = value;
    return token;
}

BinaryToken StringToken(std::string text, BinaryToken::Kind kind = BinaryToken::Kind::String) {
    BinaryToken token;
    token.kind = kind;
    token.text = std::move(text);
    return token;
}

std::string Octal(int code) {
    char text[8];
    std::snprintf(text, sizeof text, "0%o", code);
    return text;
}

bool IsWhiteSpace(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

bool BinaryDecoder::ReadUnsigned(ByteSource& bytes, int count, std::uint32_t* value,
                                 BinaryToken* error) {
    *value = 0;
    for (int i = 0; i < count; ++i) {
        const int byte = bytes.Next();
        if (byte < 0) {
            *error = Truncated("a binary token");
            return false;
        }
        *value = (*value << 8) | static_cast<std::uint32_t>(byte);
    }
    return true;
}

// 0200 + 4d + w: a signed integer of w+1 bytes whose bottom d bytes lie after the binary point.
BinaryToken BinaryDecoder::DecodeNumber(int code, ByteSource& bytes) {
    const int size = (code & 3) + 1;
    const int fraction = (code >> 2) & 3;
    std::uint32_t raw = 0;
    BinaryToken error;
    if (!ReadUnsigned(bytes, size, &raw, &error)) return error;
    const int bits = 8 * size;
    // Two's complement of `bits` bits.
    const std::int64_t value = (raw >> (bits - 1)) & 1u
                                   ? static_cast<std::int64_t>(raw) - (std::int64_t(1) << bits)
                                   : static_cast<std::int64_t>(raw);
    return NumberToken(static_cast<double>(value) / static_cast<double>(1u << (8 * fraction)));
}

BinaryToken BinaryDecoder::DecodeString(std::uint32_t length, ByteSource& bytes) {
    std::string text;
    text.reserve(std::min(length, kStringReserve));
    for (std::uint32_t i = 0; i < length; ++i) {
        const int byte = bytes.Next();
        if (byte < 0) return Truncated("a binary string");
        text.push_back(static_cast<char>(byte));
    }
    return StringToken(std::move(text));
}

// 0244 (4 bytes) and 0245 (8 bytes): IEEE floating point, most significant byte first.
BinaryToken BinaryDecoder::DecodeFloat(ByteSource& bytes, int size) {
    std::uint64_t raw = 0;
    for (int i = 0; i < size; ++i) {
        const int byte = bytes.Next();
        if (byte < 0) return Truncated(size == 4 ? "a binary float" : "a binary double");
        raw = (raw << 8) | static_cast<std::uint64_t>(byte);
    }
    if (size == 8) {
        double value;
        std::memcpy(&value, &raw, sizeof value);
        return NumberToken(value);
    }
    const std::uint32_t raw32 = static_cast<std::uint32_t>(raw);
    float value;
    std::memcpy(&value, &raw32, sizeof value);
    return NumberToken(value);
}

BinaryToken BinaryDecoder::ReadQuotedString(ByteSource& bytes) {
    std::string body;
    for (int c = bytes.Next(); c != '"'; c = bytes.Next()) {
        if (c < 0) return Truncated("a string");
        body.push_back(static_cast<char>(c));
        if (c == '\\') {
            const int escaped = bytes.Next();
            if (escaped < 0) return Truncated("a string");
            body.push_back(static_cast<char>(escaped));
        }
    }
    BinaryToken token = StringToken("");
    DecodeEscapes(body.data(), static_cast<int>(body.size()), &token.text);
    return token;
}

// RISpec App. C.2: "the string being defined is transmitted in an encoded or unencoded form".
BinaryToken BinaryDecoder::ReadStringOperand(ByteSource& bytes) {
    int c = bytes.Next();
    while (IsWhiteSpace(c)) c = bytes.Next();
    if (c < 0) return Truncated("a string definition");
    if (c == '"') return ReadQuotedString(bytes);
    if ((c >= 0220 && c <= 0243) || c == 0317 || c == 0320) {
        BinaryToken token = Decode(c, bytes);
        if (token.kind == BinaryToken::Kind::String || token.kind == BinaryToken::Kind::Error)
            return token;
    }
    return Error("expected a string after a binary definition, found byte " + Octal(c));
}

// 0314 | code | string: binds a one-byte code to a request name.
BinaryToken BinaryDecoder::DefineRequest(ByteSource& bytes) {
    const int code = bytes.Next();
    if (code < 0) return Truncated("a request definition (0314)");
    BinaryToken name = ReadStringOperand(bytes);
    if (name.kind == BinaryToken::Kind::Error) return name;
    if (name.text.empty()) return Error("request definition (0314) with an empty name");
    requests_[code] = std::move(name.text);
    return BinaryToken{};
}

// 0315 + w | token | string: binds a token of w+1 bytes to a string.
BinaryToken BinaryDecoder::DefineString(int code, ByteSource& bytes) {
    std::uint32_t id = 0;
    BinaryToken error;
    if (!ReadUnsigned(bytes, code - 0315 + 1, &id, &error)) return error;
    BinaryToken text = ReadStringOperand(bytes);
    if (text.kind == BinaryToken::Kind::Error) return text;
    strings_[id] = std::move(text.text);
    return BinaryToken{};
}

// 0317 + w | token: a string defined by 0315 + w.
BinaryToken BinaryDecoder::ReferenceString(int code, ByteSource& bytes) {
    std::uint32_t id = 0;
    BinaryToken error;
    if (!ReadUnsigned(bytes, code - 0317 + 1, &id, &error)) return error;
    const auto found = strings_.find(id);
    if (found == strings_.end())
        return Error("reference to string " + std::to_string(id) +
                     ", which was not defined (0315/0316)");
    return StringToken(found->second);
}

BinaryToken BinaryDecoder::Decode(int code, ByteSource& bytes) {
    std::uint32_t length = 0;
    BinaryToken error;
    if (code <= 0217) return DecodeNumber(code, bytes);
    if (code <= 0237) return DecodeString(static_cast<std::uint32_t>(code - 0220), bytes);
    if (code <= 0243) {  // 0240 + l | length (l+1 bytes) | string
        if (!ReadUnsigned(bytes, code - 0240 + 1, &length, &error)) return error;
        return DecodeString(length, bytes);
    }
    if (code == 0244) return DecodeFloat(bytes, 4);
    if (code == 0245) return DecodeFloat(bytes, 8);
    if (code == 0246) {  // 0246 | code: a request defined by 0314
        const int request = bytes.Next();
        if (request < 0) return Truncated("a request reference (0246)");
        if (requests_[request].empty())
            return Error("reference to request code " + std::to_string(request) +
                         ", which was not defined (0314)");
        return StringToken(requests_[request], BinaryToken::Kind::Request);
    }
    if (code >= 0310 && code <= 0313) {  // 0310 + l | length (l+1 bytes) | IEEE floats
        if (!ReadUnsigned(bytes, code - 0310 + 1, &length, &error)) return error;
        arrayLeft_ = length;
        BinaryToken token;
        token.kind = BinaryToken::Kind::ArrayBegin;
        return token;
    }
    if (code == 0314) return DefineRequest(bytes);
    if (code == 0315 || code == 0316) return DefineString(code, bytes);
    if (code == 0317 || code == 0320) return ReferenceString(code, bytes);
    return Error("reserved byte " + Octal(code));
}

BinaryToken BinaryDecoder::NextArrayItem(ByteSource& bytes) {
    if (arrayLeft_-- == 0) {
        BinaryToken token;
        token.kind = BinaryToken::Kind::ArrayEnd;
        return token;
    }
    BinaryToken item = DecodeFloat(bytes, 4);
    if (item.kind == BinaryToken::Kind::Error) {
        arrayLeft_ = -1;
        item.text = "the input ends inside a binary float array (the file is truncated)";
    }
    return item;
}

}  // namespace gonio
