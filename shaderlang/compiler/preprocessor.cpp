#include "shaderlang/compiler/preprocessor.h"

#include <cctype>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace gonio::sl {

namespace {

struct Macro {
    bool functionLike = false;
    std::vector<std::string> params;
    std::string body;
};

struct Conditional {
    bool active;        // lines in the current branch are kept
    bool taken;         // some branch of this #if was kept
    bool parentActive;  // the enclosing region is kept
    bool seenElse = false;
};

bool IsIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Replaces comments by spaces (keeping newlines, so line numbers stay), leaving strings alone.
std::string StripComments(const std::string& text) {
    std::string out = text;
    size_t i = 0;
    while (i < out.size()) {
        char c = out[i];
        if (c == '"') {
            for (++i; i < out.size() && out[i] != '"' && out[i] != '\n'; ++i) {
                if (out[i] == '\\') ++i;
            }
            ++i;
        } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
            out[i] = out[i + 1] = ' ';
            i += 2;
            while (i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/')) {
                if (out[i] != '\n') out[i] = ' ';
                ++i;
            }
            if (i < out.size()) out[i] = out[i + 1] = ' ', i += 2;
        } else {
            ++i;
        }
    }
    return out;
}

class Preprocessor {
  public:
    Preprocessor(const PreprocessOptions& options, Diagnostics& diagnostics)
        : options_(options), diagnostics_(diagnostics) {
        for (const auto& [name, value] : options.defines) {
            macros_[name].body = value.empty() ? "1" : value;
        }
    }

    void ProcessFile(const std::string& text, const std::string& fileName, int depth);
    std::string Output() const { return out_.str(); }
    int Errors() const { return errors_; }

  private:
    void Error(int line, int column, const std::string& message) {
        ++errors_;
        diagnostics_.Error(FileLoc{file_, line, column}, message);
    }
    void Directive(const std::string& line, int lineNumber, int depth, const std::string& dir);
    std::string Expand(const std::string& text, std::set<std::string>& disabled, int line);
    // Expand over a whole line, with no macro disabled; an expansion past kMaxExpandedLine (a
    // macro that doubles itself 30 times would take gigabytes) is an error and gives "".
    std::string ExpandLine(const std::string& text, int line);
    long EvaluateCondition(const std::string& text, int line);
    bool EndsInMacroCall(const std::string& text) const;
    bool Active() const { return conditionals_.empty() || conditionals_.back().active; }
    void Marker(int line) { out_ << "#line " << line << " \"" << *file_ << "\"\n"; }

    const PreprocessOptions& options_;
    Diagnostics& diagnostics_;
    std::map<std::string, Macro> macros_;
    std::vector<Conditional> conditionals_;
    std::shared_ptr<const std::string> file_;
    std::ostringstream out_;
    int errors_ = 0;
    bool expansionTooLarge_ = false;  // set by Expand past kMaxExpandedLine
};

constexpr size_t kMaxExpandedLine = size_t(1) << 20;

std::string Trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    size_t e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

std::string Directory(const std::string& path) {
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

void Preprocessor::ProcessFile(const std::string& text, const std::string& fileName, int depth) {
    auto saved = file_;
    file_ = std::make_shared<const std::string>(fileName);
    size_t conditionalDepth = conditionals_.size();
    std::string clean = StripComments(text);
    Marker(1);
    std::istringstream in(clean);
    std::string physical;
    int lineNumber = 0;
    // A file written on Windows ends its lines in CR LF: the CR is not part of the line (else a
    // backslash before it would not splice the next one).
    auto readLine = [&](std::string& out) {
        if (!std::getline(in, out)) return false;
        if (!out.empty() && out.back() == '\r') out.pop_back();
        return true;
    };
    while (readLine(physical)) {
        ++lineNumber;
        int first = lineNumber;
        std::string line = physical;
        // Line splicing: a backslash at the end joins the next line.
        while (!line.empty() && line.back() == '\\' && readLine(physical)) {
            line.pop_back();
            line += physical;
            ++lineNumber;
        }
        std::string trimmed = Trim(line);
        const bool directive = !trimmed.empty() && trimmed[0] == '#';
        // A function-like macro's arguments may span lines, as in C (`ADD(1,` / `2)`): the
        // lines are joined until the call's parenthesis closes.
        while (!directive && Active() && EndsInMacroCall(line) && readLine(physical)) {
            line += ' ' + physical;
            ++lineNumber;
        }
        if (directive) {
            Directive(trimmed.substr(1), first, depth, Directory(fileName));
        } else if (Active()) {
            out_ << ExpandLine(line, first) << '\n';
        } else {
            out_ << '\n';
        }
        for (int i = first; i < lineNumber; ++i) out_ << '\n';
    }
    if (conditionals_.size() > conditionalDepth) {
        Error(lineNumber, 1, "#if without #endif at the end of the file");
        conditionals_.resize(conditionalDepth);
    }
    file_ = saved;
}

void Preprocessor::Directive(const std::string& text, int line, int depth, const std::string& dir) {
    std::string rest = Trim(text);
    size_t nameEnd = 0;
    while (nameEnd < rest.size() && IsIdentChar(rest[nameEnd])) ++nameEnd;
    std::string name = rest.substr(0, nameEnd);
    std::string arg = Trim(rest.substr(nameEnd));
    const bool active = Active();

    if (name == "if" || name == "ifdef" || name == "ifndef") {
        bool value = false;
        if (active) {
            if (name == "if") {
                value = EvaluateCondition(arg, line) != 0;
            } else {
                std::string macro = arg.substr(0, arg.find_first_of(" \t"));
                if (macro.empty() || !IsIdentStart(macro[0])) {
                    Error(line, 1, "#" + name + " expects a macro name");
                }
                value = macros_.count(macro) == (name == "ifdef" ? 1u : 0u);
            }
        }
        conditionals_.push_back({active && value, value, active});
        out_ << '\n';
        return;
    }
    if (name == "elif" || name == "else" || name == "endif") {
        if (conditionals_.empty()) {
            Error(line, 1, "#" + name + " without #if");
            out_ << '\n';
            return;
        }
        Conditional& c = conditionals_.back();
        if (name == "endif") {
            conditionals_.pop_back();
        } else if (c.seenElse) {
            Error(line, 1, "#" + name + " after #else");
        } else if (name == "else") {
            c.seenElse = true;
            c.active = c.parentActive && !c.taken;
            c.taken = true;
        } else {
            bool value = c.parentActive && !c.taken && EvaluateCondition(arg, line) != 0;
            c.active = value;
            c.taken = c.taken || value;
        }
        out_ << '\n';
        return;
    }
    if (!active) {
        out_ << '\n';
        return;
    }
    if (name == "define") {
        size_t i = 0;
        while (i < arg.size() && IsIdentChar(arg[i])) ++i;
        std::string macroName = arg.substr(0, i);
        if (macroName.empty() || !IsIdentStart(macroName[0])) {
            Error(line, 1, "#define expects a macro name");
        } else {
            Macro macro;
            if (i < arg.size() && arg[i] == '(') {
                macro.functionLike = true;
                size_t close = arg.find(')', i);
                if (close == std::string::npos) {
                    Error(line, 1,
                          "missing ')' in the parameter list of macro '" + macroName + "'");
                    close = arg.size();
                }
                std::stringstream params(arg.substr(i + 1, close - i - 1));
                std::string p;
                while (std::getline(params, p, ',')) {
                    if (!Trim(p).empty()) macro.params.push_back(Trim(p));
                }
                i = std::min(close + 1, arg.size());
            }
            macro.body = Trim(arg.substr(i));
            macros_[macroName] = macro;
        }
    } else if (name == "undef") {
        macros_.erase(arg);
    } else if (name == "include") {
        char close = arg.empty() ? 0 : (arg[0] == '"' ? '"' : (arg[0] == '<' ? '>' : 0));
        size_t end = close ? arg.find(close, 1) : std::string::npos;
        if (end == std::string::npos) {
            Error(line, 1, "#include expects \"file\" or <file>");
        } else if (depth > 32) {
            Error(line, 1, "#include nested more than 32 deep (a recursive include?)");
        } else {
            std::string target = arg.substr(1, end - 1);
            std::vector<std::string> dirs;
            if (close == '"') dirs.push_back(dir);
            dirs.insert(dirs.end(), options_.includeDirs.begin(), options_.includeDirs.end());
            std::string text, found, why;
            for (const std::string& d : dirs) {
                std::string candidate = target[0] == '/' ? target : d + "/" + target;
                std::error_code error;
                if (!std::filesystem::exists(candidate, error)) continue;
                if (ReadTextFile(candidate, &text, &why)) found = candidate;
                break;
            }
            if (!why.empty()) {
                Error(line, 1, "cannot include '" + target + "': " + why);
            } else if (found.empty()) {
                Error(line, 1, "cannot find include file '" + target + "'");
            } else {
                ProcessFile(text, found, depth + 1);
                Marker(line + 1);
                return;
            }
        }
    } else if (name == "line" ||
               (!rest.empty() && std::isdigit(static_cast<unsigned char>(rest[0])))) {
        out_ << "#line " << (name == "line" ? arg : rest) << '\n';
        return;
    } else if (name == "error") {
        Error(line, 1, "#error " + arg);
    } else if (name == "pragma" || name == "warning" || name.empty()) {
        if (name == "warning") diagnostics_.Warning(FileLoc{file_, line, 1}, "#warning " + arg);
    } else {
        Error(line, 1, "unknown preprocessor directive #" + name);
    }
    out_ << '\n';
}

// Whether `text` ends inside the argument list of a call of a function-like macro.
bool Preprocessor::EndsInMacroCall(const std::string& text) const {
    size_t i = 0;
    auto skipString = [&] {
        for (++i; i < text.size() && text[i] != '"'; ++i) {
            if (text[i] == '\\') ++i;
        }
        ++i;
    };
    while (i < text.size()) {
        if (text[i] == '"') {
            skipString();
            continue;
        }
        if (!IsIdentStart(text[i])) {
            // Skip a number whole, so that the suffix of 1.0f is not taken for a name.
            if (std::isdigit(static_cast<unsigned char>(text[i])))
                while (i < text.size() && (IsIdentChar(text[i]) || text[i] == '.')) ++i;
            else
                ++i;
            continue;
        }
        size_t start = i;
        while (i < text.size() && IsIdentChar(text[i])) ++i;
        auto it = macros_.find(text.substr(start, i - start));
        if (it == macros_.end() || !it->second.functionLike) continue;
        size_t j = i;
        while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
        if (j >= text.size() || text[j] != '(') continue;
        int nesting = 0;
        for (i = j; i < text.size() && (i == j || nesting > 0);) {
            if (text[i] == '"') {
                skipString();
                continue;
            }
            if (text[i] == '(') ++nesting;
            if (text[i] == ')') --nesting;
            ++i;
        }
        if (nesting > 0) return true;
    }
    return false;
}

// Expands macros in `text`. `disabled` holds the macros being expanded, which are not expanded
// again inside themselves (C's rule, which also stops runaway recursion).
std::string Preprocessor::ExpandLine(const std::string& text, int line) {
    std::set<std::string> disabled;
    std::string expanded = Expand(text, disabled, line);
    if (!expansionTooLarge_) return expanded;
    expansionTooLarge_ = false;
    Error(line, 1,
          "the macros of this line expand to more than " + std::to_string(kMaxExpandedLine >> 20) +
              " MiB (a macro that doubles?)");
    return "";
}

std::string Preprocessor::Expand(const std::string& text, std::set<std::string>& disabled,
                                 int line) {
    std::string out;
    size_t i = 0;
    while (i < text.size()) {
        if (out.size() > kMaxExpandedLine) expansionTooLarge_ = true;
        if (expansionTooLarge_) return out;
        char c = text[i];
        if (c == '"') {
            size_t start = i;
            for (++i; i < text.size() && text[i] != '"'; ++i) {
                if (text[i] == '\\') ++i;
            }
            i = std::min(i + 1, text.size());
            out += text.substr(start, i - start);
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i < text.size() && (IsIdentChar(text[i]) || text[i] == '.')) out += text[i++];
            continue;
        }
        if (!IsIdentStart(c)) {
            out += c;
            ++i;
            continue;
        }
        size_t start = i;
        while (i < text.size() && IsIdentChar(text[i])) ++i;
        std::string word = text.substr(start, i - start);
        auto it = macros_.find(word);
        if (it == macros_.end() || disabled.count(word)) {
            out += word;
            continue;
        }
        const Macro& macro = it->second;
        std::string body = macro.body;
        if (macro.functionLike) {
            size_t j = i;
            while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
            if (j >= text.size() || text[j] != '(') {
                out += word;  // a function-like macro's name without arguments is not a call
                continue;
            }
            std::vector<std::string> args(1);
            int nesting = 0;
            for (++j; j < text.size(); ++j) {
                char a = text[j];
                if (a == '(') ++nesting;
                if (a == ')' && nesting-- == 0) break;
                if (a == ',' && nesting == 0) {
                    args.emplace_back();
                    continue;
                }
                args.back() += a;
            }
            if (j >= text.size()) {
                Error(line, int(start) + 1, "unterminated call of macro '" + word + "'");
                out += word;
                continue;
            }
            i = j + 1;
            if (args.size() == 1 && Trim(args[0]).empty() && macro.params.empty()) args.clear();
            if (args.size() != macro.params.size()) {
                Error(line, int(start) + 1,
                      "macro '" + word + "' expects " + std::to_string(macro.params.size()) +
                          " arguments, got " + std::to_string(args.size()));
                continue;
            }
            std::map<std::string, std::string> values;
            for (size_t k = 0; k < args.size(); ++k) {
                values[macro.params[k]] = Expand(Trim(args[k]), disabled, line);
            }
            std::string substituted;
            for (size_t k = 0; k < body.size();) {
                if (IsIdentStart(body[k])) {
                    size_t e = k;
                    while (e < body.size() && IsIdentChar(body[e])) ++e;
                    std::string id = body.substr(k, e - k);
                    auto v = values.find(id);
                    substituted += v == values.end() ? id : v->second;
                    k = e;
                } else {
                    substituted += body[k++];
                }
            }
            body = substituted;
        }
        disabled.insert(word);
        out += Expand(body, disabled, line);
        disabled.erase(word);
    }
    return out;
}

// Integer expressions of #if / #elif (C's operators and precedences).
class ConditionParser {
  public:
    explicit ConditionParser(const std::string& text) : s_(text) {}
    bool Parse(long* value) {
        *value = Ternary();
        Skip();
        return ok_ && pos_ == s_.size();
    }

  private:
    void Skip() {
        while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    }
    bool Accept(const char* op) {
        Skip();
        size_t n = std::char_traits<char>::length(op);
        if (s_.compare(pos_, n, op) != 0) return false;
        // Do not take '<' out of '<<' or '<=', '&' out of '&&' and the like.
        if (n == 1 && pos_ + 1 < s_.size()) {
            char next = s_[pos_ + 1];
            if ((op[0] == '<' || op[0] == '>') && (next == op[0] || next == '=')) return false;
            if ((op[0] == '&' || op[0] == '|') && next == op[0]) return false;
            if ((op[0] == '!' || op[0] == '=') && next == '=') return false;
        }
        pos_ += n;
        return true;
    }
    // Parentheses, ?: and unary operators recurse: a bound on the nesting makes a pathological
    // expression an error rather than a stack overflow.
    struct Nested {
        explicit Nested(ConditionParser& parser) : parser(parser) {
            if (++parser.nesting_ > kMaxNesting) parser.ok_ = false;
        }
        ~Nested() { --parser.nesting_; }
        ConditionParser& parser;
    };
    long Ternary() {
        Nested nested(*this);
        if (!ok_) return 0;
        long c = Binary(0);
        if (Accept("?")) {
            long a = Ternary();
            if (!Accept(":")) ok_ = false;
            long b = Ternary();
            return c ? a : b;
        }
        return c;
    }
    long Binary(int level) {
        static const std::vector<std::vector<const char*>> levels = {{"||"},
                                                                     {"&&"},
                                                                     {"|"},
                                                                     {"^"},
                                                                     {"&"},
                                                                     {"==", "!="},
                                                                     {"<=", ">=", "<", ">"},
                                                                     {"<<", ">>"},
                                                                     {"+", "-"},
                                                                     {"*", "/", "%"}};
        if (level == int(levels.size())) return Unary();
        long left = Binary(level + 1);
        for (bool more = true; more;) {
            more = false;
            for (const char* op : levels[level]) {
                if (!Accept(op)) continue;
                long right = Binary(level + 1);
                left = Apply(op, left, right);
                more = true;
                break;
            }
        }
        return left;
    }
    long Apply(const std::string& op, long a, long b) {
        if (op == "||") return a || b;
        if (op == "&&") return a && b;
        if (op == "|") return a | b;
        if (op == "^") return a ^ b;
        if (op == "&") return a & b;
        if (op == "==") return a == b;
        if (op == "!=") return a != b;
        if (op == "<=") return a <= b;
        if (op == ">=") return a >= b;
        if (op == "<") return a < b;
        if (op == ">") return a > b;
        // Wrapping arithmetic: overflow in a #if must not be undefined behaviour.
        using U = unsigned long;
        if (op == "<<") return b >= 0 && b < 63 ? long(U(a) << b) : 0;
        if (op == ">>") return b >= 0 && b < 63 ? a >> b : 0;
        if (op == "+") return long(U(a) + U(b));
        if (op == "-") return long(U(a) - U(b));
        if (op == "*") return long(U(a) * U(b));
        if ((op == "/" || op == "%") && (b == 0 || (b == -1 && a == LONG_MIN))) {
            ok_ = false;
            return 0;
        }
        return op == "/" ? a / b : a % b;
    }
    long Unary() {
        Nested nested(*this);
        if (!ok_) return 0;
        if (Accept("!")) return !Unary();
        if (Accept("-")) return long(0ul - static_cast<unsigned long>(Unary()));
        if (Accept("+")) return Unary();
        if (Accept("~")) return ~Unary();
        if (Accept("(")) {
            long v = Ternary();
            if (!Accept(")")) ok_ = false;
            return v;
        }
        Skip();
        if (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) {
            char* end = nullptr;
            long v = std::strtol(s_.c_str() + pos_, &end, 0);  // saturates instead of throwing
            pos_ = size_t(end - s_.c_str());
            while (pos_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[pos_]))) ++pos_;
            return v;
        }
        ok_ = false;
        return 0;
    }

    static constexpr int kMaxNesting = 200;
    const std::string& s_;
    size_t pos_ = 0;
    bool ok_ = true;
    int nesting_ = 0;
};

long Preprocessor::EvaluateCondition(const std::string& text, int line) {
    // defined X and defined(X) first, so that the macro X is not expanded; then macros; then
    // any identifier left is 0, as in C.
    std::string resolved;
    for (size_t i = 0; i < text.size();) {
        if (IsIdentStart(text[i])) {
            size_t e = i;
            while (e < text.size() && IsIdentChar(text[e])) ++e;
            std::string word = text.substr(i, e - i);
            if (word == "defined") {
                size_t k = e;
                while (k < text.size() && text[k] == ' ') ++k;
                bool paren = k < text.size() && text[k] == '(';
                if (paren) ++k;
                while (k < text.size() && text[k] == ' ') ++k;
                size_t ne = k;
                while (ne < text.size() && IsIdentChar(text[ne])) ++ne;
                resolved += macros_.count(text.substr(k, ne - k)) ? " 1 " : " 0 ";
                if (paren) {
                    while (ne < text.size() && text[ne] == ' ') ++ne;
                    if (ne < text.size() && text[ne] == ')') ++ne;
                }
                i = ne;
                continue;
            }
            resolved += word;
            i = e;
        } else {
            resolved += text[i++];
        }
    }
    const std::string expanded = ExpandLine(resolved, line);
    std::string numeric;
    for (size_t i = 0; i < expanded.size();) {
        if (IsIdentStart(expanded[i])) {
            while (i < expanded.size() && IsIdentChar(expanded[i])) ++i;
            numeric += " 0 ";
        } else {
            numeric += expanded[i++];
        }
    }
    long value = 0;
    ConditionParser parser(numeric);
    if (!parser.Parse(&value)) Error(line, 1, "invalid #if expression: " + Trim(text));
    return value;
}

}  // namespace

bool ReadTextFile(const std::string& path, std::string* text, std::string* why) {
    auto fail = [&](const std::string& reason) {
        if (why) *why = reason;
        return false;
    };
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return fail("not a regular file");
    if (std::filesystem::file_size(path, error) > kMaxSourceBytes)
        return fail("larger than " + std::to_string(kMaxSourceBytes >> 20) + " MiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail("cannot be read");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return fail("cannot be read");
    *text = buffer.str();
    return true;
}

bool Preprocess(const std::string& source, const std::string& fileName,
                const PreprocessOptions& options, std::string* output, Diagnostics& diagnostics) {
    Preprocessor pp(options, diagnostics);
    pp.ProcessFile(source, fileName, 0);
    *output = pp.Output();
    return pp.Errors() == 0;
}

}  // namespace gonio::sl
