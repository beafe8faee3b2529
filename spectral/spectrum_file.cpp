#include "spectral/spectrum_file.h"

#include <cmath>

#include "spectral/number_format.h"
#include "spectral/spectral_error.h"
#include "spectral/text_file.h"

namespace gonio::spectral {

namespace {

constexpr double kTSlack = 1e-6;  // curve parameters this close are the same point

struct Line {
    std::vector<std::string> words;
    int number;
};

// The non-comment, non-blank lines, with their line numbers.
std::vector<Line> ContentLines(const std::vector<std::string>& lines) {
    std::vector<Line> result;
    for (size_t i = 0; i < lines.size(); ++i) {
        std::vector<std::string> words = SplitBlanks(lines[i]);
        if (words.empty() || words[0][0] == '#') continue;
        result.push_back({std::move(words), int(i) + 1});
    }
    return result;
}

class Parser {
  public:
    Parser(const std::vector<std::string>& lines, std::string name)
        : name_(std::move(name)), lastLine_(int(lines.size())), lines_(ContentLines(lines)) {}

    Spectrum Parse() {
        if (lines_.empty())
            FailAt(name_, lastLine_, "no `cspec` or `curve` definition: the file is empty");
        const Line& header = lines_.front();
        if (header.words[0] == "cspec") return ParseSamples(header);
        if (header.words[0] == "curve") return ParseCurve(header);
        Fail(header, "unknown keyword \"" + header.words[0] + "\": expected `cspec` or `curve`");
    }

  private:
    [[noreturn]] void Fail(const Line& line, const std::string& message) const {
        FailAt(name_, line.number, message);
    }

    double Number(const Line& line, size_t index, const char* what) const {
        double value = 0;
        if (!ParseNumber(line.words[index], &value))
            Fail(line, std::string("expected a number for ") + what + ", got \"" +
                           line.words[index] + "\"");
        return value;
    }

    void NonNegative(const Line& line, double value) const {
        if (value < 0)
            Fail(line, "negative value " + line.words.back() +
                           ": a spectral power distribution cannot be negative");
    }

    Spectrum ParseSamples(const Line& header) const {
        if (header.words.size() != 4)
            Fail(header, "expected `cspec START END STEP`, got " +
                             std::to_string(header.words.size() - 1) + " numbers");
        const double start = Number(header, 1, "START");
        const double end = Number(header, 2, "END");
        const double step = Number(header, 3, "STEP");
        if (!(step > 0)) Fail(header, "cspec STEP must be positive, got " + header.words[3]);
        if (!(end > start)) Fail(header, "cspec END must exceed START");
        const double steps = (end - start) / step;
        if (std::abs(steps - std::round(steps)) > 1e-6)
            Fail(header, "cspec range " + header.words[1] + "-" + header.words[2] +
                             " nm is not a whole number of " + header.words[3] + " nm steps");
        const size_t count = size_t(std::llround(steps)) + 1;
        std::vector<double> values;
        for (size_t i = 1; i < lines_.size(); ++i) {
            const Line& line = lines_[i];
            if (values.size() == count)
                Fail(line, "more values than `cspec` declares (" + std::to_string(count) + " for " +
                               header.words[1] + "-" + header.words[2] + " nm)");
            if (line.words.size() != 1)
                Fail(line, "expected one value per line, got " + std::to_string(line.words.size()));
            const double value = Number(line, 0, "a sample");
            NonNegative(line, value);
            values.push_back(value);
        }
        if (values.size() < count)
            FailAt(name_, lastLine_,
                   "truncated: `cspec` at line " + std::to_string(header.number) + " declares " +
                       std::to_string(count) + " values, the file has " +
                       std::to_string(values.size()));
        return Spectrum::Regular(start, step, std::move(values));
    }

    Spectrum ParseCurve(const Line& header) const {
        if (header.words.size() != 4)
            Fail(header, "expected `curve N START END`, got " +
                             std::to_string(header.words.size() - 1) + " numbers");
        const double n = Number(header, 1, "N");
        const double start = Number(header, 2, "START");
        const double end = Number(header, 3, "END");
        if (n != std::floor(n) || n < 4)
            Fail(header,
                 "curve N must be a whole number of at least 4 (two knots and the two "
                 "phantom points), got " +
                     header.words[1]);
        if (!(end > start)) Fail(header, "curve END must exceed START");
        const size_t count = size_t(n);
        std::vector<double> t, p;
        for (size_t i = 1; i < lines_.size(); ++i) {
            const Line& line = lines_[i];
            if (t.size() == count)
                Fail(line,
                     "more control points than `curve` declares (" + std::to_string(count) + ")");
            if (line.words.size() != 2)
                Fail(line, "expected a control point `t value`, got " +
                               std::to_string(line.words.size()) + " numbers");
            const double ti = Number(line, 0, "t");
            const double value = Number(line, 1, "the value");
            if (ti < -kTSlack || ti > 1 + kTSlack)
                Fail(line, "control point t = " + line.words[0] + " lies outside [0, 1]");
            NonNegative(line, value);
            if (!t.empty() && ti < t.back() - kTSlack)
                Fail(line,
                     "control point t = " + line.words[0] + " is smaller than the one before");
            // Only a phantom point may share its neighbour's t.
            if (t.size() >= 2 && t.size() + 1 < count && ti <= t.back() + kTSlack)
                Fail(line, "control point t = " + line.words[0] + " repeats the one before");
            t.push_back(ti);
            p.push_back(value);
            lineOf_.push_back(line.number);
        }
        if (t.size() < count)
            FailAt(name_, lastLine_,
                   "truncated: `curve` at line " + std::to_string(header.number) + " declares " +
                       std::to_string(count) + " control points, the file has " +
                       std::to_string(t.size()));
        if (std::abs(t[0] - t[1]) > kTSlack || std::abs(t[count - 1] - t[count - 2]) > kTSlack)
            FailAt(name_, std::abs(t[0] - t[1]) > kTSlack ? lineOf_[0] : lineOf_[count - 1],
                   "the first and last control points must be repeated (the phantom points)");
        if (std::abs(t[1]) > kTSlack || std::abs(t[count - 2] - 1) > kTSlack)
            FailAt(name_, std::abs(t[1]) > kTSlack ? lineOf_[1] : lineOf_[count - 2],
                   "the control points span t = " + ShortestDecimal(t[1]) + ".." +
                       ShortestDecimal(t[count - 2]) + ", which does not cover " + header.words[2] +
                       "-" + header.words[3] + " nm (t = 0..1)");
        std::vector<double> wavelengths, values;
        for (size_t i = 1; i + 1 < count; ++i) {
            wavelengths.push_back(start + t[i] * (end - start));
            values.push_back(p[i]);
        }
        wavelengths.front() = start;  // exactly, whatever the rounding of t
        wavelengths.back() = end;
        Spectrum spectrum(std::move(wavelengths), std::move(values), Interpolation::CatmullRom);
        spectrum.SetPhantoms(p.front(), p.back());
        return spectrum;
    }

    std::string name_;
    int lastLine_;
    std::vector<Line> lines_;
    mutable std::vector<int> lineOf_;
};

std::string CommentLines(const std::string& comment) {
    std::string text;
    size_t start = 0;
    while (start < comment.size()) {
        size_t end = comment.find('\n', start);
        if (end == std::string::npos) end = comment.size();
        text += "# " + comment.substr(start, end - start) + "\n";
        start = end + 1;
    }
    return text;
}

}  // namespace

Spectrum ParseSpectrumFile(const std::vector<std::string>& lines, const std::string& name) {
    return Parser(lines, name).Parse();
}

Spectrum ReadSpectrumFile(const std::string& path) {
    return ParseSpectrumFile(ReadTextLines(path), path);
}

std::string FormatSpectrumFile(const Spectrum& spectrum, const std::string& comment) {
    if (spectrum.Empty()) throw SpectralError("cannot write an empty spectrum");
    for (double v : spectrum.Values())
        if (v < 0) throw SpectralError("cannot write a negative value to a light-source file");
    std::string text = CommentLines(comment);
    const double start = spectrum.MinWavelength(), end = spectrum.MaxWavelength();
    if (spectrum.GetInterpolation() == Interpolation::CatmullRom) {
        if (spectrum.PhantomBefore() < 0 || spectrum.PhantomAfter() < 0)
            throw SpectralError("cannot write a negative phantom value to a light-source file");
        const std::vector<double>& w = spectrum.Wavelengths();
        const std::vector<double>& v = spectrum.Values();
        text += "curve " + std::to_string(w.size() + 2) + " " + ShortestDecimal(start) + " " +
                ShortestDecimal(end) + "\n";
        auto point = [&](double nm, double value) {
            text +=
                ShortestDecimal((nm - start) / (end - start)) + " " + ShortestDecimal(value) + "\n";
        };
        point(start, spectrum.PhantomBefore());
        for (size_t i = 0; i < w.size(); ++i) point(w[i], v[i]);
        point(end, spectrum.PhantomAfter());
        return text;
    }
    double step = 0;
    if (!spectrum.IsRegular(&step))
        throw SpectralError("a `cspec` file needs evenly spaced samples");
    text += "cspec " + ShortestDecimal(start) + " " + ShortestDecimal(end) + " " +
            ShortestDecimal(step) + "\n";
    for (double v : spectrum.Values()) text += ShortestDecimal(v) + "\n";
    return text;
}

void WriteSpectrumFile(const std::string& path, const Spectrum& spectrum,
                       const std::string& comment) {
    WriteTextFileAtomically(path, FormatSpectrumFile(spectrum, comment));
}

}  // namespace gonio::spectral
