#pragma once
// Reading the fields of a request's JSON body, each a ViewerError naming the field when it is
// missing or of the wrong kind, so that a bad request is a 400 with a message, never a crash.

#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gonio::viewer {

// Throws ViewerError when `body` is not JSON or not an object.
nlohmann::json ParseJsonObject(const std::string& body);

double Number(const nlohmann::json& object, const char* field);
double OptionalNumber(const nlohmann::json& object, const char* field, double otherwise);
std::string String(const nlohmann::json& object, const char* field);
std::string OptionalString(const nlohmann::json& object, const char* field,
                           const std::string& otherwise);
// Finite numbers, at least `minimumCount` of them.
std::vector<double> NumberArray(const nlohmann::json& object, const char* field,
                                size_t minimumCount);
// Exactly `count` finite, non-negative numbers (a light's spectrum, an RGB).
Eigen::VectorXd NonNegativeVector(const nlohmann::json& object, const char* field, size_t count);

}  // namespace gonio::viewer
