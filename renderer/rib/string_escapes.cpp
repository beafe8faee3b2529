// The C escapes of RIB string constants (RISpec App. C.1): \n \t \r \b \f \a \v, octal
// \ddd, hex \xhh; any other escaped character stands for itself.

#include "renderer/rib/string_escapes.h"

namespace gonio {
namespace {

int OctalDigit(char c) { return c >= '0' && c <= '7' ? c - '0' : -1; }

int HexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

void DecodeEscapes(const char* text, int length, std::string* out) {
    out->clear();
    for (int i = 0; i < length; ++i) {
        if (text[i] != '\\' || i + 1 == length) {
            out->push_back(text[i]);
            continue;
        }
        const char c = text[++i];
        switch (c) {
            case 'n':
                out->push_back('\n');
                break;
            case 't':
                out->push_back('\t');
                break;
            case 'r':
                out->push_back('\r');
                break;
            case 'b':
                out->push_back('\b');
                break;
            case 'f':
                out->push_back('\f');
                break;
            case 'a':
                out->push_back('\a');
                break;
            case 'v':
                out->push_back('\v');
                break;
            case 'x': {
                int value = 0, digits = 0;
                while (digits < 2 && i + 1 < length && HexDigit(text[i + 1]) >= 0)
                    value = value * 16 + HexDigit(text[++i]), ++digits;
                out->push_back(digits ? static_cast<char>(value) : 'x');
                break;
            }
            default:
                if (OctalDigit(c) >= 0) {
                    int value = OctalDigit(c), digits = 1;
                    while (digits < 3 && i + 1 < length && OctalDigit(text[i + 1]) >= 0)
                        value = value * 8 + OctalDigit(text[++i]), ++digits;
                    out->push_back(static_cast<char>(value));
                } else {
                    out->push_back(c);  // \\ \" \' \? and anything else stand for themselves
                }
        }
    }
}

}  // namespace gonio
