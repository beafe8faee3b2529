#include "spectral/image_basis_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <sstream>

#include "spectral/number_format.h"
#include "spectral/spectral_error.h"

namespace gonio::spectral {

namespace {

constexpr const char* kBasisWavelengthsAttribute = "spectralBasisWavelengths";

std::string VectorAttribute(int index) {
    char name[48];
    std::snprintf(name, sizeof name, "spectralBasisVector.%02d", index);
    return name;
}

std::string NumberList(const double* values, size_t count) {
    std::string text;
    for (size_t i = 0; i < count; ++i) text += (i ? " " : "") + ShortestDecimal(values[i]);
    return text;
}

const std::string* FindAttribute(const HeaderAttributes& attributes, const std::string& name) {
    const auto found = std::find_if(attributes.begin(), attributes.end(),
                                    [&](const auto& a) { return a.first == name; });
    return found == attributes.end() ? nullptr : &found->second;
}

std::vector<double> ParseNumberList(const HeaderAttributes& attributes, const std::string& name) {
    const std::string* text = FindAttribute(attributes, name);
    if (!text) throw SpectralError("the header has no attribute \"" + name + "\"");
    std::istringstream in(*text);
    std::vector<double> values;
    std::string word;
    while (in >> word) {
        char* end = nullptr;
        const double value = std::strtod(word.c_str(), &end);
        if (end != word.c_str() + word.size() || !std::isfinite(value))
            throw SpectralError("the header attribute \"" + name + "\" holds \"" + word +
                                "\", not a finite number");
        values.push_back(value);
    }
    return values;
}

}  // namespace

std::string BasisChannelName(int index) {
    char name[32];
    std::snprintf(name, sizeof name, "basis.%02d", index);
    return name;
}

bool ParseBasisChannelName(const std::string& name, int* index) {
    static const std::regex kBasis(R"(basis\.([0-9]{2,3}))");
    std::smatch match;
    if (!std::regex_match(name, match, kBasis)) return false;
    *index = std::stoi(match[1].str());
    return true;
}

HeaderAttributes BasisHeaderAttributes(const std::vector<double>& wavelengths,
                                       const Eigen::MatrixXd& basis, double lostEnergyFraction) {
    HeaderAttributes attributes = {
        {kBasisWavelengthsAttribute, NumberList(wavelengths.data(), wavelengths.size())}};
    for (int i = 0; i < basis.cols(); ++i) {
        const Eigen::VectorXd column = basis.col(i);
        attributes.emplace_back(VectorAttribute(i), NumberList(column.data(), column.size()));
    }
    attributes.emplace_back("spectralBasisLostEnergy", ShortestDecimal(lostEnergyFraction));
    return attributes;
}

StoredBasis ReadBasisHeader(const HeaderAttributes& attributes, int k) {
    StoredBasis basis;
    basis.wavelengths = ParseNumberList(attributes, kBasisWavelengthsAttribute);
    const size_t n = basis.wavelengths.size();
    if (n < 3)
        throw SpectralError(std::string("the header attribute \"") + kBasisWavelengthsAttribute +
                            "\" has " + std::to_string(n) + " wavelengths; a spectrum needs 3");
    for (size_t i = 1; i < n; ++i)
        if (!(basis.wavelengths[i] > basis.wavelengths[i - 1]))
            throw SpectralError(std::string("the wavelengths of \"") + kBasisWavelengthsAttribute +
                                "\" do not increase");
    basis.vectors.resize(Eigen::Index(n), k);
    for (int i = 0; i < k; ++i) {
        const std::vector<double> values = ParseNumberList(attributes, VectorAttribute(i));
        if (values.size() != n)
            throw SpectralError("the header attribute \"" + VectorAttribute(i) + "\" has " +
                                std::to_string(values.size()) + " numbers for " +
                                std::to_string(n) + " wavelengths");
        basis.vectors.col(i) = Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(n));
    }
    return basis;
}

}  // namespace gonio::spectral
