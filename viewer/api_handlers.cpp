#include "viewer/api_handlers.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>

#include "spectral/colorimetry.h"
#include "spectral/light_match.h"
#include "spectral/spectral_error.h"
#include "viewer/illuminants.h"
#include "viewer/image_export.h"
#include "viewer/json_fields.h"
#include "viewer/light_files.h"

namespace gonio::viewer {

namespace {

Reply JsonReply(const nlohmann::json& value) { return {value.dump(), "application/json", {}}; }

Reply BinaryReply(const std::vector<float>& values) {
    return {LittleEndianFloats(values), "application/octet-stream", {}};
}

std::vector<double> Values(const Eigen::VectorXd& v) { return {v.begin(), v.end()}; }

// "largest" (the page's patch: the largest components made equal), "euclidean" (the thesis's
// text) or "none" (the target as given).
Eigen::Vector3d MatchTarget(const nlohmann::json& request, const Eigen::VectorXd& light,
                            const Eigen::Matrix3Xd& toRgb, const Eigen::Vector3d& target) {
    const std::string brightness = OptionalString(request, "brightness", "largest");
    if (brightness == "none") return target;
    if (brightness != "largest" && brightness != "euclidean")
        throw ViewerError("unknown brightness \"" + brightness +
                          "\": expected largest, euclidean or none");
    return spectral::NormalisedTarget(
        light, toRgb, target,
        brightness == "largest" ? spectral::Brightness::Largest : spectral::Brightness::Euclidean);
}

// The vectors of an image's basis, k lists of n samples; null for an image of samples.
nlohmann::json BasisVectors(const Eigen::MatrixXd& basis) {
    if (basis.cols() == 0) return nullptr;
    nlohmann::json vectors = nlohmann::json::array();
    for (int k = 0; k < basis.cols(); ++k) {
        const Eigen::VectorXd column = basis.col(k);
        vectors.push_back(std::vector<double>(column.data(), column.data() + column.size()));
    }
    return vectors;
}

std::vector<std::vector<double>> Rows(const Eigen::Matrix3Xd& m) {
    std::vector<std::vector<double>> rows(3);
    for (int c = 0; c < 3; ++c)
        for (Eigen::Index i = 0; i < m.cols(); ++i) rows[c].push_back(m(c, i));
    return rows;
}

// CIELAB of linear sRGB relative to sRGB's white at luminance `whiteY` (CIE 15:2004 eq. 8.1).
spectral::Lab LabOfRgb(const float* rgb, double whiteY) {
    const spectral::Xyz xyz = spectral::LinearSrgbToXyz(spectral::Rgb(rgb[0], rgb[1], rgb[2]));
    return spectral::XyzToLab(xyz, spectral::SrgbWhite() * whiteY);
}

double BrightestLuminance(const std::vector<float>& rgb) {
    double brightest = 0;
    for (size_t p = 0; p + 2 < rgb.size(); p += 3)
        brightest =
            std::max(brightest,
                     spectral::LinearSrgbToXyz(spectral::Rgb(rgb[p], rgb[p + 1], rgb[p + 2])).y());
    return brightest;
}

}  // namespace

std::string LittleEndianFloats(const std::vector<float>& values) {
    std::string bytes(values.size() * 4, '\0');
    for (size_t i = 0; i < values.size(); ++i) {
        uint32_t bits = 0;
        std::memcpy(&bits, &values[i], 4);
        for (int b = 0; b < 4; ++b) bytes[4 * i + b] = char((bits >> (8 * b)) & 0xff);
    }
    return bytes;
}

ApiHandlers::ApiHandlers(const ReflectanceImage& image)
    : image_(image),
      box_(ConversionMatrix(RgbConversion::Box, image.wavelengths)),
      cie_(ConversionMatrix(RgbConversion::Cie, image.wavelengths)) {}

Eigen::VectorXd ApiHandlers::Light(const nlohmann::json& request, const char* field) const {
    return NonNegativeVector(request, field, image_.wavelengths.size());
}

const Eigen::Matrix3Xd& ApiHandlers::Matrix(const nlohmann::json& request) const {
    return ParseRgbConversion(OptionalString(request, "conversion", "cie")) == RgbConversion::Box
               ? box_
               : cie_;
}

std::vector<float> ApiHandlers::RelitImage(const nlohmann::json& request) const {
    return Relight(image_, Light(request, "light"), Matrix(request));
}

Reply ApiHandlers::Metadata() const {
    return JsonReply({{"file", image_.path},
                      {"width", image_.width},
                      {"height", image_.height},
                      {"wavelengths", image_.wavelengths},
                      {"toRgb", {{"box", Rows(box_)}, {"cie", Rows(cie_)}}},
                      {"hasPreview", !image_.previewRgb.empty()},
                      {"basis", BasisVectors(image_.basis)}});
}

Reply ApiHandlers::Spectra() const { return BinaryReply(image_.spectra); }

Reply ApiHandlers::Coefficients() const {
    if (image_.coefficients.empty())
        throw ViewerError(image_.path + " holds samples, not coefficients in a basis");
    return BinaryReply(image_.coefficients);
}

Reply ApiHandlers::Illuminants() const { return JsonReply({{"names", IlluminantNames()}}); }

Reply ApiHandlers::Illuminant(const std::string& name) const {
    return JsonReply(IlluminantPreset(name, image_.wavelengths, cie_));
}

Reply ApiHandlers::Relit(const nlohmann::json& request) const {
    return BinaryReply(RelitImage(request));
}

Reply ApiHandlers::Export(const nlohmann::json& request) const {
    const ExportFormat format = ParseExportFormat(OptionalString(request, "format", "png"));
    const std::string name = format == ExportFormat::Png ? "relit.png" : "relit.exr";
    return {EncodeImage(RelitImage(request), image_.width, image_.height, format),
            format == ExportFormat::Png ? "image/png" : "image/x-exr",
            {{"Content-Disposition", "attachment; filename=\"" + name + "\""}}};
}

// Thesis fig. 6.3 as a map: the CIEDE2000 between the image under two lights, both in CIELAB
// relative to sRGB's white at the brightest luminance of the image under the first light.
Reply ApiHandlers::Difference(const nlohmann::json& request) const {
    const std::vector<float> a = Relight(image_, Light(request, "lightA"), cie_);
    const std::vector<float> b = Relight(image_, Light(request, "lightB"), cie_);
    const double whiteY = BrightestLuminance(a);
    if (!(whiteY > 0)) throw ViewerError("the image is black under lightA: no white to compare to");
    std::vector<float> map(a.size() / 3);
    for (size_t p = 0; p < map.size(); ++p)
        map[p] =
            float(spectral::Ciede2000(LabOfRgb(&a[3 * p], whiteY), LabOfRgb(&b[3 * p], whiteY)));
    const double mean = std::accumulate(map.begin(), map.end(), 0.0) / double(map.size());
    const double max = *std::max_element(map.begin(), map.end());
    Reply reply = BinaryReply(map);
    reply.headers = {{"X-Mean-DeltaE", std::to_string(mean)},
                     {"X-Max-DeltaE", std::to_string(max)}};
    return reply;
}

Reply ApiHandlers::LoadLight(const std::string& text, const std::string& name) const {
    return JsonReply(LoadLightFile(text, name, image_.wavelengths));
}

Reply ApiHandlers::SaveLight(const nlohmann::json& request) const {
    return {SaveLightFile(request), "text/plain; charset=utf-8", {}};
}

// Thesis §6.2.2's Match RGB: the light closest to the posted one (L2) whose RGB is the target
// at the light's brightness, non-negative; an unreachable target is reported, not forced.
Reply ApiHandlers::Match(const nlohmann::json& request) const {
    const Eigen::VectorXd light = Light(request, "light");
    const Eigen::Matrix3Xd& toRgb = Matrix(request);
    const Eigen::Vector3d target =
        MatchTarget(request, light, toRgb, NonNegativeVector(request, "target", 3));
    spectral::LightMatch match;
    try {
        match = spectral::MatchLightToRgb(light, toRgb, target);
    } catch (const spectral::SpectralError& e) {
        throw ViewerError(e.what());
    }
    return JsonReply({{"reachable", match.reachable},
                      {"spectrum", Values(match.spectrum)},
                      {"rgb", Values(toRgb * match.spectrum)},
                      {"target", Values(target)},
                      {"lambda", Values(match.lambda)},
                      {"newtonSteps", match.newtonSteps},
                      {"rgbResidual", match.rgbResidual},
                      {"complementarity", match.complementarity},
                      {"certificate", Values(match.certificate)},
                      {"relativeChange", match.relativeChange},
                      {"message", match.message}});
}

}  // namespace gonio::viewer
