#include "spectral/cone_projection.h"

#include <vector>

namespace gonio::spectral {
namespace {

// Below this share of |t| · (the longest column), a gradient entry wᵢ = Mᵢᵀ r is rounding, not a
// direction in which the residual still falls.
constexpr double kGradientTolerance = 1e-13;

// min |M_P z − t| over the passive columns P (a complete orthogonal decomposition, so nearly
// dependent columns still give the least-norm answer instead of a blow-up).
Eigen::VectorXd PassiveLeastSquares(const Eigen::Matrix3Xd& m, const std::vector<int>& passive,
                                    const Eigen::Vector3d& target) {
    Eigen::Matrix3Xd columns(3, Eigen::Index(passive.size()));
    for (size_t k = 0; k < passive.size(); ++k) columns.col(Eigen::Index(k)) = m.col(passive[k]);
    return columns.completeOrthogonalDecomposition().solve(target);
}

// Lawson & Hanson's inner loop (NNLS steps 6-11): moves x towards the passive set's least-squares
// solution z only as far as x stays ≥ 0, and frees the columns that reach 0, until z > 0 on the
// whole passive set. Each pass frees at least one column, so it ends within |P| passes.
void SolvePassiveSet(const Eigen::Matrix3Xd& m, const Eigen::Vector3d& target,
                     std::vector<int>* passive, Eigen::VectorXd* x) {
    while (!passive->empty()) {
        const Eigen::VectorXd z = PassiveLeastSquares(m, *passive, target);
        if (z.minCoeff() > 0) {
            for (size_t k = 0; k < passive->size(); ++k) (*x)((*passive)[k]) = z(Eigen::Index(k));
            return;
        }
        double alpha = 1;
        size_t blocking = 0;
        for (size_t k = 0; k < passive->size(); ++k) {
            const double xk = (*x)((*passive)[k]);
            const double zk = z(Eigen::Index(k));
            if (zk <= 0 && xk / (xk - zk) < alpha) alpha = xk / (xk - zk), blocking = k;
        }
        for (size_t k = 0; k < passive->size(); ++k) {
            double& xk = (*x)((*passive)[k]);
            xk += alpha * (z(Eigen::Index(k)) - xk);
        }
        (*x)((*passive)[blocking]) = 0;  // exactly, not rounding's ±1e-17
        std::vector<int> kept;
        for (int column : *passive)
            if ((*x)(column) > 0)
                kept.push_back(column);
            else
                (*x)(column) = 0;
        *passive = kept;
    }
}

bool Contains(const std::vector<int>& set, int value) {
    for (int v : set)
        if (v == value) return true;
    return false;
}

// The column outside P along which the residual falls fastest (NNLS step 3-4), or -1 if none
// does beyond rounding.
int EnteringColumn(const Eigen::Matrix3Xd& m, const Eigen::Vector3d& target,
                   const Eigen::VectorXd& x, const std::vector<int>& passive) {
    const Eigen::VectorXd w = m.transpose() * (target - m * x);
    const double tolerance = kGradientTolerance * target.norm() * m.colwise().norm().maxCoeff();
    int best = -1;
    for (Eigen::Index j = 0; j < w.size(); ++j)
        if (w(j) > tolerance && !Contains(passive, int(j)) && (best < 0 || w(j) > w(best)))
            best = int(j);
    return best;
}

}  // namespace

ConeProjection ProjectOntoCone(const Eigen::Matrix3Xd& m, const Eigen::Vector3d& target) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(m.cols());
    std::vector<int> passive;
    // Lawson & Hanson prove termination in exact arithmetic; the cap only guards against
    // rounding making a column enter and leave forever.
    for (Eigen::Index iteration = 0; iteration < 3 * m.cols() + 3; ++iteration) {
        const int entering = EnteringColumn(m, target, x, passive);
        if (entering < 0) break;
        passive.push_back(entering);
        // A column whose own least-squares weight is not positive cannot lower the residual:
        // only rounding let it look useful (Lawson & Hanson §23.3), so stop here.
        if (PassiveLeastSquares(m, passive, target)(Eigen::Index(passive.size()) - 1) <= 0) break;
        SolvePassiveSet(m, target, &passive, &x);
    }
    return ConeProjection{x, target - m * x};
}

}  // namespace gonio::spectral
