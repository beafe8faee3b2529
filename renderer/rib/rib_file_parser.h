#pragma once
// One RIB input (a file, an archive, standard input or a string) being parsed: its Flex scanner
// and Bison parser, the values of the request being read, and the functions the lexer and the
// grammar actions call. Archives get a RibFileParser of their own; what they share (the target,
// the search path, the include stack) lives in RibSession.

#include <zlib.h>

#include <cstdint>
#include <memory>
#include <string>

#include "base/file_loc.h"
#include "renderer/rib/request_table.h"
#include "renderer/rib/request_values.h"
#include "renderer/rib/rib_binary.h"

namespace gonio {

class RibSession;

class RibFileParser {
  public:
    RibFileParser(RibSession& session, std::shared_ptr<const std::string> name, gzFile input);
    RibFileParser(RibSession& session, std::shared_ptr<const std::string> name,
                  const std::string& text);

    // Reads the whole input, calling the session's target once per request (rib_lexer.l).
    void Parse();

    // The lexer's position: the line and column of the next character, and the bytes consumed.
    int line = 1;
    int column = 1;
    std::int64_t offset = 0;

    // Called by the lexer.
    int ReadInput(char* buffer, int maxSize);
    std::int64_t Delivered() const { return delivered_; }  // bytes ReadInput has handed over
    bool ParseNumber(const char* text, int length, double* value);
    int NewString(const char* text, int length);  // decodes C escapes; returns the pool index
    // A request table index, or for an unknown name a negative number that Dispatch turns back
    // into the name.
    int LookupRequest(const char* text, int length);
    void LexError(int errorLine, int errorColumn, const std::string& message);
    // A binary token (RISpec App. C.2) whose code byte was just read: returns the grammar token
    // and sets `number` or `index`, or returns 0 for a definition, which is no token.
    int BinaryToken(int code, ByteSource& bytes, double* number, int* index, int tokenLine,
                    int tokenColumn);
    bool InBinaryArray() const { return binary_.InArray(); }
    int BinaryArrayItem(ByteSource& bytes, double* number, int tokenLine, int tokenColumn);
    void SetLookahead(int token, int tokenLine, int tokenColumn);
    bool ShouldStop() const;

    // Called by the grammar actions.
    void AddNumber(double number, int valueLine, int valueColumn);
    void AddString(int index, int valueLine, int valueColumn);
    void BeginArray();
    void ArrayNumber(double number) { arrayNumbers_->push_back(number); }  // hot: inline
    void ArrayString(int index);
    void EndArray(int openLine, int openColumn);
    void Dispatch(int request, int requestLine, int requestColumn);
    void Discard();
    void SyntaxError();

  private:
    FileLoc Loc(int atLine, int atColumn) const { return FileLoc{name_, atLine, atColumn}; }
    std::string DescribeLookahead() const;

    RibSession& session_;
    std::shared_ptr<const std::string> name_;
    gzFile input_ = nullptr;
    const std::string* text_ = nullptr;
    std::int64_t delivered_ = 0;
    bool inputEnded_ = false;  // a binary token was cut off by the end of the input
    BinaryDecoder binary_;

    RequestValues values_;
    RequestArgs args_;         // reused so that its vectors keep their capacity
    bool requestBad_ = false;  // an error inside the request was already reported

    // The array being read.
    bool inArray_ = false;
    int arrayLine_ = 0, arrayColumn_ = 0;
    std::vector<double>* arrayNumbers_ = nullptr;  // its numbers
    std::size_t arrayIndex_ = 0;
    std::size_t arrayStringsBegin_ = 0, arrayStrings_ = 0;

    // The token the grammar is looking at, for syntax error messages.
    int lookahead_ = 0;
    int lookaheadLine_ = 0, lookaheadColumn_ = 0;
    std::string lastRequestName_;  // of the last request name read, known or not
    // Unknown request names: the current request's and the lookahead's may both be unknown.
    std::string unknownNames_[2];
    int nextUnknown_ = 0;
    bool readFailed_ = false;
};

}  // namespace gonio
