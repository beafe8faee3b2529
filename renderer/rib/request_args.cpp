// Matching a request's values against its signature, and typed access to the result.

#include <cfloat>
#include <climits>
#include <cmath>

#include "base/diagnostics.h"
#include "renderer/rib/request_table.h"

namespace gonio {
namespace {

// Converts without undefined behaviour: a double beyond float range becomes an infinity.
float ToFloat(double value) {
    if (value > FLT_MAX) return INFINITY;
    if (value < -FLT_MAX) return -INFINITY;
    return static_cast<float>(value);
}

bool IsInteger(double value) {
    return value >= INT_MIN && value <= INT_MAX && value == std::floor(value);
}

bool IsNumberSignature(std::string_view signature) {
    return signature.find_first_not_of("fi") == std::string_view::npos;
}

std::string Plural(std::size_t count, const char* noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

}  // namespace

std::string DescribeValue(const RibValue& value) {
    switch (value.kind) {
        case ValueKind::Number:
            return "a number";
        case ValueKind::String:
            return "a string";
        case ValueKind::NumberArray:
            return "an array of " + Plural(value.count, "number");
        case ValueKind::StringArray:
            return "an array of " + Plural(value.count, "string");
    }
    return "a value";
}

// Tries each alternative of a rule's signature in turn; reports the last one's error.
class RequestMatcher {
  public:
    RequestMatcher(const RequestRule& rule, RequestValues& values, int ncomps, const FileLoc& loc)
        : rule_(rule), values_(values), ncomps_(ncomps), loc_(loc) {}

    bool Match(RequestArgs* args, MatchError* error) {
        std::string_view signatures = rule_.signature;
        for (int alternative = 0;; ++alternative) {
            const std::size_t bar = signatures.find('|');
            std::string_view signature = signatures.substr(0, bar);
            args->slots_.clear();
            args->params_.clear();
            args->values_ = &values_;
            args->loc_ = loc_;
            args->name_ = rule_.name;
            args->alternative_ = alternative;
            if (MatchAlternative(signature, args, error)) return true;
            if (bar == std::string_view::npos) return false;
            signatures.remove_prefix(bar + 1);
        }
    }

  private:
    const std::vector<RibValue>& Values() const { return values_.values; }

    bool Fail(MatchError* error, int line, int column, std::string message) {
        error->line = line;
        error->column = column;
        error->message = std::move(message);
        return false;
    }
    bool FailAt(MatchError* error, const RibValue& value, std::string message) {
        return Fail(error, value.line, value.column, std::move(message));
    }
    bool FailAtRequest(MatchError* error, std::string message) {
        return Fail(error, loc_.line, loc_.column, std::move(message));
    }

    bool MatchAlternative(std::string_view signature, RequestArgs* args, MatchError* error) {
        if (signature == "*") return true;
        std::string expanded;
        bool arrayForm = false;
        if (signature == "c") {
            expanded.assign(static_cast<std::size_t>(ncomps_), 'f');
            arrayForm = true;
        } else {
            expanded.assign(signature);
            arrayForm =
                expanded.size() >= 2 && expanded.find_first_not_of('f') == std::string::npos;
        }
        std::size_t next = 0;
        const bool ok = IsNumberSignature(expanded)
                            ? MatchNumbers(expanded, arrayForm, args, &next, error)
                            : MatchMixed(expanded, args, &next, error);
        return ok && MatchParams(next, expanded.size(), args, error);
    }

    // Floats and integers only: "Sphere expects 4 numbers, got 3".
    bool MatchNumbers(const std::string& signature, bool arrayForm, RequestArgs* args,
                      std::size_t* next, MatchError* error) {
        const std::vector<RibValue>& values = Values();
        const std::size_t wanted = signature.size();
        if (wanted == 0) return true;
        if (!values.empty() && values[0].kind == ValueKind::NumberArray &&
            (arrayForm || wanted == 1)) {
            if (values[0].count != wanted)
                return FailAt(error, values[0],
                              std::string(rule_.name) + " expects " + Plural(wanted, "number") +
                                  ", got " + std::to_string(values[0].count));
            for (std::size_t k = 0; k < wanted; ++k) args->slots_.push_back({&values[0], k});
            *next = 1;
        } else {
            std::size_t scalars = 0;
            while (scalars < values.size() && values[scalars].kind == ValueKind::Number) ++scalars;
            if (scalars != wanted && !(scalars > wanted && rule_.takesParams)) {
                return FailAtRequest(error, std::string(rule_.name) + " expects " +
                                                Plural(wanted, "number") + ", got " +
                                                std::to_string(scalars));
            }
            for (std::size_t k = 0; k < wanted; ++k) args->slots_.push_back({&values[k], 0});
            *next = wanted;
        }
        for (std::size_t k = 0; k < wanted; ++k) {
            if (signature[k] != 'i') continue;
            const double number = args->Number(static_cast<int>(k));
            if (!IsInteger(number))
                return FailAt(error, *args->slots_[k].value,
                              std::string(rule_.name) + " argument " + std::to_string(k + 1) +
                                  " must be an integer, got " + FormatNumber(number));
        }
        return true;
    }

    bool MatchMixed(const std::string& signature, RequestArgs* args, std::size_t* next,
                    MatchError* error) {
        const std::vector<RibValue>& values = Values();
        if (values.size() < signature.size())
            return FailAtRequest(error, std::string(rule_.name) + " expects " +
                                            Plural(signature.size(), "argument") + ", got " +
                                            std::to_string(values.size()));
        for (std::size_t k = 0; k < signature.size(); ++k) {
            const RibValue& value = values[k];
            const char* expected = CheckSlot(signature[k], value);
            if (expected)
                return FailAt(error, value,
                              std::string(rule_.name) + " argument " + std::to_string(k + 1) +
                                  " must be " + expected + ", got " + DescribeValue(value));
            args->slots_.push_back({&value, 0});
        }
        *next = signature.size();
        return true;
    }

    // nullptr if `value` fits `letter`, else what was expected.
    const char* CheckSlot(char letter, const RibValue& value) const {
        const bool number = value.kind == ValueKind::Number ||
                            (value.kind == ValueKind::NumberArray && value.count == 1);
        const bool string = value.kind == ValueKind::String ||
                            (value.kind == ValueKind::StringArray && value.count == 1);
        switch (letter) {
            case 'f':
                return number ? nullptr : "a number";
            case 'i':
                return number && IsInteger(values_.Number(value, 0)) ? nullptr : "an integer";
            case 's':
                return string ? nullptr : "a string";
            case 'h':
                return string || (number && IsInteger(values_.Number(value, 0)))
                           ? nullptr
                           : "a handle (an integer or a string)";
            case 'F':
                return value.kind == ValueKind::NumberArray ? nullptr : "an array of numbers";
            case 'I':
                return value.kind == ValueKind::NumberArray && AllIntegers(value)
                           ? nullptr
                           : "an array of integers";
            case 'S':
                return value.kind == ValueKind::StringArray ||
                               (value.kind == ValueKind::NumberArray && value.count == 0)
                           ? nullptr
                           : "an array of strings";
            case 'B':
                return string || (value.kind == ValueKind::NumberArray && value.count == 16)
                           ? nullptr
                           : "a basis name or an array of 16 numbers";
        }
        return "a known argument kind";  // a bad signature letter: a bug in the table
    }

    bool AllIntegers(const RibValue& value) const {
        for (std::size_t k = 0; k < value.count; ++k)
            if (!IsInteger(values_.arrays[value.begin][k])) return false;
        return true;
    }

    // The "token" value pairs after the positional arguments.
    bool MatchParams(std::size_t first, std::size_t positional, RequestArgs* args,
                     MatchError* error) {
        const std::vector<RibValue>& values = Values();
        if (first >= values.size()) return true;
        if (!rule_.takesParams) {
            if (values[first].kind == ValueKind::String)
                return FailAt(error, values[first],
                              std::string(rule_.name) + " takes no parameter list");
            return FailAtRequest(error, std::string(rule_.name) + " expects " +
                                            Plural(positional, "argument") + ", got " +
                                            std::to_string(values.size()));
        }
        for (std::size_t k = first; k < values.size(); k += 2) {
            const RibValue& token = values[k];
            if (token.kind != ValueKind::String)
                return FailAt(error, token,
                              "expected a parameter name (a string) in the parameter list of " +
                                  std::string(rule_.name) + ", got " + DescribeValue(token));
            if (k + 1 == values.size())
                return FailAt(error, token,
                              "parameter \"" + values_.strings[token.begin] + "\" has no value");
        }
        BuildParams(first, args);
        return true;
    }

    // Only once the request is known to be good: numeric arrays move into their Params.
    void BuildParams(std::size_t first, RequestArgs* args) {
        const std::vector<RibValue>& values = Values();
        for (std::size_t k = first; k < values.size(); k += 2) {
            const RibValue& token = values[k];
            const RibValue& value = values[k + 1];
            Param param;
            param.token = values_.strings[token.begin];
            param.loc = FileLoc{loc_.file, token.line, token.column};
            if (value.kind == ValueKind::Number) {
                param.numbers.assign(1, values_.numbers[value.begin]);
            } else if (value.kind == ValueKind::NumberArray) {
                param.numbers = std::move(values_.arrays[value.begin]);
            } else {
                const auto begin = values_.strings.begin() + value.begin;
                param.strings.assign(begin, begin + value.count);
                param.isString = true;
            }
            args->params_.push_back(std::move(param));
        }
    }

    const RequestRule& rule_;
    RequestValues& values_;
    int ncomps_;
    const FileLoc& loc_;
};

bool MatchRequest(const RequestRule& rule, RequestValues& values, int ncomps, const FileLoc& loc,
                  RequestArgs* args, MatchError* error) {
    return RequestMatcher(rule, values, ncomps, loc).Match(args, error);
}

double RequestArgs::Number(int k) const {
    const Slot& slot = slots_[k];
    return values_->Number(*slot.value, slot.element);
}

float RequestArgs::F(int k) const { return ToFloat(Number(k)); }

int RequestArgs::I(int k) const { return static_cast<int>(Number(k)); }

const std::string& RequestArgs::S(int k) const { return values_->strings[slots_[k].value->begin]; }

RtHandle RequestArgs::H(int k) const {
    if (!slots_[k].value->IsNumeric()) return RtHandle{S(k), true};
    return RtHandle{std::to_string(I(k)), false};
}

RtBasis RequestArgs::B(int k) const {
    const RibValue& value = *slots_[k].value;
    RtBasis basis;
    if (!value.IsNumeric()) {
        basis.name = S(k);
        return basis;
    }
    for (std::size_t j = 0; j < 16; ++j) basis.matrix[j] = ToFloat(values_->arrays[value.begin][j]);
    return basis;
}

std::vector<float> RequestArgs::FA(int k) const {
    const RibValue& value = *slots_[k].value;
    std::vector<float> result(value.count);
    for (std::size_t j = 0; j < value.count; ++j)
        result[j] = ToFloat(values_->arrays[value.begin][j]);
    return result;
}

std::vector<int> RequestArgs::IA(int k) const {
    const RibValue& value = *slots_[k].value;
    std::vector<int> result(value.count);
    for (std::size_t j = 0; j < value.count; ++j)
        result[j] = static_cast<int>(values_->arrays[value.begin][j]);
    return result;
}

std::vector<std::string> RequestArgs::SA(int k) const {
    const RibValue& value = *slots_[k].value;
    if (value.IsNumeric()) return {};  // an empty array
    const auto begin = values_->strings.begin() + value.begin;
    return std::vector<std::string>(begin, begin + value.count);
}

std::vector<float> RequestArgs::AllFloats() const {
    std::vector<float> result(slots_.size());
    for (std::size_t k = 0; k < slots_.size(); ++k) result[k] = F(static_cast<int>(k));
    return result;
}

RtMatrix RequestArgs::Matrix() const {
    RtMatrix m{};
    for (int k = 0; k < 16; ++k) m[k] = F(k);
    return m;
}

}  // namespace gonio
