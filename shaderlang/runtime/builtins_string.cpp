// String built-ins (RISpec §15.5): printf, format, concat, match.
//
// Conversions: %f %e %g (float), %d %i (float printed as an integer), %p (point, vector or
// normal: three numbers), %c (colour: ncomps numbers), %m (matrix: 16 numbers), %s (string, or
// any value), %% (a percent sign). Flags, width and precision apply to each number. printf with
// varying arguments prints one line per active point.

#include <cstdio>
#include <regex>

#include "shaderlang/runtime/builtins_util.h"
#include "shaderlang/shading_context.h"

namespace gonio::sl::builtins {

namespace {

std::string FormatNumber(const std::string& spec, char conversion, float value) {
    char buffer[64];
    if (conversion == 'd' || conversion == 'i') {
        std::string format = spec + "d";
        std::snprintf(buffer, sizeof buffer, format.c_str(), static_cast<int>(value));
    } else {
        std::string format = spec + conversion;
        std::snprintf(buffer, sizeof buffer, format.c_str(), static_cast<double>(value));
    }
    return buffer;
}

// Every number of argument a at point p, joined by spaces, each formatted by spec + conversion.
std::string FormatValues(const BuiltinCall& call, int a, int p, const std::string& spec,
                         char conversion) {
    std::string out;
    for (int c = 0; c < call.args[a].width; ++c) {
        if (c > 0) out += ' ';
        out += FormatNumber(spec, conversion, call.args[a].At(c, p));
    }
    return out;
}

std::string FormatArgument(const BuiltinCall& call, int a, int p, const std::string& spec,
                           char conversion) {
    if (call.argTypes[a].base == BaseType::String) {
        const StringArg& s = call.strings[a];
        if (!s.data) return "";
        std::string text = s.data[0];
        for (int i = 1; i < call.argTypes[a].arrayLength; ++i) text += " " + s.data[i];
        return text;
    }
    switch (conversion) {
        case 'd':
        case 'i':
        case 'e':
        case 'g':
            return FormatValues(call, a, p, spec, conversion);
        default:
            return FormatValues(call, a, p, spec, 'f');  // f, p, c, m, s of a number
    }
}

// Formats the call's first (string) argument with the following arguments at point p.
std::string FormatAt(const BuiltinCall& call, int p) {
    const std::string& format = call.strings[0].data[0];
    std::string out;
    int next = 1;
    for (size_t i = 0; i < format.size(); ++i) {
        if (format[i] != '%') {
            out += format[i];
            continue;
        }
        size_t j = i + 1;
        while (j < format.size() &&
               std::string("-+ #0123456789.").find(format[j]) != std::string::npos) {
            ++j;
        }
        if (j >= format.size()) {
            out += format.substr(i);
            break;
        }
        char conversion = format[j];
        if (conversion == '%') {
            out += '%';
        } else if (next < call.argCount) {
            out += FormatArgument(call, next++, p, format.substr(i, j - i), conversion);
        } else {
            out += format.substr(i, j - i + 1);  // more conversions than arguments: print as is
        }
        i = j;
    }
    return out;
}

void PrintfKernel(const BuiltinCall& call) {
    if (!call.context) return;
    ForEachPoint(call, [&](int p) { call.context->Print(FormatAt(call, p)); });
}

// Strings are uniform, so format() of varying values formats the first active point.
int FirstActivePoint(const BuiltinCall& call) {
    if (!IsVaryingCall(call)) return 0;
    for (int p = 0; p < call.n; ++p) {
        if (call.IsActive(p)) return p;
    }
    return 0;
}

void FormatKernel(const BuiltinCall& call) {
    call.stringResult.data[0] = FormatAt(call, FirstActivePoint(call));
}

void ConcatKernel(const BuiltinCall& call) {
    std::string out;
    for (int a = 0; a < call.argCount; ++a) out += call.strings[a].data[0];
    call.stringResult.data[0] = out;
}

// match(pattern, subject): 1 if the regular expression (ECMAScript syntax) matches anywhere in
// subject. A malformed pattern warns and gives 0.
void MatchKernel(const BuiltinCall& call) {
    const std::string& pattern = call.strings[0].data[0];
    const std::string& subject = call.strings[1].data[0];
    float found = 0.0f;
    try {
        found = std::regex_search(subject, std::regex(pattern)) ? 1.0f : 0.0f;
    } catch (const std::regex_error& e) {
        if (call.context) {
            call.context->RuntimeWarning("match:" + pattern, "match: bad regular expression \"" +
                                                                 pattern + "\": " + e.what());
        }
    }
    ForEachPoint(call, [&](int p) { call.result.At(0, p) = found; });
}

}  // namespace

void AddStringBuiltins(BuiltinList* list) {
    list->Add("printf", "x", "s*", PrintfKernel, kHasSideEffects);
    list->Add("format", "s", "s*", FormatKernel);
    std::string strings = "s";
    for (int count = 2; count <= 16; ++count) {
        strings += "s";
        list->Add("concat", "s", strings, ConcatKernel);
    }
    list->Add("concat", "s", "s", ConcatKernel);
    list->Add("match", "f", "ss", MatchKernel);
}

}  // namespace gonio::sl::builtins
