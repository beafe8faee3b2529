// The per-input parsing state: values of the current request, strings and numbers from the
// lexer, and the dispatch of each finished request through the request table.

#include "renderer/rib/rib_file_parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "renderer/rib/rib_session.h"
#include "renderer/rib/string_escapes.h"
#include "rib_grammar.hpp"

namespace gonio {
namespace {

// Binary input has no lines to speak of: its errors also say where they are in bytes.
std::string AtOffset(std::int64_t offset) {
    return "binary RIB at byte offset " + std::to_string(offset) + ": ";
}

}  // namespace

RibFileParser::RibFileParser(RibSession& session, std::shared_ptr<const std::string> name,
                             gzFile input)
    : session_(session), name_(std::move(name)), input_(input) {}

RibFileParser::RibFileParser(RibSession& session, std::shared_ptr<const std::string> name,
                             const std::string& text)
    : session_(session), name_(std::move(name)), text_(&text) {}

int RibFileParser::ReadInput(char* buffer, int maxSize) {
    if (text_) {
        const std::size_t got = std::min(static_cast<std::size_t>(maxSize),
                                         text_->size() - static_cast<std::size_t>(delivered_));
        std::memcpy(buffer, text_->data() + delivered_, got);
        delivered_ += static_cast<std::int64_t>(got);
        return static_cast<int>(got);
    }
    if (!input_ || readFailed_) return 0;
    const int got = gzread(input_, buffer, static_cast<unsigned>(maxSize));
    if (got > 0) delivered_ += got;
    int code = 0;
    const char* why = gzerror(input_, &code);
    // gzread hands over what it could decompress of a cut stream and flags the early end as
    // Z_BUF_ERROR only through gzerror: without this check a truncated .rib.gz renders its first
    // frames and exits 0.
    if (got >= 0 && code != Z_BUF_ERROR) return got;
    if (code == Z_ERRNO) why = std::strerror(errno);
    if (code == Z_BUF_ERROR) why = "the compressed stream ends early (the file is truncated)";
    session_.Error(Loc(line, column), std::string("cannot read the file: ") + why);
    readFailed_ = true;
    return std::max(got, 0);
}

bool RibFileParser::ParseNumber(const char* text, int length, double* value) {
    if (*text == '+') ++text, --length;  // from_chars does not take a leading '+'
    const auto result = std::from_chars(text, text + length, *value);
    if (result.ec == std::errc()) return true;
    // Out of range: an underflow is a harmless zero, an overflow is an error.
    *value = std::strtod(text, nullptr);
    return std::isfinite(*value);
}

int RibFileParser::NewString(const char* text, int length) {
    std::size_t index = 0;
    DecodeEscapes(text, length, &values_.NewString(&index));
    return static_cast<int>(index);
}

int RibFileParser::LookupRequest(const char* text, int length) {
    lastRequestName_.assign(text, static_cast<std::size_t>(length));
    const RequestRule* rule = FindRequest(lastRequestName_);
    if (rule) return static_cast<int>(rule - AllRequests().data());
    unknownNames_[nextUnknown_] = lastRequestName_;
    const int code = -2 - nextUnknown_;
    nextUnknown_ ^= 1;
    return code;
}

void RibFileParser::LexError(int errorLine, int errorColumn, const std::string& message) {
    session_.Error(Loc(errorLine, errorColumn), message);
}

void RibFileParser::SetLookahead(int token, int tokenLine, int tokenColumn) {
    lookahead_ = token;
    lookaheadLine_ = tokenLine;
    lookaheadColumn_ = tokenColumn;
    if (token == '[' && !inArray_) {  // the '[' that opens an array (they do not nest)
        arrayLine_ = tokenLine;
        arrayColumn_ = tokenColumn;
    }
}

bool RibFileParser::ShouldStop() const { return session_.Stopped() || inputEnded_; }

int RibFileParser::BinaryToken(int code, ByteSource& bytes, double* number, int* index,
                               int tokenLine, int tokenColumn) {
    const std::int64_t start = offset - 1;
    gonio::BinaryToken token = binary_.Decode(code, bytes);
    switch (token.kind) {
        case BinaryToken::Kind::Definition:
            return 0;
        case BinaryToken::Kind::Number:
            *number = token.number;
            return RIB_NUMBER;
        case BinaryToken::Kind::String: {
            std::size_t slot = 0;
            values_.NewString(&slot) = std::move(token.text);
            *index = static_cast<int>(slot);
            return RIB_STRING;
        }
        case BinaryToken::Kind::Request:
            *index = LookupRequest(token.text.data(), static_cast<int>(token.text.size()));
            return RIB_REQUEST;
        case BinaryToken::Kind::ArrayBegin:
            return '[';
        case BinaryToken::Kind::ArrayEnd:
        case BinaryToken::Kind::Error:
            break;
    }
    inputEnded_ = token.truncated;
    LexError(tokenLine, tokenColumn, AtOffset(start) + token.text);
    return RIB_LEX_ERROR;
}

int RibFileParser::BinaryArrayItem(ByteSource& bytes, double* number, int tokenLine,
                                   int tokenColumn) {
    const std::int64_t start = offset;
    gonio::BinaryToken item = binary_.NextArrayItem(bytes);
    if (item.kind == BinaryToken::Kind::ArrayEnd) return ']';
    if (item.kind == BinaryToken::Kind::Number) {
        *number = item.number;
        return RIB_NUMBER;
    }
    inputEnded_ = true;
    LexError(tokenLine, tokenColumn, AtOffset(start) + item.text);
    return RIB_LEX_ERROR;
}

void RibFileParser::AddNumber(double number, int valueLine, int valueColumn) {
    RibValue value;
    value.kind = ValueKind::Number;
    value.line = valueLine;
    value.column = valueColumn;
    value.begin = values_.numbers.size();
    values_.numbers.push_back(number);
    values_.values.push_back(value);
}

void RibFileParser::AddString(int index, int valueLine, int valueColumn) {
    RibValue value;
    value.kind = ValueKind::String;
    value.line = valueLine;
    value.column = valueColumn;
    value.begin = static_cast<std::size_t>(index);
    values_.values.push_back(value);
}

void RibFileParser::BeginArray() {
    inArray_ = true;
    arrayNumbers_ = &values_.NewArray(&arrayIndex_);
    arrayStrings_ = 0;
}

void RibFileParser::ArrayString(int index) {
    // The lexer fills the pool in order, so an array's strings are consecutive.
    if (arrayStrings_++ == 0) arrayStringsBegin_ = static_cast<std::size_t>(index);
}

void RibFileParser::EndArray(int openLine, int openColumn) {
    inArray_ = false;
    if (!arrayNumbers_->empty() && arrayStrings_) {
        session_.Error(Loc(openLine, openColumn),
                       "array mixes numbers and strings (an array holds one or the other)");
        requestBad_ = true;
        return;
    }
    RibValue value;
    value.line = openLine;
    value.column = openColumn;
    if (arrayStrings_) {
        value.kind = ValueKind::StringArray;
        value.begin = arrayStringsBegin_;
        value.count = arrayStrings_;
    } else {
        value.kind = ValueKind::NumberArray;
        value.begin = arrayIndex_;
        value.count = arrayNumbers_->size();
    }
    values_.values.push_back(value);
}

void RibFileParser::Dispatch(int request, int requestLine, int requestColumn) {
    const FileLoc loc = Loc(requestLine, requestColumn);
    if (request < 0) {
        session_.Error(loc, "unknown request '" + unknownNames_[-2 - request] + "'");
    } else if (!requestBad_) {
        const RequestRule& rule = AllRequests()[static_cast<std::size_t>(request)];
        MatchError error;
        if (MatchRequest(rule, values_, session_.ColorComponents(), loc, &args_, &error))
            rule.call(args_, session_.Target(), session_);
        else
            session_.Error(Loc(error.line, error.column), error.message);
    }
    Discard();
}

void RibFileParser::Discard() {
    values_.Clear();
    requestBad_ = false;
    inArray_ = false;
}

std::string RibFileParser::DescribeLookahead() const {
    switch (lookahead_) {
        case 0:
            return "the end of the file";
        case RIB_NUMBER:
            return "a number";
        case RIB_STRING:
            return "a string";
        case RIB_REQUEST:
            return "request '" + lastRequestName_ + "'";
        case '[':
            return "'['";
        case ']':
            return "']'";
    }
    return "an unexpected token";
}

void RibFileParser::SyntaxError() {
    if (lookahead_ == RIB_LEX_ERROR) return;  // the lexer has said what is wrong
    const FileLoc loc = Loc(lookaheadLine_, lookaheadColumn_);
    std::string message;
    if (inArray_ && lookahead_ == '[') {
        message = "arrays cannot be nested (the array opened at " + std::to_string(arrayLine_) +
                  ":" + std::to_string(arrayColumn_) + " is still open)";
    } else if (inArray_) {
        message = "expected ']' to close the array opened at " + std::to_string(arrayLine_) + ":" +
                  std::to_string(arrayColumn_) + ", found " + DescribeLookahead();
    } else if (lookahead_ == ']') {
        message = "']' without a matching '['";
    } else {
        message = "expected a request name, found " + DescribeLookahead();
    }
    session_.Error(loc, message);
}

}  // namespace gonio
