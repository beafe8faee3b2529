#pragma once
// The values of one request as the grammar delivers them, before the request table gives them a
// meaning: scalars and bracketed arrays of numbers or strings, in source order. They live in
// pools that are reused from request to request, so that reading costs no allocation per token;
// a numeric array has a vector of its own that moves into its Param without a copy, which
// matters for meshes of millions of points.

#include <cstddef>
#include <string>
#include <vector>

namespace gonio {

enum class ValueKind { Number, String, NumberArray, StringArray };

struct RibValue {
    ValueKind kind = ValueKind::Number;
    int line = 0;
    int column = 0;
    // Number: index in RequestValues::numbers; NumberArray: index in ::arrays; String and
    // StringArray: first index in ::strings.
    std::size_t begin = 0;
    std::size_t count = 1;  // elements (1 for a scalar)

    bool IsNumeric() const { return kind == ValueKind::Number || kind == ValueKind::NumberArray; }
    bool IsArray() const {
        return kind == ValueKind::NumberArray || kind == ValueKind::StringArray;
    }
};

// Describes a value for error messages: "a number", "an array of 3 strings", ...
std::string DescribeValue(const RibValue& value);

struct RequestValues {
    std::vector<double> numbers;              // scalar numbers
    std::vector<std::vector<double>> arrays;  // slots [0, arrayCount) are in use
    std::size_t arrayCount = 0;
    std::vector<std::string> strings;  // slots [0, stringCount) are in use; the rest are reused
    std::size_t stringCount = 0;
    std::vector<RibValue> values;

    // The `k`th number of a numeric value (k = 0 for a scalar).
    double Number(const RibValue& value, std::size_t k) const {
        return value.kind == ValueKind::Number ? numbers[value.begin] : arrays[value.begin][k];
    }

    std::vector<double>& NewArray(std::size_t* index) {
        if (arrayCount == arrays.size()) arrays.emplace_back();
        *index = arrayCount++;
        arrays[*index].clear();
        return arrays[*index];
    }

    // Stores a string in the next pool slot and returns its index.
    std::string& NewString(std::size_t* index) {
        if (stringCount == strings.size()) strings.emplace_back();
        *index = stringCount++;
        return strings[*index];
    }
    void Clear() {
        numbers.clear();
        arrayCount = 0;
        stringCount = 0;
        values.clear();
    }
};

}  // namespace gonio
