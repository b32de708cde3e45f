// Weighted PCA helpers of the grid normals (paper Eq. 1): a fast Gaussian
// weight for the bounded exponent range used there and the normal of a 3x3
// weighted covariance. Internal to src/edges.
#ifndef EDGEFIT_SRC_EDGES_WEIGHTED_PCA_H_
#define EDGEFIT_SRC_EDGES_WEIGHTED_PCA_H_

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace edgefit {
namespace internal {

// exp(x) for x in [-2, 0] (Eq. 1 with h = d_max / 2 gives exponents
// -2 d^2 / d_max^2 in [-2, 0]) as (Taylor_5(x / 4))^4: relative error < 1e-4,
// branch free, so the window loops vectorise (std::exp does not).
// Also for vectors of floats (row_block.h).
template <typename T>
inline T GaussianWeightExp(T x) {
  const T y = 0.25f * x;
  T e = 1.0f + y * (1.0f + y * (0.5f + y * (1.0f / 6 + y * (1.0f / 24 + y * (1.0f / 120)))));
  e *= e;
  return e * e;
}

// Weighted second moments of neighbour offsets d_k = p_k - p_i.
struct WeightedMoments {
  float w = 0, sx = 0, sy = 0, sz = 0;
  float xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
};

// Unit eigenvector of the smallest eigenvalue of the weighted covariance
// (the WPCA normal), oriented so that n . p_scanner < 0 (toward the scanner
// at the origin). Returns false when the weights sum to zero.
inline bool NormalFromMoments(const WeightedMoments& m, const Eigen::Vector3f& p_scanner,
                              Eigen::Vector3f* n) {
  if (!(m.w > 0.0f)) return false;
  const float inv = 1.0f / m.w;
  const float mx = m.sx * inv, my = m.sy * inv, mz = m.sz * inv;
  Eigen::Matrix3f cov;
  cov(0, 0) = m.xx * inv - mx * mx;
  cov(0, 1) = m.xy * inv - mx * my;
  cov(0, 2) = m.xz * inv - mx * mz;
  cov(1, 1) = m.yy * inv - my * my;
  cov(1, 2) = m.yz * inv - my * mz;
  cov(2, 2) = m.zz * inv - mz * mz;
  cov(1, 0) = cov(0, 1);
  cov(2, 0) = cov(0, 2);
  cov(2, 1) = cov(1, 2);
  // Closed form (Eigen's computeDirect) in double: float loses the smallest
  // eigenvector of nearly flat patches; double costs little here.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov.cast<double>(), Eigen::ComputeEigenvectors);
  Eigen::Vector3f normal = solver.eigenvectors().col(0).cast<float>();  // eigenvalues ascending
  const float norm = normal.norm();
  if (!(norm > 0.0f)) return false;
  normal /= norm;
  if (normal.dot(p_scanner) > 0.0f) normal = -normal;
  *n = normal;
  return true;
}

}  // namespace internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_EDGES_WEIGHTED_PCA_H_
