#pragma once
// Analytic reference BRDFs spelled "lambert:ALBEDO" or "phong:KD,KS,EXPONENT" (the normalised
// Phong of DESIGN.md: kd/π + ks (n+2)/(2π) cosⁿα). They draw synthetic photon maps and give the
// curves that reconstructions are compared with.

#include <Imath/ImathVec.h>

#include <string>

namespace gonio {

class AnalyticBrdf {
  public:
    // Throws std::invalid_argument with the expected spelling on a bad model string.
    static AnalyticBrdf Parse(const std::string& spelling);

    // Local frame, z the normal; wIn towards the light, wOut towards the viewer (1/sr).
    double Eval(const Imath::V3d& wIn, const Imath::V3d& wOut) const;
    // ∫ f cos θ_out dω_out at incidence thetaIn (radians), by quadrature.
    double Albedo(double thetaIn) const;
    std::string Spelling() const { return spelling_; }
    double Kd() const { return kd_; }
    double Ks() const { return ks_; }
    double Exponent() const { return exponent_; }

    // Draws an outgoing direction for wIn from the mixture of a cosine lobe (probability
    // kd/(kd+ks)) and the Phong lobe around the mirror direction (thesis eq. 3.17); returns
    // its pdf per steradian. u1 picks the lobe, u2 and u3 place the direction.
    Imath::V3d Sample(const Imath::V3d& wIn, double u1, double u2, double u3, double* pdf) const;
    double Pdf(const Imath::V3d& wIn, const Imath::V3d& wOut) const;

  private:
    std::string spelling_;
    double kd_ = 0.0, ks_ = 0.0, exponent_ = 1.0;
};

}  // namespace gonio
