#include "brdfsim/section.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "base/math.h"

namespace gonio {

namespace {

// Negative zenith: the same zenith on the other side of the pole.
void Fold(double thetaDeg, double phiDeg, double* theta, double* phi) {
    *theta = std::abs(thetaDeg) * kDegree;
    *phi = (thetaDeg < 0 ? phiDeg + 180.0 : phiDeg) * kDegree;
}
}  // namespace

SectionAxis ParseSectionAxis(const std::string& text) {
    if (text == "theta-in") return SectionAxis::kThetaIn;
    if (text == "phi-in") return SectionAxis::kPhiIn;
    if (text == "theta-out") return SectionAxis::kThetaOut;
    if (text == "phi-out") return SectionAxis::kPhiOut;
    throw std::invalid_argument("--vary expects theta-in, phi-in, theta-out or phi-out, got '" +
                                text + "'");
}

const char* SectionAxisName(SectionAxis axis) {
    switch (axis) {
        case SectionAxis::kThetaIn:
            return "theta-in";
        case SectionAxis::kPhiIn:
            return "phi-in";
        case SectionAxis::kThetaOut:
            return "theta-out";
        case SectionAxis::kPhiOut:
            return "phi-out";
    }
    return "?";
}

std::string SectionCut::Label() const {
    char text[128];
    std::string label;
    const struct {
        SectionAxis axis;
        const char* name;
        double value;
    } angles[] = {{SectionAxis::kThetaIn, "θi", thetaIn},
                  {SectionAxis::kPhiIn, "φi", phiIn},
                  {SectionAxis::kThetaOut, "θo", thetaOut},
                  {SectionAxis::kPhiOut, relativePhi ? "φo-φi" : "φo", phiOut}};
    for (const auto& a : angles) {
        if (a.axis == vary) continue;
        std::snprintf(text, sizeof text, "%s%s=%g°", label.empty() ? "" : " ", a.name, a.value);
        label += text;
    }
    return reciprocal ? label + " reciprocal" : label;
}

std::string SectionCut::AxisLabel() const {
    const std::string name = SectionAxisName(vary);
    return relativePhi && vary == SectionAxis::kPhiOut ? name + " - phi-in" : name;
}

void DefaultRange(SectionAxis axis, double* from, double* to) {
    switch (axis) {
        case SectionAxis::kThetaOut:
            *from = -89, *to = 89;
            break;
        case SectionAxis::kThetaIn:
            *from = 0, *to = 89;
            break;
        default:
            *from = 0, *to = 360;
            break;
    }
}

void CutAngles(const SectionCut& cut, double x, double* thetaIn, double* phiIn, double* thetaOut,
               double* phiOut) {
    double ti = cut.thetaIn, pi = cut.phiIn, to = cut.thetaOut, po = cut.phiOut;
    switch (cut.vary) {
        case SectionAxis::kThetaIn:
            ti = x;
            break;
        case SectionAxis::kPhiIn:
            pi = x;
            break;
        case SectionAxis::kThetaOut:
            to = x;
            break;
        case SectionAxis::kPhiOut:
            po = x;
            break;
    }
    if (cut.relativePhi) po += pi;
    Fold(ti, pi, thetaIn, phiIn);
    Fold(to, po, thetaOut, phiOut);
}

Section ComputeSection(const Brdf& brdf, const SectionCut& cut) {
    if (cut.samples < 1) throw std::invalid_argument("a section needs at least one sample");
    Section section;
    section.x.resize(cut.samples);
    section.f.assign(cut.samples, std::vector<float>(brdf.NumComponents()));
    tbb::parallel_for(0, cut.samples, [&](int i) {
        const double x =
            cut.samples == 1 ? cut.from : cut.from + (cut.to - cut.from) * i / (cut.samples - 1);
        double ti, pi, to, po;
        CutAngles(cut, x, &ti, &pi, &to, &po);
        section.x[i] = x;
        if (cut.reciprocal && to > ti) {
            brdf.EvalAngles(to, po, ti, pi, section.f[i].data());
        } else {
            brdf.EvalAngles(ti, pi, to, po, section.f[i].data());
        }
    });
    return section;
}

}  // namespace gonio
