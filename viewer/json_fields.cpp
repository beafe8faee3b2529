#include "viewer/json_fields.h"

#include <cmath>

#include "viewer/reflectance_image.h"

namespace gonio::viewer {

namespace {

const nlohmann::json& Field(const nlohmann::json& object, const char* field) {
    const auto found = object.find(field);
    if (found == object.end()) throw ViewerError(std::string("missing field \"") + field + "\"");
    return *found;
}

double FiniteNumber(const nlohmann::json& value, const std::string& what) {
    if (!value.is_number()) throw ViewerError(what + " must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) throw ViewerError(what + " must be finite");
    return number;
}

}  // namespace

nlohmann::json ParseJsonObject(const std::string& body) {
    nlohmann::json parsed = nlohmann::json::parse(body, nullptr, false);
    if (parsed.is_discarded()) throw ViewerError("the request body is not JSON");
    if (!parsed.is_object()) throw ViewerError("the request body must be a JSON object");
    return parsed;
}

double Number(const nlohmann::json& object, const char* field) {
    return FiniteNumber(Field(object, field), std::string("\"") + field + "\"");
}

double OptionalNumber(const nlohmann::json& object, const char* field, double otherwise) {
    return object.contains(field) ? Number(object, field) : otherwise;
}

std::string String(const nlohmann::json& object, const char* field) {
    const nlohmann::json& value = Field(object, field);
    if (!value.is_string()) throw ViewerError(std::string("\"") + field + "\" must be a string");
    return value.get<std::string>();
}

std::string OptionalString(const nlohmann::json& object, const char* field,
                           const std::string& otherwise) {
    return object.contains(field) ? String(object, field) : otherwise;
}

std::vector<double> NumberArray(const nlohmann::json& object, const char* field,
                                size_t minimumCount) {
    const nlohmann::json& value = Field(object, field);
    const std::string name = std::string("\"") + field + "\"";
    if (!value.is_array()) throw ViewerError(name + " must be an array of numbers");
    if (value.size() < minimumCount)
        throw ViewerError(name + " needs at least " + std::to_string(minimumCount) + " numbers");
    std::vector<double> numbers;
    for (size_t i = 0; i < value.size(); ++i)
        numbers.push_back(FiniteNumber(value[i], name + "[" + std::to_string(i) + "]"));
    return numbers;
}

Eigen::VectorXd NonNegativeVector(const nlohmann::json& object, const char* field, size_t count) {
    const std::vector<double> numbers = NumberArray(object, field, 0);
    if (numbers.size() != count)
        throw ViewerError(std::string("\"") + field + "\" has " + std::to_string(numbers.size()) +
                          " numbers; " + std::to_string(count) + " are needed");
    for (size_t i = 0; i < count; ++i)
        if (numbers[i] < 0)
            throw ViewerError(std::string("\"") + field + "\"[" + std::to_string(i) +
                              "] is negative: spectra and RGB here are not");
    return Eigen::Map<const Eigen::VectorXd>(numbers.data(), Eigen::Index(count));
}

}  // namespace gonio::viewer
