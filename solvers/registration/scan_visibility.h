// How the scanners of a scan set view a point of a model surface: the
// visibility test of the ICP engine (weighted_icp.h) and of the rough sweeps
// (joint_sweep.h). The scan's range image is the z-buffer of the real scene:
// whatever hid a CAD point from a scanner (other parts of the link, other
// links, cables, clutter) is in it.
#ifndef EDGEFIT_SOLVERS_REGISTRATION_SCAN_VISIBILITY_H_
#define EDGEFIT_SOLVERS_REGISTRATION_SCAN_VISIBILITY_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/correspondence/correspondences.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// The view one scanner has of a surface point, worst to best.
enum class ScanView {
  kBackFacing,  // the outward normal faces away from the scanner
  kGrazing,     // facing it so obliquely that its scan points lie farther apart than max_gap
  kOutside,     // outside the scan's angular window
  kOccluded,    // the scan's range at the point's cell is shorter by more than the tolerance
  kEmpty,       // the ray through the point returned nothing (sky, dropout)
  kSeen,        // facing, and the scan's range is not shorter: the point should be in the scan
};

class ScanVisibility {
 public:
  // `scans` and `missing` (nullptr: none; cells taken as if their beam had
  // returned nothing, kEmpty: mixed pixels) are borrowed and must outlive
  // this object.
  explicit ScanVisibility(const ScanSet* scans, const CellMask* missing = nullptr);

  // The view of scan s of q_world with outward unit normal n_world;
  // tolerance [m]: how much nearer than q the scan's range at q's cell may
  // be before q counts as occluded. max_gap [m] (0: off): a surface seen at
  // incidence angle theta from range r with the lattice's angular step d
  // holds scan points about r d / cos(theta) apart along it; above max_gap
  // the point is kGrazing (a face seen edge-on has too few points to say
  // where it is). Unorganized scans or scans without a lattice have no range
  // image: facing points are kSeen.
  ScanView View(size_t s, const Eigen::Vector3d& q_world, const Eigen::Vector3d& n_world,
                double tolerance, double max_gap = 0.0) const;
  // The best view over all scans. facing_only: only the normal test (a
  // facing point is kSeen without looking at the range image).
  ScanView BestView(const Eigen::Vector3d& q_world, const Eigen::Vector3d& n_world,
                    double tolerance, bool facing_only = false, double max_gap = 0.0) const;

 private:
  const ScanSet* scans_;
  const CellMask* missing_;
  std::vector<Pose> T_scanner_world_;                   // per scan
  std::vector<Eigen::Vector3d> scanner_origins_world_;  // per scan
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REGISTRATION_SCAN_VISIBILITY_H_
