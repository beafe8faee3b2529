#include "brdfsim/svg_plot.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "base/interrupt_cleanup.h"

namespace gonio {

namespace {

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

}  // namespace

void WriteSvgPlot(const std::string& path, const PlotLabels& labels,
                  const std::vector<PlotSeries>& series, const PlotLayout& layout) {
    const double left = layout.Left(), top = layout.Top();
    const double plotW = layout.PlotWidth(), plotH = layout.PlotHeight();
    std::ostringstream svg;
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << layout.Width() << "\" height=\""
        << layout.Height() << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<defs><clipPath id=\"frame\"><rect x=\"" << left << "\" y=\"" << top << "\" width=\""
        << plotW << "\" height=\"" << plotH << "\"/></clipPath></defs>\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << left + plotW / 2 << "\" y=\"22\" text-anchor=\"middle\" "
        << "font-size=\"14\">" << Escape(labels.title) << "</text>\n";
    for (double t : layout.XTicks()) {
        svg << "<line x1=\"" << layout.X(t) << "\" y1=\"" << top << "\" x2=\"" << layout.X(t)
            << "\" y2=\"" << top + plotH << "\" stroke=\"#e0e0e0\"/>\n"
            << "<text x=\"" << layout.X(t) << "\" y=\"" << top + plotH + 18
            << "\" text-anchor=\"middle\">" << TickText(t) << "</text>\n";
    }
    for (double t : layout.YTicks()) {
        svg << "<line x1=\"" << left << "\" y1=\"" << layout.Y(t) << "\" x2=\"" << left + plotW
            << "\" y2=\"" << layout.Y(t) << "\" stroke=\"#e0e0e0\"/>\n"
            << "<text x=\"" << left - 8 << "\" y=\"" << layout.Y(t) + 4 << "\" text-anchor=\"end\">"
            << TickText(t) << "</text>\n";
    }
    svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << plotW << "\" height=\""
        << plotH << "\" fill=\"none\" stroke=\"black\"/>\n"
        << "<text x=\"" << left + plotW / 2 << "\" y=\"" << layout.Height() - 15
        << "\" text-anchor=\"middle\">" << Escape(labels.xLabel) << "</text>\n"
        << "<text transform=\"translate(20," << top + plotH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << Escape(labels.yLabel) << "</text>\n";
    for (std::size_t i = 0; i < series.size(); ++i) {
        const PlotSeries& s = series[i];
        const std::string colour = PlotLayout::ColourHex(static_cast<int>(i));
        const char* dash = s.dashed ? " stroke-dasharray=\"6,4\"" : "";
        svg << "<polyline clip-path=\"url(#frame)\" fill=\"none\" stroke=\"" << colour
            << "\" stroke-width=\"1.8\"" << dash << " points=\"";
        for (std::size_t j = 0; j < s.x.size() && j < s.y.size(); ++j) {
            if (!std::isfinite(s.y[j])) continue;
            svg << layout.X(s.x[j]) << "," << layout.Y(s.y[j]) << " ";
        }
        svg << "\"/>\n";
        const double ly = layout.LegendY(static_cast<int>(i));
        svg << "<line x1=\"" << layout.LegendLineX0() << "\" y1=\"" << ly << "\" x2=\""
            << layout.LegendLineX1() << "\" y2=\"" << ly << "\" stroke=\"" << colour
            << "\" stroke-width=\"1.8\"" << dash << "/>\n<text x=\"" << layout.LegendTextX()
            << "\" y=\"" << ly + 4 << "\" font-size=\"10\">" << Escape(s.label) << "</text>\n";
    }
    svg << "</svg>\n";

    const std::string temp = path + ".tmp." + std::to_string(::getpid());
    const PendingTemporary pending(temp);
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
