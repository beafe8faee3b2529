#pragma once
// The evaluation interface every BRDF representation implements (the thesis's GPBRDF,
// Appendix C.6). Evaluation is const and thread-safe: the shading builtin brdf() calls it from
// all render threads at once.

#include <Imath/ImathVec.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gonio {

class Brdf {
  public:
    virtual ~Brdf() = default;
    virtual int NumComponents() const = 0;
    virtual bool IsIsotropic() const = 0;
    // f(ω' → ω) in 1/sr, NumComponents() values. Local frame: z the surface normal, x the
    // direction of anisotropy; wIn points to the light, wOut to the viewer, both unit. A
    // direction at or below the horizon gives 0.
    virtual void Eval(const Imath::V3f& wIn, const Imath::V3f& wOut, float* f) const = 0;
    // Bytes held by the representation (splats, cell lists, tables).
    virtual std::size_t MemoryBytes() const = 0;

    // Angles in radians, φ from +x towards +y.
    void EvalAngles(double thetaIn, double phiIn, double thetaOut, double phiOut, float* f) const;
};

Imath::V3f DirectionFromAngles(double theta, double phi);

// f for `count` direction pairs given as planes (3 × count floats each, x then y then z), into
// colorComponents × count floats, component-major (the shading language's batch layout); only
// the points with active[p] set (all when active is null) are written. The BRDF's components
// become the colour's: copied when the counts agree, one (grey) component broadcast, otherwise
// their mean (the caller says so).
void EvalPlanes(const Brdf& brdf, int colorComponents, int count, const float* wIn,
                const float* wOut, const uint8_t* active, float* out);

// ∫ f(ω'→ω) cos θ dω over the outgoing hemisphere, per component, by a product midpoint rule
// in sin²θ and φ with `thetaSteps` × 2·thetaSteps points, evaluated on both cores.
std::vector<double> Albedo(const Brdf& brdf, const Imath::V3f& wIn, int thetaSteps = 48);

}  // namespace gonio
