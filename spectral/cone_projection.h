#pragma once
// Which colours some non-negative spectrum produces: the convex cone {M x : x ≥ 0} spanned by the
// columns of a 3 × n matrix M (for a colour matrix, the spectral locus closed by the purple line,
// at every brightness). A colour t is tested by projecting it onto the cone with non-negative
// least squares (Lawson & Hanson, "Solving Least Squares Problems", 1974, ch. 23, algorithm NNLS):
// x* ≥ 0 minimising |M x − t|. The residual r = t − M x* is zero when t lies in the cone; when it
// does not, NNLS's optimality conditions (Mᵀ r ≤ 0, rᵀ M x* = 0) make y = −r a Farkas
// certificate: Mᵀ y ≥ 0 and yᵀ t = −|r|² < 0, so no x ≥ 0 has M x = t.

#include <Eigen/Dense>

namespace gonio::spectral {

struct ConeProjection {
    Eigen::VectorXd weights;   // x* ≥ 0, at most rank(M) of them non-zero
    Eigen::Vector3d residual;  // t − M x*
};

// Lawson & Hanson's active-set NNLS; with 3 rows it ends after a few dozen column swaps at most.
ConeProjection ProjectOntoCone(const Eigen::Matrix3Xd& m, const Eigen::Vector3d& target);

}  // namespace gonio::spectral
