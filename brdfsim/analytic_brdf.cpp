#include "brdfsim/analytic_brdf.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "base/math.h"

namespace gonio {

namespace {

std::vector<double> ParseNumberList(const std::string& text) {
    std::vector<double> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        std::size_t used = 0;
        double value;
        try {
            value = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || !std::isfinite(value)) return {};
        values.push_back(value);
    }
    return values;
}

Imath::V3d Mirror(const Imath::V3d& w) { return Imath::V3d(-w.x, -w.y, w.z); }

// An orthonormal frame around a unit vector (Duff et al. 2017).
void Frame(const Imath::V3d& n, Imath::V3d* t, Imath::V3d* b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    *t = Imath::V3d(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = Imath::V3d(c, sign + n.y * n.y * a, -n.y);
}

}  // namespace

AnalyticBrdf AnalyticBrdf::Parse(const std::string& spelling) {
    const std::string usage =
        "expected lambert:ALBEDO or phong:KD,KS,EXPONENT, got '" + spelling + "'";
    const auto colon = spelling.find(':');
    if (colon == std::string::npos) throw std::invalid_argument(usage);
    const std::string name = spelling.substr(0, colon);
    const std::vector<double> values = ParseNumberList(spelling.substr(colon + 1));
    AnalyticBrdf brdf;
    brdf.spelling_ = spelling;
    if (name == "lambert" && values.size() == 1) {
        brdf.kd_ = values[0];
    } else if (name == "phong" && values.size() == 3) {
        brdf.kd_ = values[0];
        brdf.ks_ = values[1];
        brdf.exponent_ = values[2];
    } else {
        throw std::invalid_argument(usage);
    }
    if (brdf.kd_ < 0 || brdf.ks_ < 0 || brdf.kd_ + brdf.ks_ <= 0 || brdf.exponent_ < 0) {
        throw std::invalid_argument(usage + " (needs kd, ks >= 0, kd + ks > 0, exponent >= 0)");
    }
    return brdf;
}

double AnalyticBrdf::Eval(const Imath::V3d& wIn, const Imath::V3d& wOut) const {
    if (wIn.z <= 0 || wOut.z <= 0) return 0.0;
    double f = kd_ / kPi;
    if (ks_ > 0) {
        const double cosAlpha = wOut.dot(Mirror(wIn));
        if (cosAlpha > 0) f += ks_ * (exponent_ + 2) / (2 * kPi) * std::pow(cosAlpha, exponent_);
    }
    return f;
}

double AnalyticBrdf::Albedo(double thetaIn) const {
    const Imath::V3d wIn(std::sin(thetaIn), 0.0, std::cos(thetaIn));
    // cos θ dω = ½ d(sin²θ) dφ: midpoint rule in s = sin²θ and φ.
    const int ns = 400, nphi = 800;
    double sum = 0.0;
    for (int i = 0; i < ns; ++i) {
        const double s = (i + 0.5) / ns;
        const double sinT = std::sqrt(s), cosT = std::sqrt(1 - s);
        for (int j = 0; j < nphi; ++j) {
            const double phi = 2 * kPi * (j + 0.5) / nphi;
            sum += Eval(wIn, Imath::V3d(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
        }
    }
    return sum * 0.5 * (1.0 / ns) * (2 * kPi / nphi);
}

Imath::V3d AnalyticBrdf::Sample(const Imath::V3d& wIn, double u1, double u2, double u3,
                                double* pdf) const {
    const double pDiffuse = kd_ / (kd_ + ks_);
    Imath::V3d axis(0, 0, 1);
    double cosT;
    if (u1 < pDiffuse) {
        cosT = std::sqrt(1 - u2);  // cosine-weighted
    } else {
        axis = Mirror(wIn);
        cosT = std::pow(1 - u2, 1.0 / (exponent_ + 1));  // thesis eq. 3.17
    }
    const double sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT));
    const double phi = 2 * kPi * u3;
    Imath::V3d t, b;
    Frame(axis, &t, &b);
    const Imath::V3d w = (t * std::cos(phi) + b * std::sin(phi)) * sinT + axis * cosT;
    *pdf = Pdf(wIn, w);
    return w;
}

double AnalyticBrdf::Pdf(const Imath::V3d& wIn, const Imath::V3d& wOut) const {
    const double pDiffuse = kd_ / (kd_ + ks_);
    double pdf = wOut.z > 0 ? pDiffuse * wOut.z / kPi : 0.0;
    const double cosAlpha = wOut.dot(Mirror(wIn));
    if (pDiffuse < 1 && cosAlpha > 0) {
        pdf += (1 - pDiffuse) * (exponent_ + 1) / (2 * kPi) * std::pow(cosAlpha, exponent_);
    }
    return pdf;
}

}  // namespace gonio
