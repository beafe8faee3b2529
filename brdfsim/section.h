#pragma once
// Cross sections of a BRDF (thesis GPBRDFSection / GPBRDFsectSlow): one of the four angles varies,
// the other three are fixed. The thesis hard-coded the cut in its source; here it is a parameter.

#include <string>
#include <vector>

#include "brdfsim/brdf.h"

namespace gonio {

enum class SectionAxis { kThetaIn, kPhiIn, kThetaOut, kPhiOut };

// Parses "theta-in", "phi-in", "theta-out", "phi-out"; throws std::invalid_argument.
SectionAxis ParseSectionAxis(const std::string& text);
const char* SectionAxisName(SectionAxis axis);

// Angles in degrees. A negative θ on the varying axis means the same zenith on the opposite side
// (φ + 180°), so a θ_out cut from -89° to 89° crosses the whole plane of incidence.
struct SectionCut {
    double thetaIn = 45, phiIn = 0, thetaOut = 45, phiOut = 0;
    SectionAxis vary = SectionAxis::kThetaOut;
    double from = -89, to = 89;
    int samples = 100;
    bool relativePhi = false;  // φ_out counts from φ_in (thesis figs. 5.16, 5.21: Δφ)
    // Where θ_out > θ_in, evaluate f(ω'→ω) as f(ω→ω') (Helmholtz reciprocity), so that the
    // direction photons leave by is the less grazing one: the splat estimate divides each photon
    // leaving near ω by cos θ_out and does not converge at θ_out = 80° (docs/gallery.md), while
    // on the incoming side it averages over simulated incidences.
    bool reciprocal = false;

    // "θi=45 φi=0 φo=0" without the varying angle, for labels.
    std::string Label() const;
    // The varying angle's name for an axis: "phi-out", or "phi-out - phi-in" when relative.
    std::string AxisLabel() const;
};

// Default range of an axis: -89..89 for θ_out, 0..89 for θ_in, 0..360 for φ.
void DefaultRange(SectionAxis axis, double* from, double* to);

struct Section {
    std::vector<double> x;              // the varying angle, degrees
    std::vector<std::vector<float>> f;  // per sample, NumComponents() values (1/sr)
};

// Samples evaluated on both cores.
Section ComputeSection(const Brdf& brdf, const SectionCut& cut);

// The four angles (radians) of sample x of the cut, with negative θ folded to φ + π and, for a
// relative cut, φ_in added to φ_out.
void CutAngles(const SectionCut& cut, double x, double* thetaIn, double* phiIn, double* thetaOut,
               double* phiOut);

}  // namespace gonio
