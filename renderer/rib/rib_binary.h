#pragma once
// The binary encoding of RIB (RISpec 3.2 App. C.2): a byte >= 0200 outside a string constant
// starts an encoded token. The lexer (rib_lexer.l) hands the code byte and the bytes that follow
// to a BinaryDecoder, which turns them into the same tokens the ASCII rules produce (a number, a
// string, a request name, an array of numbers), so that ASCII and binary mix freely in one input.
// The decoder also keeps what a binary stream defines for later reference: encoded requests
// (0314, referenced by 0246) and defined strings (0315-0316, referenced by 0317-0320).

#include <cstdint>
#include <string>
#include <unordered_map>

namespace gonio {

// The bytes after a code byte, one at a time.
class ByteSource {
  public:
    virtual ~ByteSource() = default;
    virtual int Next() = 0;  // 0..255, or -1 at the end of the input
};

struct BinaryToken {
    enum class Kind {
        Definition,  // a request or string was defined: no token, lexing goes on
        Number,
        String,
        Request,     // `text` is the request's name
        ArrayBegin,  // a float array (0310-0313): its items follow through NextArrayItem
        ArrayEnd,
        Error,  // `text` says what is wrong; `truncated`: the input ended inside the token
    };
    Kind kind = Kind::Definition;
    double number = 0;
    std::string text;
    bool truncated = false;
};

class BinaryDecoder {
  public:
    // Decodes the token whose code byte (0200-0377) has just been read.
    BinaryToken Decode(int code, ByteSource& bytes);
    // True while a float array's items are being handed over.
    bool InArray() const { return arrayLeft_ >= 0; }
    // The next item of the current float array (a Number), or ArrayEnd after the last one.
    BinaryToken NextArrayItem(ByteSource& bytes);

  private:
    bool ReadUnsigned(ByteSource& bytes, int count, std::uint32_t* value, BinaryToken* error);
    BinaryToken DecodeNumber(int code, ByteSource& bytes);
    BinaryToken DecodeString(std::uint32_t length, ByteSource& bytes);
    BinaryToken DecodeFloat(ByteSource& bytes, int size);
    // The string operand of a definition: encoded, a reference, or an ASCII "..." constant.
    BinaryToken ReadStringOperand(ByteSource& bytes);
    BinaryToken ReadQuotedString(ByteSource& bytes);
    BinaryToken DefineRequest(ByteSource& bytes);
    BinaryToken DefineString(int code, ByteSource& bytes);
    BinaryToken ReferenceString(int code, ByteSource& bytes);

    std::string requests_[256];  // encoded requests; an empty name is undefined
    std::unordered_map<std::uint32_t, std::string> strings_;
    std::int64_t arrayLeft_ = -1;
};

}  // namespace gonio
