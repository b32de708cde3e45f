// One Ceres solve of the weighted ICP (weighted_icp.h) for fixed
// correspondences: the data residuals of paper Eq. (8) (or point-to-plane)
// and, for a link on a joint, its constraint in the chosen parameterisation
// (Eq. (10) axis points, Eq. (14) line and plane, or the joint value alone).
// Internal to edgefit::solvers; all autodiff cost instantiations of the
// engine live in icp_step.cc, so they compile once.
#ifndef EDGEFIT_SOLVERS_REGISTRATION_ICP_STEP_H_
#define EDGEFIT_SOLVERS_REGISTRATION_ICP_STEP_H_

#include <ceres/loss_function.h>

#include <Eigen/Core>
#include <vector>

#include "edgefit/correspondence/correspondences.h"
#include "edgefit/scan/organized_scan.h"
#include "solvers/registration/link_motion.h"
#include "solvers/registration/weighted_icp.h"

namespace edgefit {

struct IcpStepInput {
  const std::vector<Eigen::Vector3f>* p_link = nullptr;          // CAD samples, link frame
  const std::vector<Correspondence>* correspondences = nullptr;  // gated matches
  const ScanSet* scans = nullptr;
  const std::vector<std::vector<Eigen::Vector3f>>* normals_scanner = nullptr;  // or nullptr
  // PlaneNormals::kModel: the samples' normals (link frame, parallel to
  // p_link) and the rotation that poses them for this solve; nullptr: the
  // scan's normals.
  const std::vector<Eigen::Vector3f>* n_link = nullptr;
  Eigen::Matrix3d R_world_link = Eigen::Matrix3d::Identity();
  const LinkMotion* motion = nullptr;
  const WeightedIcpOptions* options = nullptr;
  const ResidualOptions* residuals = nullptr;
  ceres::LossFunction* loss = nullptr;  // borrowed, shared by the data residuals
  // Penalty anchors in the link frame (kPoseWithPenalties): the axis points
  // are axis_center_link +/- axis_half_span * axis; the plane point of
  // Eq. (14) is axis_center_link + axis_half_span * (a unit normal of axis).
  Eigen::Vector3d axis_center_link = Eigen::Vector3d::Zero();
  double axis_half_span = 0.1;  // [m]
};

// The parameters of the solve: a 6-DoF pose (angle-axis rotation and
// translation of T_world_link) or a joint value q.
struct IcpParameters {
  double rotation_world_link[3] = {0.0, 0.0, 0.0};
  double translation_world_link[3] = {0.0, 0.0, 0.0};
  double q = 0.0;
};

// Whether the solve uses the joint value (true) or the 6-DoF pose (false).
bool SolvesJointValue(const LinkMotion& motion, const ResidualOptions& residuals);

// Builds and solves the problem from *parameters; on success updates them
// and sets *final_cost. Returns false when Ceres gives no usable solution.
bool SolveIcpStep(const IcpStepInput& input, IcpParameters* parameters, double* final_cost);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REGISTRATION_ICP_STEP_H_
