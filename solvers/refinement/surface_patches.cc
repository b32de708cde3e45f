#include "solvers/refinement/surface_patches.h"

#include <glog/logging.h>

#include <Eigen/Eigenvalues>
#include <cmath>

namespace edgefit {

bool InverseNormalMatrix(const ceres::CRSMatrix& jacobian, Eigen::MatrixXd* H_inverse,
                         std::vector<bool>* estimable) {
  Eigen::MatrixXd JtJ = Eigen::MatrixXd::Zero(jacobian.num_cols, jacobian.num_cols);
  for (int row = 0; row < jacobian.num_rows; ++row) {
    const int begin = jacobian.rows[static_cast<size_t>(row)];
    const int end = jacobian.rows[static_cast<size_t>(row) + 1];
    for (int a = begin; a < end; ++a) {
      for (int b = begin; b < end; ++b) {
        JtJ(jacobian.cols[static_cast<size_t>(a)], jacobian.cols[static_cast<size_t>(b)]) +=
            jacobian.values[static_cast<size_t>(a)] * jacobian.values[static_cast<size_t>(b)];
      }
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(JtJ);
  const Eigen::VectorXd& eigenvalues = eigen.eigenvalues();
  const Eigen::MatrixXd& V = eigen.eigenvectors();
  const double largest = eigenvalues.maxCoeff();
  if (!(largest > 0.0)) return false;
  Eigen::VectorXd inverse = Eigen::VectorXd::Zero(eigenvalues.size());
  Eigen::VectorXd null_share = Eigen::VectorXd::Zero(eigenvalues.size());  // per parameter
  for (Eigen::Index i = 0; i < eigenvalues.size(); ++i) {
    if (eigenvalues[i] > 1e-12 * largest) {
      inverse[i] = 1.0 / eigenvalues[i];
    } else {
      null_share += V.col(i).cwiseAbs2();
    }
  }
  *H_inverse = V * inverse.asDiagonal() * V.transpose();
  estimable->resize(static_cast<size_t>(eigenvalues.size()));
  for (Eigen::Index k = 0; k < eigenvalues.size(); ++k) {
    (*estimable)[static_cast<size_t>(k)] = null_share[k] <= 1e-4;
  }
  return true;
}

void SurfacePatches::AddPlaneRow(int link, const Eigen::Vector3d& p_link,
                                 const Eigen::Vector3d& n_world, double scale) {
  std::array<int64_t, 4> key = {link, 0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    key[static_cast<size_t>(a) + 1] = static_cast<int64_t>(std::floor(p_link[a] / size_));
  }
  const auto inserted = ids_.emplace(key, static_cast<int>(ids_.size()));
  rows_.emplace_back(inserted.first->second, scale * n_world.normalized());
}

void SurfacePatches::AddPointRows() { rows_.insert(rows_.end(), 3, {-1, Eigen::Vector3d::Zero()}); }

Eigen::MatrixXd SurfacePatches::Covariance(const ceres::CRSMatrix& jacobian,
                                           const Eigen::MatrixXd& H_inverse,
                                           double sigma_cad) const {
  CHECK_EQ(rows_.size(), static_cast<size_t>(jacobian.num_rows));
  const int columns = jacobian.num_cols;
  if (sigma_cad == 0.0) return Eigen::MatrixXd::Zero(columns, columns);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(columns, 3 * static_cast<Eigen::Index>(ids_.size()));
  for (size_t row = 0; row < rows_.size(); ++row) {
    const auto& [patch, normal] = rows_[row];
    if (patch < 0) continue;
    for (int k = jacobian.rows[row]; k < jacobian.rows[row + 1]; ++k) {
      g.block<1, 3>(jacobian.cols[static_cast<size_t>(k)], 3 * patch) +=
          jacobian.values[static_cast<size_t>(k)] * normal.transpose();
    }
  }
  // Coefficient by coefficient (lazyProduct): Eigen's blocked product splits
  // its long inner sums by the number of OpenMP threads, and the deviations
  // then differed in their last digit between thread counts.
  const Eigen::MatrixXd spread = H_inverse.lazyProduct(g);
  return sigma_cad * sigma_cad * spread.lazyProduct(spread.transpose());
}

}  // namespace edgefit
