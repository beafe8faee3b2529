#pragma once
// The colour representations of thesis ch. 6, evaluated on patches (no geometry): one light
// shining on surfaces, the light reflected once (l∘r_j) and twice (l∘r_j1∘r_j2, all ordered
// pairs). Each representation gives the tristimulus values it would compute for these paths:
//
//  reference        the working grid's samples (81 at 5 nm over 380-780 nm), exact products
//  rgb              light and reflectances reduced to linear sRGB, products per channel
//  bands-k          k box bands, edges from the scene's one-bounce spectra, products per band
//  svd-k exact      thesis §6.1.2 basis (first k left singular vectors of the one-bounce
//                   matrix); each surface stored as the coefficients of its product with the
//                   light, so direct light is the exact projection (§6.1.3); a second bounce
//                   through the k×k projected operator Bᵀ diag(r) B
//  svd-k rendered   what Option "spectral" "basis" "svd" renders: the basis of
//                   render_color_space.h's LightSvdBasis, direct light projected as above, and
//                   a second bounce multiplying coordinates component by component
//  svd-k eq. 6.9    the thesis's eq. 6.9 as written: coefficients multiplied component by
//                   component. Wrong for an SVD basis, whose vectors overlap; kept to measure it
//
// One light per scene: by superposition (§6.1.3) each light is rendered, and measured, alone.

#include <Eigen/Dense>
#include <vector>

#include "spectral/colorimetry.h"

namespace gonio::spectral {

struct PatchScene {
    SampledObserver observer;
    Eigen::VectorXd light;          // on observer.grid
    Eigen::MatrixXd reflectances;   // one column per surface
    Eigen::VectorXd rgbIlluminant;  // D65: reflectances' RGB is their colour under it
};

// Raw tristimulus values (Σ S cmf Δλ, not normalised), one column per path: one-bounce in surface
// order, two-bounce with index j1·m + j2.
struct BounceColours {
    Eigen::Matrix3Xd oneBounce;
    Eigen::Matrix3Xd twoBounce;
};

BounceColours ReferenceColours(const PatchScene& scene);
BounceColours RgbColours(const PatchScene& scene);

// The band edges as sample indices e_0 = 0 < e_1 < ... < e_k = n; band b holds samples
// [e_b, e_{b+1}). The edges split the one-bounce energy seen by the observer,
// Σ_j l(λ) r_j(λ) (x̄ + ȳ + z̄)(λ), into k equal shares (thesis §6.1.2: the representation follows
// the spectra that actually appear), each band at least one sample. 1 ≤ k ≤ n.
std::vector<int> BandEdges(const PatchScene& scene, int k);
BounceColours BandColours(const PatchScene& scene, int k);

// The first k left singular vectors of [l∘r_1 ... l∘r_m] (n × k, orthonormal columns), each
// signed so its samples sum to ≥ 0. 1 ≤ k ≤ min(n, m).
Eigen::MatrixXd SvdBasis(const PatchScene& scene, int k);
BounceColours SvdExactDirectColours(const PatchScene& scene, int k);
BounceColours SvdRenderedColours(const PatchScene& scene, int k);
BounceColours SvdEq69Colours(const PatchScene& scene, int k);

}  // namespace gonio::spectral
