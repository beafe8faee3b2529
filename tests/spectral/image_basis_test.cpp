// The basis of an image's own pixel spectra (spectral/image_basis.h) and its header layout
// (spectral/image_basis_layout.h): spectra that lie in a k-dimensional space are reproduced
// exactly by k vectors, the lost energy is what projection loses, and the header reads back
// what was written or says what is wrong with it.

#include "spectral/image_basis.h"

#include <gtest/gtest.h>

#include <random>

#include "spectral/image_basis_layout.h"
#include "spectral/spectral_error.h"

namespace gonio::spectral {
namespace {

constexpr int kSamples = 81;

// `pixels` spectra of kSamples samples, each a random non-negative mixture of `rank` random
// non-negative spectra: they span exactly a rank-dimensional space (random samples keep the
// generators far from dependent, so rank − 1 vectors are clearly not enough).
std::vector<float> LowRankSpectra(int rank, size_t pixels, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(0, 1);
    Eigen::MatrixXd generators(kSamples, rank);
    for (int j = 0; j < rank; ++j)
        for (int i = 0; i < kSamples; ++i) generators(i, j) = uniform(random);
    std::vector<float> spectra(pixels * kSamples);
    for (size_t p = 0; p < pixels; ++p) {
        Eigen::VectorXd mixture(rank);
        for (int j = 0; j < rank; ++j) mixture[j] = uniform(random);
        const Eigen::VectorXd spectrum = generators * mixture;
        for (int i = 0; i < kSamples; ++i) spectra[p * kSamples + i] = float(spectrum[i]);
    }
    return spectra;
}

// max over pixels of ‖r − B c‖ / ‖r‖, c the pixel's projected coefficients.
double WorstRelativeResidual(const std::vector<float>& spectra, const Eigen::MatrixXd& basis) {
    const size_t pixels = spectra.size() / kSamples;
    const std::vector<float> c = ProjectSpectra(spectra.data(), pixels, basis);
    const int k = int(basis.cols());
    double worst = 0;
    for (size_t p = 0; p < pixels; ++p) {
        const Eigen::VectorXd r =
            Eigen::Map<const Eigen::VectorXf>(&spectra[p * kSamples], kSamples).cast<double>();
        const Eigen::VectorXd coded =
            basis * Eigen::Map<const Eigen::VectorXf>(&c[p * k], k).cast<double>();
        worst = std::max(worst, (r - coded).norm() / r.norm());
    }
    return worst;
}

TEST(ImageBasis, SpectraOfRankKAreExactInKVectors) {
    for (int rank : {1, 3, 6, 12}) {
        const std::vector<float> spectra = LowRankSpectra(rank, 3000, 7 + rank);
        const ImageSpectraBasis principal = PrincipalSpectra(spectra.data(), 3000, kSamples);
        const Eigen::MatrixXd basis = principal.Basis(rank);
        // float precision: the spectra were rounded to float, the coefficients are floats
        EXPECT_LE(WorstRelativeResidual(spectra, basis), 1e-6) << rank;
        EXPECT_LE(principal.LostEnergyFraction(rank), 1e-12) << rank;
        if (rank > 1) {  // one vector fewer cannot be exact: the check above can fail
            EXPECT_GT(principal.LostEnergyFraction(rank - 1), 1e-4) << rank;
            EXPECT_GT(WorstRelativeResidual(spectra, principal.Basis(rank - 1)), 1e-5) << rank;
        }
    }
}

TEST(ImageBasis, IsOrthonormalSignedAndOrderedByEnergy) {
    const std::vector<float> spectra = LowRankSpectra(8, 2000, 3);
    const ImageSpectraBasis principal = PrincipalSpectra(spectra.data(), 2000, kSamples);
    const Eigen::MatrixXd& d = principal.directions;
    EXPECT_LE((d.transpose() * d - Eigen::MatrixXd::Identity(kSamples, kSamples)).norm(), 1e-12);
    for (int i = 0; i < kSamples; ++i) {
        EXPECT_GE(d.col(i).sum(), 0) << i;
        EXPECT_GE(principal.energies[i], 0) << i;
        if (i > 0) EXPECT_LE(principal.energies[i], principal.energies[i - 1]) << i;
    }
    double total = 0;
    for (float v : spectra) total += double(v) * v;
    EXPECT_NEAR(principal.energies.sum() / total, 1, 1e-12);
}

TEST(ImageBasis, LostEnergyIsWhatProjectionLoses) {
    const std::vector<float> spectra = LowRankSpectra(10, 1500, 11);
    const ImageSpectraBasis principal = PrincipalSpectra(spectra.data(), 1500, kSamples);
    for (int k : {2, 4, 6}) {
        const Eigen::MatrixXd basis = principal.Basis(k);
        double lost = 0, total = 0;
        for (size_t p = 0; p < 1500; ++p) {
            const Eigen::VectorXd r =
                Eigen::Map<const Eigen::VectorXf>(&spectra[p * kSamples], kSamples).cast<double>();
            lost += (r - basis * (basis.transpose() * r)).squaredNorm();
            total += r.squaredNorm();
        }
        EXPECT_NEAR(principal.LostEnergyFraction(k), lost / total, 1e-9 * lost / total + 1e-15)
            << k;
    }
}

TEST(ImageBasis, RefusesBasesOfNoVectorsOrTooMany) {
    const std::vector<float> black(10 * kSamples, 0.0f);
    const ImageSpectraBasis principal = PrincipalSpectra(black.data(), 10, kSamples);
    EXPECT_EQ(principal.LostEnergyFraction(1), 0);
    EXPECT_THROW(principal.Basis(0), SpectralError);
    EXPECT_THROW(principal.Basis(kSamples + 1), SpectralError);
}

TEST(ImageBasisLayout, TheHeaderReadsBackExactly) {
    const std::vector<float> spectra = LowRankSpectra(4, 500, 5);
    const Eigen::MatrixXd basis = PrincipalSpectra(spectra.data(), 500, kSamples).Basis(4);
    std::vector<double> nm;
    for (int i = 0; i < kSamples; ++i) nm.push_back(380 + 5 * i);
    const StoredBasis stored = ReadBasisHeader(BasisHeaderAttributes(nm, basis, 1e-3), 4);
    EXPECT_EQ(stored.wavelengths, nm);
    EXPECT_EQ(stored.vectors, basis);
    int index = -1;
    EXPECT_EQ(BasisChannelName(7), "basis.07");
    EXPECT_TRUE(ParseBasisChannelName("basis.12", &index));
    EXPECT_EQ(index, 12);
    EXPECT_FALSE(ParseBasisChannelName("basis.x", &index));
    EXPECT_FALSE(ParseBasisChannelName("S0.550,00nm", &index));
}

void ExpectBadHeader(const HeaderAttributes& attributes, int k, const std::string& why) {
    try {
        ReadBasisHeader(attributes, k);
        ADD_FAILURE() << "accepted; expected: " << why;
    } catch (const SpectralError& e) {
        EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
}

TEST(ImageBasisLayout, ABadHeaderSaysWhatIsWrong) {
    const std::string nm = "400 500 600";
    ExpectBadHeader({}, 1, "no attribute \"spectralBasisWavelengths\"");
    ExpectBadHeader({{"spectralBasisWavelengths", "400 500"}}, 1, "has 2 wavelengths");
    ExpectBadHeader({{"spectralBasisWavelengths", "400 600 500"}}, 1, "do not increase");
    ExpectBadHeader({{"spectralBasisWavelengths", nm}}, 1, "\"spectralBasisVector.00\"");
    ExpectBadHeader({{"spectralBasisWavelengths", nm}, {"spectralBasisVector.00", "1 2"}}, 1,
                    "has 2 numbers for 3 wavelengths");
    ExpectBadHeader({{"spectralBasisWavelengths", nm}, {"spectralBasisVector.00", "1 x 2"}}, 1,
                    "\"x\", not a finite number");
    ExpectBadHeader({{"spectralBasisWavelengths", nm}, {"spectralBasisVector.00", "1 nan 2"}}, 1,
                    "not a finite number");
    ExpectBadHeader({{"spectralBasisWavelengths", nm}, {"spectralBasisVector.00", "1 1 1"}}, 2,
                    "\"spectralBasisVector.01\"");
}

}  // namespace
}  // namespace gonio::spectral
