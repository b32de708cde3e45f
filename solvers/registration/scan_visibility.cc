#include "solvers/registration/scan_visibility.h"

#include <glog/logging.h>

#include <algorithm>

namespace edgefit {

ScanVisibility::ScanVisibility(const ScanSet* scans, const CellMask* missing)
    : scans_(scans), missing_(missing) {
  CHECK(scans_ != nullptr);
  if (missing_ != nullptr) CHECK_EQ(missing_->size(), scans_->scans.size());
  for (const OrganizedScan& scan : scans_->scans) {
    T_scanner_world_.push_back(scan.T_world_scanner().inverse());
    scanner_origins_world_.push_back(scan.T_world_scanner().translation());
  }
}

ScanView ScanVisibility::View(size_t s, const Eigen::Vector3d& q_world,
                              const Eigen::Vector3d& n_world, double tolerance,
                              double max_gap) const {
  const Eigen::Vector3d to_scanner = scanner_origins_world_[s] - q_world;
  const double facing = n_world.dot(to_scanner);  // |n| = 1: r cos(theta)
  if (facing <= 0.0) return ScanView::kBackFacing;
  const OrganizedScan& scan = scans_->scans[s];
  if (!scan.organized() || !scan.lattice().valid()) return ScanView::kSeen;
  if (max_gap > 0.0) {
    // gap = r d / cos(theta) = r^2 d / (n . (o - q)).
    const double step = std::max(std::abs(scan.lattice().row_step()),
                                 std::abs(scan.lattice().col_step()));
    if (to_scanner.squaredNorm() * step > max_gap * facing) return ScanView::kGrazing;
  }
  const Eigen::Vector3d q_scanner = T_scanner_world_[s] * q_world;
  int row = 0, col = 0;
  if (!scan.lattice().ProjectToCell(q_scanner, &row, &col)) return ScanView::kOutside;
  const size_t cell = scan.Index(row, col);
  if (!scan.IsValid(cell) || (missing_ != nullptr && (*missing_)[s][cell] != 0)) {
    return ScanView::kEmpty;
  }
  return static_cast<double>(scan.point_scanner(cell).norm()) >= q_scanner.norm() - tolerance
             ? ScanView::kSeen
             : ScanView::kOccluded;
}

ScanView ScanVisibility::BestView(const Eigen::Vector3d& q_world, const Eigen::Vector3d& n_world,
                                  double tolerance, bool facing_only, double max_gap) const {
  ScanView best = ScanView::kBackFacing;
  for (size_t s = 0; s < T_scanner_world_.size() && best != ScanView::kSeen; ++s) {
    if (facing_only) {
      if (n_world.dot(scanner_origins_world_[s] - q_world) > 0.0) best = ScanView::kSeen;
      continue;
    }
    best = std::max(best, View(s, q_world, n_world, tolerance, max_gap));
  }
  return best;
}

}  // namespace edgefit
