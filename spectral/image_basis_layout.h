#pragma once
// How a spectral image in a basis is laid out in an OpenEXR file (docs/spectral.md, "Reflectance
// images in a basis"): beside the RGB preview, channel "basis.NN" holds each pixel's coefficient
// of basis vector NN, and the header's string attributes hold the wavelengths and the vectors as
// decimal numbers that read back as the same doubles:
//
//   spectralBasisWavelengths   "380 385 … 780"     the n wavelengths (nm), increasing
//   spectralBasisVector.NN     "v_1 v_2 … v_n"     basis vector NN at those wavelengths
//   spectralBasisLostEnergy    "1.2e-05"           the fraction of the pixels' energy it misses
//
// Strings, not OpenEXR float vectors, because they pass unchanged through every reader gonio
// uses (the OpenImageIO plugin returns a file's string metadata). The spectrum of a pixel is
// Σ_NN coefficient_NN · vector_NN.

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

namespace gonio::spectral {

using HeaderAttributes = std::vector<std::pair<std::string, std::string>>;

// "basis.07" for index 7.
std::string BasisChannelName(int index);
// The index of a channel "basis.NN", or false for any other name.
bool ParseBasisChannelName(const std::string& name, int* index);

// The header attributes of an image whose coefficients are in `basis` (n × k, one column per
// vector, at `wavelengths`).
HeaderAttributes BasisHeaderAttributes(const std::vector<double>& wavelengths,
                                       const Eigen::MatrixXd& basis, double lostEnergyFraction);

struct StoredBasis {
    std::vector<double> wavelengths;  // n, increasing
    Eigen::MatrixXd vectors;          // n × k
};

// The basis of an image with k coefficient channels, from its header. Throws SpectralError
// saying which attribute is missing or malformed: no wavelengths, wavelengths not increasing, a
// vector missing or of another length, a number that does not parse or is not finite.
StoredBasis ReadBasisHeader(const HeaderAttributes& attributes, int k);

}  // namespace gonio::spectral
