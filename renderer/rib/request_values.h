#pragma once
// The values of one request as the grammar delivers them, before the request table gives them a
// meaning: scalars and bracketed arrays of numbers or strings, in source order. Numbers and
// strings live in pools that are reused from request to request, so a large mesh costs no
// allocation per number.

#include <cstddef>
#include <string>
#include <vector>

namespace gonio {

enum class ValueKind { Number, String, NumberArray, StringArray };

struct RibValue {
    ValueKind kind = ValueKind::Number;
    int line = 0;
    int column = 0;
    std::size_t begin = 0;  // first element in RequestValues::numbers or ::strings
    std::size_t count = 1;  // elements (1 for a scalar)

    bool IsNumeric() const { return kind == ValueKind::Number || kind == ValueKind::NumberArray; }
    bool IsArray() const {
        return kind == ValueKind::NumberArray || kind == ValueKind::StringArray;
    }
};

// Describes a value for error messages: "a number", "an array of 3 strings", ...
std::string DescribeValue(const RibValue& value);

struct RequestValues {
    std::vector<double> numbers;
    std::vector<std::string> strings;  // slots [0, stringCount) are in use; the rest are reused
    std::size_t stringCount = 0;
    std::vector<RibValue> values;

    // Stores a string in the next pool slot and returns its index.
    std::string& NewString(std::size_t* index) {
        if (stringCount == strings.size()) strings.emplace_back();
        *index = stringCount++;
        return strings[*index];
    }
    void Clear() {
        numbers.clear();
        stringCount = 0;
        values.clear();
    }
};

}  // namespace gonio
