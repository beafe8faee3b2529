#include "svg_plot.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gonio {

namespace {

constexpr double kWidth = 800, kHeight = 450;
constexpr double kLeft = 80, kRight = 280, kTop = 40, kBottom = 60;
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string Escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

std::string Number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
    return text;
}

}  // namespace

std::vector<double> NiceTicks(double lo, double hi, int count) {
    if (!(hi > lo)) hi = lo + 1;
    const double raw = (hi - lo) / std::max(count, 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        step = m * magnitude;
        if (step >= raw) break;
    }
    std::vector<double> ticks;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
        ticks.push_back(t);
    }
    return ticks;
}

void WriteSvgPlot(const std::string& path, const PlotLabels& labels,
                  const std::vector<PlotSeries>& series) {
    double xMin = 1e300, xMax = -1e300, yMax = 0;
    for (const PlotSeries& s : series) {
        for (double x : s.x) xMin = std::min(xMin, x), xMax = std::max(xMax, x);
        for (double y : s.y) {
            if (std::isfinite(y)) yMax = std::max(yMax, y);
        }
    }
    if (xMin > xMax) xMin = 0, xMax = 1;
    const std::vector<double> yTicks = NiceTicks(0, yMax > 0 ? yMax * 1.05 : 1, 6);
    const double yTop = yTicks.back() >= yMax ? yTicks.back() : yMax;
    const std::vector<double> xTicks = NiceTicks(xMin, xMax, 8);
    const double plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;
    auto px = [&](double x) { return kLeft + (x - xMin) / (xMax - xMin) * plotW; };
    auto py = [&](double y) { return kTop + plotH - y / yTop * plotH; };

    std::ostringstream svg;
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\""
        << kHeight << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << kLeft + plotW / 2 << "\" y=\"22\" text-anchor=\"middle\" "
        << "font-size=\"14\">" << Escape(labels.title) << "</text>\n";
    for (double t : xTicks) {
        svg << "<line x1=\"" << px(t) << "\" y1=\"" << kTop << "\" x2=\"" << px(t) << "\" y2=\""
            << kTop + plotH << "\" stroke=\"#e0e0e0\"/>\n"
            << "<text x=\"" << px(t) << "\" y=\"" << kTop + plotH + 18
            << "\" text-anchor=\"middle\">" << Number(t) << "</text>\n";
    }
    for (double t : yTicks) {
        if (t > yTop + 1e-12) continue;
        svg << "<line x1=\"" << kLeft << "\" y1=\"" << py(t) << "\" x2=\"" << kLeft + plotW
            << "\" y2=\"" << py(t) << "\" stroke=\"#e0e0e0\"/>\n"
            << "<text x=\"" << kLeft - 8 << "\" y=\"" << py(t) + 4 << "\" text-anchor=\"end\">"
            << Number(t) << "</text>\n";
    }
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << plotW << "\" height=\""
        << plotH << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text x=\"" << kLeft + plotW / 2 << "\" y=\"" << kHeight - 15
        << "\" text-anchor=\"middle\">" << Escape(labels.xLabel) << "</text>\n"
        << "<text transform=\"translate(20," << kTop + plotH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << Escape(labels.yLabel) << "</text>\n";
    for (std::size_t i = 0; i < series.size(); ++i) {
        const PlotSeries& s = series[i];
        const char* colour = kColours[i % 8];
        svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.8\""
            << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << " points=\"";
        for (std::size_t j = 0; j < s.x.size() && j < s.y.size(); ++j) {
            if (!std::isfinite(s.y[j])) continue;
            svg << px(s.x[j]) << "," << py(s.y[j]) << " ";
        }
        svg << "\"/>\n";
        const double ly = kTop + 10 + 20.0 * i;
        svg << "<line x1=\"" << kLeft + plotW + 12 << "\" y1=\"" << ly << "\" x2=\""
            << kLeft + plotW + 36 << "\" y2=\"" << ly << "\" stroke=\"" << colour
            << "\" stroke-width=\"1.8\"" << (s.dashed ? " stroke-dasharray=\"6,4\"" : "")
            << "/>\n<text x=\"" << kLeft + plotW + 42 << "\" y=\"" << ly + 4
            << "\" font-size=\"10\">" << Escape(s.label) << "</text>\n";
    }
    svg << "</svg>\n";

    const std::string temp = path + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream file(temp, std::ios::binary);
        file << svg.str();
        if (!file) {
            std::remove(temp.c_str());
            throw std::runtime_error(path + ": cannot write the plot");
        }
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        std::remove(temp.c_str());
        throw std::runtime_error(path + ": cannot write the plot");
    }
}

}  // namespace gonio
