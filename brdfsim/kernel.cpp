#include "brdfsim/kernel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "base/math.h"

namespace gonio {

namespace {

Norm ParseNormOrThrow(const std::string& text) {
    if (text == "l1" || text == "L1") return Norm::kL1;
    if (text == "l2" || text == "L2") return Norm::kL2;
    if (text == "linf" || text == "Linf" || text == "LINF") return Norm::kLinf;
    throw std::invalid_argument("unknown norm '" + text + "' (expected l1, l2 or linf)");
}

// 16-point Gauss-Legendre nodes and weights on [-1, 1].
struct GaussLegendre16 {
    std::array<double, 16> x, w;
    GaussLegendre16() {
        const int n = 16;
        for (int i = 0; i < n; ++i) {
            double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
            double dp = 0.0;
            for (int iter = 0; iter < 100; ++iter) {
                double p0 = 1.0, p1 = 0.0;
                for (int j = 1; j <= n; ++j) {
                    const double p2 = p1;
                    p1 = p0;
                    p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
                }
                dp = n * (z * p0 - p1) / (z * z - 1.0);
                const double dz = p0 / dp;
                z -= dz;
                if (std::abs(dz) < 1e-15) break;
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
    }
};

const GaussLegendre16& Nodes() {
    static const GaussLegendre16 nodes;
    return nodes;
}

// Composite Gauss-Legendre over [lo, hi] with `panels` panels: exact to rounding for the smooth
// pieces of the kernel integrals.
double Integrate(double lo, double hi, int panels, const std::function<double(double)>& g) {
    if (hi <= lo) return 0.0;
    const GaussLegendre16& gl = Nodes();
    const double h = (hi - lo) / panels;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p) {
        const double mid = lo + (p + 0.5) * h;
        for (int i = 0; i < 16; ++i) sum += gl.w[i] * g(mid + 0.5 * h * gl.x[i]);
    }
    return sum * 0.5 * h;
}

// ∫∫ k(norm(a, b) / R) wa(a) wb(b) db da over a in [aLo, aHi] (aLo >= 0), b in [0, R].
// `panels` sets the accuracy: 16 gives rounding-level masses, 4 is enough for tables that are
// interpolated anyway.
double KernelDoubleIntegral(Norm norm, double radius, double aLo, double aHi,
                            const std::function<double(double)>& wa,
                            const std::function<double(double)>& wb, int panels = 16) {
    const int inner = std::max(1, panels / 4);
    return Integrate(aLo, aHi, panels, [&](double a) {
        const double bMax = KernelSupportLimit(norm, radius, a);
        auto integrand = [&](double b) {
            return SplatKernel(CombineDistances(norm, a, b) / radius) * wb(b);
        };
        double sum;
        if (norm == Norm::kLinf && a < bMax) {  // max(a, b) has a kink at b = a
            sum = Integrate(0.0, a, inner, integrand) + Integrate(a, bMax, inner, integrand);
        } else {
            sum = Integrate(0.0, bMax, inner, integrand);
        }
        return sum * wa(a);
    });
}

double SphereWeight(double a) { return 2.0 * kPi * std::sin(a); }
double FlatWeight(double a) { return 2.0 * kPi * a; }
double LineWeight(double) { return 2.0; }  // both signs of the θ_in offset

// Fraction of the circle of geodesic radius a around a point at colatitude c that lies above the
// horizon: z(ψ) = cos c cos a + sin c sin a cos ψ > 0.
double CircleFractionAbove(double c, double a) {
    const double s = std::sin(c) * std::sin(a);
    const double zc = std::cos(c) * std::cos(a);
    if (s < 1e-300) return zc > 0.0 ? 1.0 : 0.0;
    const double u = -zc / s;
    if (u <= -1.0) return 1.0;
    if (u >= 1.0) return 0.0;
    return std::acos(u) / kPi;
}

template <typename Compute>
double Cached(std::map<std::tuple<double, int, int>, double>& cache, double radius, Norm norm,
              int variant, Compute compute) {
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    const auto key = std::make_tuple(radius, static_cast<int>(norm), variant);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    const double value = compute();
    cache.emplace(key, value);
    return value;
}

void CheckRadius(double radius) {
    if (!(radius > 0.0) || radius > kPi / 2) {
        throw std::invalid_argument("splat radius must be in (0, π/2] radians");
    }
}

// Table of in-domain masses over (cIn, cOut) in [0, π/2]², bilinearly interpolated.
class InDomainTable {
  public:
    static constexpr int kSize = 49;
    static constexpr int kPanels = 4;

    InDomainTable(double radius, Norm norm, bool isotropic) : values_(kSize * kSize) {
        for (int i = 0; i < kSize; ++i) {
            for (int j = 0; j < kSize; ++j) {
                values_[i * kSize + j] = Compute(radius, norm, isotropic, Node(i), Node(j));
            }
        }
    }

    double Lookup(double cIn, double cOut) const {
        const double u = std::clamp(cIn / Node(1), 0.0, kSize - 1.0);
        const double v = std::clamp(cOut / Node(1), 0.0, kSize - 1.0);
        const int i = std::min(static_cast<int>(u), kSize - 2);
        const int j = std::min(static_cast<int>(v), kSize - 2);
        const double fu = u - i, fv = v - j;
        auto at = [&](int a, int b) { return values_[a * kSize + b]; };
        return (1 - fu) * ((1 - fv) * at(i, j) + fv * at(i, j + 1)) +
               fu * ((1 - fv) * at(i + 1, j) + fv * at(i + 1, j + 1));
    }

  private:
    static double Node(int i) { return 0.5 * kPi * i / (kSize - 1); }

    static double Compute(double radius, Norm norm, bool isotropic, double cIn, double cOut) {
        auto wb = [&](double b) { return SphereWeight(b) * CircleFractionAbove(cOut, b); };
        if (!isotropic) {
            auto wa = [&](double a) { return SphereWeight(a) * CircleFractionAbove(cIn, a); };
            return KernelDoubleIntegral(norm, radius, 0.0, radius, wa, wb, kPanels);
        }
        // θ_in offset t keeps the splat inside when cIn + t lies in [0, π/2]; split at the ends.
        const double below = std::min(radius, cIn);            // offsets -t, t in [0, below]
        const double above = std::min(radius, kPi / 2 - cIn);  // offsets +t, t in [0, above]
        auto one = [](double) { return 1.0; };
        return KernelDoubleIntegral(norm, radius, 0.0, below, one, wb, kPanels) +
               KernelDoubleIntegral(norm, radius, 0.0, above, one, wb, kPanels);
    }

    std::vector<double> values_;
};

}  // namespace

double KernelSupportLimit(Norm norm, double radius, double a) {
    switch (norm) {
        case Norm::kL1:
            return radius - a;
        case Norm::kL2:
            return std::sqrt(std::max(0.0, radius * radius - a * a));
        case Norm::kLinf:
            return radius;
    }
    return radius;
}

Norm ParseNorm(const std::string& text) { return ParseNormOrThrow(text); }

const char* NormName(Norm norm) {
    switch (norm) {
        case Norm::kL1:
            return "l1";
        case Norm::kL2:
            return "l2";
        case Norm::kLinf:
            return "linf";
    }
    return "?";
}

Horizon ParseHorizon(const std::string& text) {
    if (text == "reflect") return Horizon::kReflect;
    if (text == "renormalize" || text == "thesis") return Horizon::kRenormalize;
    throw std::invalid_argument("unknown horizon mode '" + text +
                                "' (expected reflect or renormalize)");
}

const char* HorizonName(Horizon horizon) {
    return horizon == Horizon::kReflect ? "reflect" : "renormalize";
}

double SphereKernelMass4D(double radius, Norm norm) {
    CheckRadius(radius);
    static std::map<std::tuple<double, int, int>, double> cache;
    return Cached(cache, radius, norm, 0, [&] {
        return KernelDoubleIntegral(norm, radius, 0.0, radius, SphereWeight, SphereWeight);
    });
}

double SphereKernelMass3D(double radius, Norm norm) {
    CheckRadius(radius);
    static std::map<std::tuple<double, int, int>, double> cache;
    return Cached(cache, radius, norm, 1, [&] {
        return KernelDoubleIntegral(norm, radius, 0.0, radius, LineWeight, SphereWeight);
    });
}

double FlatKernelMass4D(double radius, Norm norm) {
    return KernelDoubleIntegral(norm, radius, 0.0, radius, FlatWeight, FlatWeight);
}

double FlatKernelMass3D(double radius, Norm norm) {
    return KernelDoubleIntegral(norm, radius, 0.0, radius, LineWeight, FlatWeight);
}

KernelOutMarginalTable::KernelOutMarginalTable(double radius, Norm norm) : radius_(radius) {
    CheckRadius(radius);
    static std::mutex mutex;
    static std::map<std::pair<double, int>, std::vector<double>> tables;
    std::lock_guard<std::mutex> lock(mutex);
    auto& slot = tables[std::make_pair(radius, static_cast<int>(norm))];
    if (slot.empty()) {
        for (int i = 0; i <= kSteps; ++i) {
            const double a = radius * i / kSteps;
            const double bMax = KernelSupportLimit(norm, radius, a);
            slot.push_back(Integrate(0.0, bMax, 4, [&](double b) {
                return SplatKernel(CombineDistances(norm, a, b) / radius) * SphereWeight(b);
            }));
        }
    }
    table_ = &slot;  // std::map nodes stay where they are
}

double KernelOutMarginalTable::operator()(double dIn) const {
    if (dIn >= radius_) return 0.0;
    const double u = dIn / radius_ * kSteps;
    const int i = std::min(static_cast<int>(u), kSteps - 1);
    return (*table_)[i] + (u - i) * ((*table_)[i + 1] - (*table_)[i]);
}

double KernelOutMarginal(double radius, Norm norm, double dIn) {
    return KernelOutMarginalTable(radius, norm)(dIn);
}

double InDomainKernelMass(double radius, Norm norm, bool isotropic, double cIn, double cOut) {
    CheckRadius(radius);
    static std::mutex mutex;
    static std::map<std::tuple<double, int, int>, std::unique_ptr<InDomainTable>> tables;
    const InDomainTable* table;
    {
        std::lock_guard<std::mutex> lock(mutex);
        auto& slot = tables[std::make_tuple(radius, static_cast<int>(norm), isotropic ? 1 : 0)];
        if (!slot) slot = std::make_unique<InDomainTable>(radius, norm, isotropic);
        table = slot.get();
    }
    return table->Lookup(cIn, cOut);
}

}  // namespace gonio
