// The CAD's own deviation as a part of the whole-chain covariance
// (chain_refinement.h). A real part is not its CAD (castings, welds, paint),
// and the difference is smooth: each patch of a link's surface, a cube of
// `size` in the link frame, is taken to be displaced as a whole by a
// displacement of its own, with standard deviation sigma_cad along each of
// the world's axes. A point-to-plane residual r_i = n_i^T (...) then changes
// by n_i^T times its patch's displacement, and the estimate x by
//
//   Cov_cad(x) = sigma_cad^2 H^-1 (sum_c sum_a g_ca g_ca^T) H^-1,
//   g_ca = sum over the rows i of patch c of n_i,a J_i,
//
// with H = J^T J. Unlike the residuals' part, more samples of the same
// patches do not shrink it.
#ifndef EDGEFIT_SOLVERS_REFINEMENT_SURFACE_PATCHES_H_
#define EDGEFIT_SOLVERS_REFINEMENT_SURFACE_PATCHES_H_

#include <ceres/crs_matrix.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace edgefit {

// H^-1 = (J^T J)^+ of a problem's Jacobian: its pseudo-inverse over the
// eigen-directions above 1e-12 of the largest eigenvalue (the others are
// directions no residual pins: a joint that moves nothing seen, a round
// base's yaw with its first joint). estimable[k]: parameter k has at most
// 1e-4 of its unit vector in those directions, so its variance s^2 H^+_kk is
// that of an estimable parameter; the others have none. False (nothing
// written) for a zero Jacobian.
bool InverseNormalMatrix(const ceres::CRSMatrix& jacobian, Eigen::MatrixXd* H_inverse,
                         std::vector<bool>* estimable);

// The patch of every residual row of a problem, in the problem's order.
class SurfacePatches {
 public:
  explicit SurfacePatches(double size) : size_(size) {}

  // The rows of one sample: one point-to-plane row (n_world: its unit
  // normal; scale: the factor its residual carries, sqrt(w_edge)), or three
  // point-to-point rows, which have no normal to be displaced along.
  void AddPlaneRow(int link, const Eigen::Vector3d& p_link, const Eigen::Vector3d& n_world,
                   double scale);
  void AddPointRows();

  // Cov_cad above for the Jacobian J of the rows added (jacobian.num_rows
  // of them) and H^-1; zero when sigma_cad is 0.
  Eigen::MatrixXd Covariance(const ceres::CRSMatrix& jacobian, const Eigen::MatrixXd& H_inverse,
                             double sigma_cad) const;

 private:
  double size_;                                        // [m]
  std::map<std::array<int64_t, 4>, int> ids_;          // (link, cube) -> patch
  std::vector<std::pair<int, Eigen::Vector3d>> rows_;  // patch (-1: none), scale * n_world
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REFINEMENT_SURFACE_PATCHES_H_
