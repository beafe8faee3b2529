#pragma once
// A spectrum: values over wavelength in nm, on a regular grid or at arbitrary knots, with the
// interpolation its source defines (piecewise linear for tables, Catmull-Rom for the thesis's
// `curve` files). Everything colorimetric works on spectra resampled onto one working grid whose
// start, end and step are run-time values (`WavelengthGrid`).

#include <string>
#include <vector>

namespace gonio::spectral {

// Sample wavelengths start, start + step, ..., end (end - start a whole number of steps).
struct WavelengthGrid {
    double start = 380;
    double end = 780;
    double step = 5;

    // Checks the grid (step > 0, end >= start, a whole number of steps within 1e-6 of a step);
    // throws SpectralError otherwise.
    static WavelengthGrid Make(double start, double end, double step);
    int Count() const;
    double At(int i) const { return start + i * step; }
    std::vector<double> Wavelengths() const;
};

// CIE 15:2004 §7.1: 380-780 nm at 5 nm is the abridged interval for colorimetry; it is our
// reference (81 samples).
inline WavelengthGrid ReferenceGrid() { return WavelengthGrid{380, 780, 5}; }

enum class Interpolation { Linear, CatmullRom };
// How a resampling evaluates the source between its knots.
enum class Resampling { Source, Linear };

class Spectrum {
  public:
    Spectrum() = default;
    // Knots must be strictly increasing, at least 2 of them, values the same count; throws
    // SpectralError otherwise. A Catmull-Rom spectrum's phantom values default to its end values.
    Spectrum(std::vector<double> wavelengths, std::vector<double> values,
             Interpolation interpolation = Interpolation::Linear);
    static Spectrum Regular(double start, double step, std::vector<double> values,
                            Interpolation interpolation = Interpolation::Linear);
    static Spectrum OnGrid(const WavelengthGrid& grid, std::vector<double> values);

    // The thesis's phantom control points (Appendix D.2.3), used only by Catmull-Rom.
    void SetPhantoms(double before, double after);
    double PhantomBefore() const { return phantomBefore_; }
    double PhantomAfter() const { return phantomAfter_; }

    const std::vector<double>& Wavelengths() const { return wavelengths_; }
    const std::vector<double>& Values() const { return values_; }
    Interpolation GetInterpolation() const { return interpolation_; }
    size_t Size() const { return values_.size(); }
    bool Empty() const { return values_.empty(); }
    double MinWavelength() const { return wavelengths_.front(); }
    double MaxWavelength() const { return wavelengths_.back(); }
    // True when the knots are evenly spaced (within 1e-9 nm); `step` receives the spacing.
    bool IsRegular(double* step = nullptr) const;
    // True when [lo, hi] lies within the knots (1e-9 nm slack).
    bool Covers(double lo, double hi) const;

    // The value at `nm` by the source's interpolation (Catmull-Rom clamped at 0, thesis §6.2.2),
    // or piecewise linear. Throws SpectralError outside the knots.
    double Evaluate(double nm, Resampling how = Resampling::Source) const;
    // The values on `grid`; throws SpectralError (naming both ranges) if the spectrum does not
    // cover it: we never invent data beyond a table.
    std::vector<double> Sample(const WavelengthGrid& grid,
                               Resampling how = Resampling::Source) const;
    Spectrum Resampled(const WavelengthGrid& grid, Resampling how = Resampling::Source) const;
    Spectrum Scaled(double factor) const;

    // "380-780 nm, 81 samples at 5 nm" or "400-700 nm, 6 knots (Catmull-Rom)".
    std::string DescribeSampling() const;

  private:
    std::vector<double> wavelengths_;
    std::vector<double> values_;
    Interpolation interpolation_ = Interpolation::Linear;
    double phantomBefore_ = 0;
    double phantomAfter_ = 0;
};

// Planck's law: spectral radiance of a blackbody at `kelvin`, W·sr⁻¹·m⁻²·nm⁻¹, at `nm`.
double PlanckRadiance(double nm, double kelvin);
// A blackbody of temperature `kelvin` sampled on `grid` (default 300-830 nm at 1 nm, the span of
// the CIE tables), normalised to 100 at 560 nm as CIE 15:2004 does for illuminant A.
Spectrum Blackbody(double kelvin, const WavelengthGrid& grid = WavelengthGrid{300, 830, 1});

}  // namespace gonio::spectral
