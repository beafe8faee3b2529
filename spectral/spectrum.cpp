#include "spectral/spectrum.h"

#include <algorithm>
#include <cmath>

#include "base/diagnostics.h"
#include "spectral/catmull_rom.h"
#include "spectral/spectral_error.h"

namespace gonio::spectral {

namespace {

constexpr double kSlack = 1e-9;  // nm: knots and grid ends closer than this are the same

}  // namespace

WavelengthGrid WavelengthGrid::Make(double start, double end, double step) {
    if (!(step > 0))
        throw SpectralError("wavelength step must be positive, got " + FormatNumber(step));
    if (!(end >= start))
        throw SpectralError("wavelength range " + FormatNumber(start) + "-" + FormatNumber(end) +
                            " nm is empty");
    const double steps = (end - start) / step;
    if (std::abs(steps - std::round(steps)) > 1e-6)
        throw SpectralError("wavelength range " + FormatNumber(start) + "-" + FormatNumber(end) +
                            " nm is not a whole number of " + FormatNumber(step) + " nm steps");
    return WavelengthGrid{start, end, step};
}

int WavelengthGrid::Count() const { return int(std::lround((end - start) / step)) + 1; }

std::vector<double> WavelengthGrid::Wavelengths() const {
    std::vector<double> result(Count());
    for (int i = 0; i < Count(); ++i) result[i] = At(i);
    return result;
}

Spectrum::Spectrum(std::vector<double> wavelengths, std::vector<double> values,
                   Interpolation interpolation)
    : wavelengths_(std::move(wavelengths)),
      values_(std::move(values)),
      interpolation_(interpolation) {
    if (wavelengths_.size() != values_.size())
        throw SpectralError("a spectrum needs as many values as wavelengths (" +
                            std::to_string(values_.size()) + " values, " +
                            std::to_string(wavelengths_.size()) + " wavelengths)");
    if (wavelengths_.size() < 2)
        throw SpectralError("a spectrum needs at least 2 samples, got " +
                            std::to_string(values_.size()));
    for (size_t i = 1; i < wavelengths_.size(); ++i)
        if (!(wavelengths_[i] > wavelengths_[i - 1] + kSlack))
            throw SpectralError("spectrum wavelengths must increase (" +
                                FormatNumber(wavelengths_[i - 1]) + " nm then " +
                                FormatNumber(wavelengths_[i]) + " nm)");
    phantomBefore_ = values_.front();
    phantomAfter_ = values_.back();
}

Spectrum Spectrum::Regular(double start, double step, std::vector<double> values,
                           Interpolation interpolation) {
    std::vector<double> wavelengths(values.size());
    for (size_t i = 0; i < values.size(); ++i) wavelengths[i] = start + double(i) * step;
    return Spectrum(std::move(wavelengths), std::move(values), interpolation);
}

Spectrum Spectrum::OnGrid(const WavelengthGrid& grid, std::vector<double> values) {
    if (int(values.size()) != grid.Count())
        throw SpectralError("a spectrum on a grid of " + std::to_string(grid.Count()) +
                            " samples got " + std::to_string(values.size()) + " values");
    return Regular(grid.start, grid.step, std::move(values));
}

void Spectrum::SetPhantoms(double before, double after) {
    phantomBefore_ = before;
    phantomAfter_ = after;
}

bool Spectrum::IsRegular(double* step) const {
    const double spacing = wavelengths_[1] - wavelengths_[0];
    for (size_t i = 2; i < wavelengths_.size(); ++i)
        if (std::abs(wavelengths_[i] - wavelengths_[i - 1] - spacing) > 1e-9 * (1 + spacing))
            return false;
    if (step) *step = spacing;
    return true;
}

bool Spectrum::Covers(double lo, double hi) const {
    return !Empty() && lo >= MinWavelength() - kSlack && hi <= MaxWavelength() + kSlack;
}

double Spectrum::Evaluate(double nm, Resampling how) const {
    if (!Covers(nm, nm))
        throw SpectralError("wavelength " + FormatNumber(nm) + " nm is outside the spectrum's " +
                            FormatNumber(MinWavelength()) + "-" + FormatNumber(MaxWavelength()) +
                            " nm");
    nm = std::clamp(nm, MinWavelength(), MaxWavelength());
    if (interpolation_ == Interpolation::CatmullRom && how == Resampling::Source) {
        // Thesis §6.2.2: the spline may dip below its lowest control point; an SPD may not.
        return std::max(
            0.0, CatmullRomHermite(wavelengths_, values_, phantomBefore_, phantomAfter_, nm));
    }
    size_t i =
        std::upper_bound(wavelengths_.begin(), wavelengths_.end(), nm) - wavelengths_.begin();
    i = std::clamp<size_t>(i, 1, wavelengths_.size() - 1) - 1;
    const double u = (nm - wavelengths_[i]) / (wavelengths_[i + 1] - wavelengths_[i]);
    return values_[i] + u * (values_[i + 1] - values_[i]);
}

std::vector<double> Spectrum::Sample(const WavelengthGrid& grid, Resampling how) const {
    if (!Covers(grid.start, grid.end))
        throw SpectralError("the spectrum covers " + FormatNumber(MinWavelength()) + "-" +
                            FormatNumber(MaxWavelength()) + " nm, not the working range " +
                            FormatNumber(grid.start) + "-" + FormatNumber(grid.end) + " nm");
    std::vector<double> result(grid.Count());
    for (int i = 0; i < grid.Count(); ++i) result[i] = Evaluate(grid.At(i), how);
    return result;
}

Spectrum Spectrum::Resampled(const WavelengthGrid& grid, Resampling how) const {
    return OnGrid(grid, Sample(grid, how));
}

Spectrum Spectrum::Scaled(double factor) const {
    Spectrum result = *this;
    for (double& v : result.values_) v *= factor;
    result.phantomBefore_ *= factor;
    result.phantomAfter_ *= factor;
    return result;
}

std::string Spectrum::DescribeSampling() const {
    std::string text =
        FormatNumber(MinWavelength()) + "-" + FormatNumber(MaxWavelength()) + " nm, ";
    double step = 0;
    if (interpolation_ == Interpolation::CatmullRom)
        return text + std::to_string(Size()) + " Catmull-Rom knots";
    if (IsRegular(&step))
        return text + std::to_string(Size()) + " samples at " + FormatNumber(step) + " nm";
    return text + std::to_string(Size()) + " knots (uneven), piecewise linear";
}

double PlanckRadiance(double nm, double kelvin) {
    // Planck's law, L(λ, T) = 2hc² / λ⁵ / (exp(hc / (λ k T)) − 1) (CIE 15:2004 eq. E.1 with
    // c1 = 2hc², c2 = hc/k); CODATA 2018 exact constants.
    constexpr double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
    const double lambda = nm * 1e-9;
    const double c1 = 2 * h * c * c;
    const double c2 = h * c / k;
    return c1 / std::pow(lambda, 5) / std::expm1(c2 / (lambda * kelvin)) * 1e-9;
}

Spectrum Blackbody(double kelvin, const WavelengthGrid& grid) {
    if (!(kelvin > 0))
        throw SpectralError("blackbody temperature must be positive, got " + FormatNumber(kelvin) +
                            " K");
    const double at560 = PlanckRadiance(560, kelvin);
    std::vector<double> values(grid.Count());
    for (int i = 0; i < grid.Count(); ++i)
        values[i] = 100 * PlanckRadiance(grid.At(i), kelvin) / at560;
    return Spectrum::OnGrid(grid, std::move(values));
}

}  // namespace gonio::spectral
