#include "solvers/joints/observability.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "edgefit/core/point_kdtree.h"
#include "solvers/joints/body.h"

namespace edgefit {

bool ObservabilityOptions::IsValid(std::string* error) const {
  if (turns.empty() || !(surface_tolerance > 0.0) || !(gap_spacings > 0.0) ||
      !(max_off_share >= 0.0 && max_off_share < 1.0) || max_samples < 100) {
    if (error != nullptr) {
      *error =
          "observability: turns must not be empty, tolerances must be > 0, the off "
          "share in [0, 1) and max_samples >= 100";
    }
    return false;
  }
  return true;
}

double TurnedOffShare(const SurfaceSamples& samples, const Eigen::Vector3d& axis_child,
                      double angle, double spacing, const ObservabilityOptions& options) {
  const size_t n = samples.points.size();
  if (n == 0 || samples.normals.size() != n) return 1.0;
  PointVectorAdaptor adaptor{&samples.points};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  const Eigen::Matrix3f R =
      Eigen::AngleAxisd(angle, axis_child.normalized()).toRotationMatrix().cast<float>();
  const float gap2 = static_cast<float>(std::pow(options.gap_spacings * spacing, 2));
  const float tolerance = static_cast<float>(options.surface_tolerance);
  size_t off = 0;
  for (const Eigen::Vector3f& p : samples.points) {
    const Eigen::Vector3f turned = R * p;
    uint32_t nearest = 0;
    float d2 = 0.0f;
    tree.knnSearch(turned.data(), 1, &nearest, &d2);
    const Eigen::Vector3f offset = turned - samples.points[nearest];
    if (d2 > gap2 || std::abs(samples.normals[nearest].dot(offset)) > tolerance) ++off;
  }
  return static_cast<double>(off) / static_cast<double>(n);
}

bool TurnIsUnobservable(const KinematicModel& model, int joint, const std::vector<double>& q,
                        const std::vector<SurfaceSamples>& link_samples, double spacing,
                        const ObservabilityOptions& options, double* largest_off_share) {
  if (largest_off_share != nullptr) *largest_off_share = 0.0;
  const Joint& j = model.joints()[static_cast<size_t>(joint)];
  if (j.type != JointType::kRevolute && j.type != JointType::kContinuous) return false;
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, Pose::Identity());
  const Body subtree = MakeSubtree(model, j.child_link, joint, T_world_link);
  SurfaceSamples samples;
  AppendBodySamples(subtree, link_samples, Pose::Identity(), &samples);
  if (samples.points.empty()) return false;
  const size_t all = samples.points.size();
  ThinSamples(options.max_samples, &samples);
  const double thinned_spacing =
      spacing * std::sqrt(static_cast<double>(all) / static_cast<double>(samples.points.size()));
  double largest = 0.0;
  for (const double angle : options.turns) {
    largest = std::max(largest, TurnedOffShare(samples, j.axis, angle, thinned_spacing, options));
    if (largest > options.max_off_share) break;  // pinned: the other turns change nothing
  }
  if (largest_off_share != nullptr) *largest_off_share = largest;
  return largest <= options.max_off_share;
}

std::vector<double> WholeTurns(const Joint& j, double q_j) {
  if (j.type != JointType::kRevolute || !j.has_limits || j.upper - j.lower <= 2.0 * M_PI) {
    return {q_j};
  }
  std::vector<double> values;
  const double first = q_j - 2.0 * M_PI * std::floor((q_j - j.lower) / (2.0 * M_PI));
  for (double v = first; v <= j.upper + 1e-12; v += 2.0 * M_PI) values.push_back(v);
  if (values.empty()) values.push_back(q_j);  // q_j outside its limits: leave it
  return values;
}

double ZeroOrNearestLimit(const Joint& j) {
  return j.has_limits ? std::min(std::max(0.0, j.lower), j.upper) : 0.0;
}

double NearestZeroTurn(const Joint& j, double q_j) {
  if (j.type == JointType::kContinuous) return std::remainder(q_j, 2.0 * M_PI);
  double best = q_j;
  for (const double v : WholeTurns(j, q_j)) {
    if (std::abs(v) < std::abs(best) - 1e-12) best = v;
  }
  return best;
}

BaseSymmetry FindBaseSymmetry(const KinematicModel& model,
                              const std::vector<SurfaceSamples>& link_samples, double spacing,
                              const ObservabilityOptions& options) {
  BaseSymmetry symmetry;
  const int root = model.root_link();
  for (size_t j = 0; j < model.joints().size() && symmetry.joint < 0; ++j) {
    const Joint& joint = model.joints()[j];
    if (joint.parent_link == root && joint.IsIndependent() && joint.type != JointType::kPrismatic) {
      symmetry.joint = static_cast<int>(j);
    }
  }
  if (symmetry.joint < 0) return BaseSymmetry();
  SurfaceSamples centred;
  AppendBodySamples(MakeBody(model, root, -1), link_samples, Pose::Identity(), &centred);
  if (centred.points.empty()) return BaseSymmetry();
  const size_t all = centred.points.size();
  ThinSamples(options.max_samples, &centred);
  spacing *= std::sqrt(static_cast<double>(all) / static_cast<double>(centred.points.size()));
  const Joint& joint = model.joints()[static_cast<size_t>(symmetry.joint)];
  // The samples with the joint's axis through the origin.
  const Eigen::Vector3f origin = joint.T_parent_joint.translation().cast<float>();
  for (Eigen::Vector3f& p : centred.points) p -= origin;
  const Eigen::Vector3d axis = joint.T_parent_joint.linear() * joint.axis;
  size_t tested = 0;
  for (int degrees = 30; degrees < 360; degrees += 15) {
    if (degrees % 30 != 0 && degrees % 45 != 0) continue;
    ++tested;
    const double turn = degrees * M_PI / 180.0;
    if (TurnedOffShare(centred, axis, turn, spacing, options) <= options.max_off_share) {
      symmetry.turns.push_back(turn);
    }
  }
  if (symmetry.turns.empty()) {
    symmetry.joint = -1;
    return symmetry;
  }
  symmetry.round = symmetry.turns.size() == tested;  // every multiple of 30 and 45 degrees
  for (const int degrees : {10, 20}) {
    symmetry.round = symmetry.round && TurnedOffShare(centred, axis, degrees * M_PI / 180.0,
                                                      spacing, options) <= options.max_off_share;
  }
  return symmetry;
}

Pose TurnBaseForJoint(const KinematicModel& model, int joint, const Pose& T_world_base,
                      double q_old, double q_new) {
  const Joint& j = model.joints()[static_cast<size_t>(joint)];
  return T_world_base * j.T_parent_joint * Pose(Eigen::AngleAxisd(q_old - q_new, j.axis)) *
         j.T_parent_joint.inverse();
}

}  // namespace edgefit
