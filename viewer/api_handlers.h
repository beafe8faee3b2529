#pragma once
// What each endpoint of api.h answers, apart from HTTP: each takes the request's parsed parts
// and returns the reply, or throws ViewerError for a bad request (api.cpp makes that a 400).

#include <Eigen/Dense>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "viewer/reflectance_image.h"
#include "viewer/relight.h"

namespace gonio::viewer {

struct Reply {
    std::string body;
    std::string contentType;
    std::map<std::string, std::string> headers;
};

class ApiHandlers {
  public:
    explicit ApiHandlers(const ReflectanceImage& image);

    Reply Metadata() const;
    Reply Spectra() const;
    // An image in a basis: its k coefficients per pixel (a 400 for an image of samples).
    Reply Coefficients() const;
    Reply Illuminants() const;
    Reply Illuminant(const std::string& name) const;
    Reply Relit(const nlohmann::json& request) const;
    Reply Export(const nlohmann::json& request) const;
    Reply Difference(const nlohmann::json& request) const;
    Reply LoadLight(const std::string& text, const std::string& name) const;
    Reply SaveLight(const nlohmann::json& request) const;
    Reply Match(const nlohmann::json& request) const;

  private:
    // The light `field` of a request: one non-negative number per wavelength.
    Eigen::VectorXd Light(const nlohmann::json& request, const char* field) const;
    const Eigen::Matrix3Xd& Matrix(const nlohmann::json& request) const;
    std::vector<float> RelitImage(const nlohmann::json& request) const;

    const ReflectanceImage& image_;
    Eigen::Matrix3Xd box_, cie_;
};

// The bytes of `values` as little-endian float32, whatever the host's byte order.
std::string LittleEndianFloats(const std::vector<float>& values);

}  // namespace gonio::viewer
