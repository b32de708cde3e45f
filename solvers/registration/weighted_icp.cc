#include "solvers/registration/weighted_icp.h"

#include <ceres/rotation.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "costs/robust_loss.h"
#include "edgefit/core/median.h"
#include "solvers/registration/icp_step.h"

namespace edgefit {

const char* IcpStopReasonName(IcpStopReason reason) {
  switch (reason) {
    case IcpStopReason::kConverged:
      return "converged";
    case IcpStopReason::kMaxIterations:
      return "max_iterations";
    case IcpStopReason::kTooFewCorrespondences:
      return "too_few_correspondences";
    case IcpStopReason::kSolverFailed:
      return "solver_failed";
  }
  return "?";
}

bool WeightedIcpOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (!(convergence_displacement >= 0.0)) return fail("convergence_displacement must be >= 0");
  if (min_correspondences < 1) return fail("min_correspondences must be at least 1");
  if (!correspondence.IsValid(error)) return false;
  if (solver_iterations < 1) return fail("solver_iterations must be at least 1");
  if (!(final_gate > 0.0) || !std::isfinite(final_gate)) return fail("final_gate must be > 0");
  if (!(quality_max_view_gap >= 0.0) || !std::isfinite(quality_max_view_gap)) {
    return fail("quality_max_view_gap must be finite and >= 0");
  }
  if (!(quality_reach >= 0.0) || !std::isfinite(quality_reach)) {
    return fail("quality_reach must be finite and >= 0");
  }
  if (!(crop_margin >= 0.0) || !std::isfinite(crop_margin)) {
    return fail("crop_margin must be finite and >= 0");
  }
  return true;
}

std::string WeightedIcpSummary::BriefReport() const {
  char line[256];
  std::snprintf(line, sizeof(line),
                "%d iterations (%s), %zu/%zu visible samples inliers (%.1f%%), RMS %.3f mm, "
                "cost %.6g, %.3f s",
                iterations, IcpStopReasonName(stop_reason), inliers, visible_points,
                100.0 * inlier_share, rms * 1e3, final_cost, seconds);
  return line;
}

namespace {

Pose PoseFromParameters(const IcpParameters& parameters) {
  double R[9];  // column-major
  ceres::AngleAxisToRotationMatrix(parameters.rotation_world_link, R);
  Pose T = Pose::Identity();
  T.linear() = Eigen::Map<const Eigen::Matrix3d>(R);
  T.translation() = Eigen::Map<const Eigen::Vector3d>(parameters.translation_world_link);
  return T;
}

void SetPoseParameters(const Pose& T, IcpParameters* parameters) {
  const Eigen::Matrix3d R = T.linear();  // column-major, as ceres expects
  ceres::RotationMatrixToAngleAxis(R.data(), parameters->rotation_world_link);
  Eigen::Map<Eigen::Vector3d>(parameters->translation_world_link) = T.translation();
}

// Largest distance a point of `corners_link` moves between two poses.
double MaxDisplacement(const std::array<Eigen::Vector3d, 8>& corners_link, const Pose& before,
                       const Pose& after) {
  double max_distance = 0.0;
  for (const Eigen::Vector3d& c : corners_link) {
    max_distance = std::max(max_distance, (after * c - before * c).norm());
  }
  return max_distance;
}

}  // namespace

WeightedIcp::WeightedIcp(const ScanSet* scans, CorrespondenceSearch* search,
                         const std::vector<std::vector<Eigen::Vector3f>>* normals_scanner,
                         const ResidualOptions& residuals)
    : scans_(scans),
      search_(search),
      normals_scanner_(normals_scanner),
      residuals_(residuals),
      visibility_(scans) {
  CHECK(scans_ != nullptr && search_ != nullptr);
}

size_t WeightedIcp::SelectAndPose(const SurfaceSamples& samples, const Pose& T_world_link,
                                  WeightedIcpOptions::Visibility visibility, double gate,
                                  double max_view_gap) {
  const Eigen::Matrix3d R = T_world_link.linear();
  const Eigen::Vector3d& t = T_world_link.translation();
  const bool has_normals = samples.normals.size() == samples.points.size();
  const bool filter = visibility != WeightedIcpOptions::Visibility::kAll && has_normals;
  p_used_link_.clear();
  n_used_link_.clear();
  q_world_.clear();
  // The visibility test in parallel, the samples kept in their order: the
  // same selection for any thread count.
  const int64_t count = static_cast<int64_t>(samples.points.size());
  views_.assign(samples.points.size(), ScanView::kSeen);
  if (filter) {
    const bool facing_only = visibility == WeightedIcpOptions::Visibility::kFacing;
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < count; ++i) {
      const size_t k = static_cast<size_t>(i);
      const Eigen::Vector3d q = R * samples.points[k].cast<double>() + t;
      const Eigen::Vector3d n = R * samples.normals[k].cast<double>();
      views_[k] = visibility_.BestView(q, n, gate, facing_only, max_view_gap);
    }
  }
  size_t occluded = 0;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    occluded += views_[i] == ScanView::kOccluded;
    if (views_[i] != ScanView::kSeen) continue;
    const Eigen::Vector3d q = R * samples.points[i].cast<double>() + t;
    p_used_link_.push_back(samples.points[i]);
    if (has_normals) n_used_link_.push_back(samples.normals[i]);
    q_world_.push_back(q.cast<float>());
  }
  return occluded;
}

Status WeightedIcp::Fit(const SurfaceSamples& samples, const LinkMotion& motion,
                        const WeightedIcpOptions& options, LinkState* state,
                        WeightedIcpSummary* summary) {
  CHECK(state != nullptr && summary != nullptr);
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error) || !residuals_.IsValid(&error)) {
    return Status::Error("weighted ICP: " + error);
  }
  const std::vector<Eigen::Vector3f>& p_link = samples.points;
  if (p_link.empty()) return Status::Error("weighted ICP: the link has no CAD samples");
  const bool model_normals =
      options.point_to_plane && options.plane_normals == WeightedIcpOptions::PlaneNormals::kModel;
  if (options.point_to_plane && !model_normals && normals_scanner_ == nullptr) {
    return Status::Error("weighted ICP: point_to_plane needs target normals");
  }
  if (model_normals && samples.normals.size() != p_link.size()) {
    return Status::Error("weighted ICP: point_to_plane with model normals needs sample normals");
  }
  const bool joint_space = SolvesJointValue(motion, residuals_);
  std::unique_ptr<ceres::LossFunction> loss;
  EDGEFIT_RETURN_IF_ERROR(MakeLoss(residuals_.loss, residuals_.loss_scale, &loss));

  *summary = WeightedIcpSummary();
  summary->source_points = p_link.size();

  // The samples' box in the link frame: its corners bound every sample's
  // motion, its centre anchors the axis points of the penalties.
  Eigen::AlignedBox3d box_link;
  for (const Eigen::Vector3f& p : p_link) box_link.extend(p.cast<double>());
  std::array<Eigen::Vector3d, 8> corners_link;
  for (int i = 0; i < 8; ++i) {
    corners_link[static_cast<size_t>(i)] =
        box_link.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i));
  }
  IcpStepInput input;
  input.p_link = &p_used_link_;
  input.n_link = model_normals ? &n_used_link_ : nullptr;
  input.correspondences = &correspondences_;
  input.scans = scans_;
  input.normals_scanner = normals_scanner_;
  input.motion = &motion;
  input.options = &options;
  input.residuals = &residuals_;
  input.loss = loss.get();
  const Eigen::Vector3d centre = box_link.center();
  input.axis_center_link = motion.axis_joint * motion.axis_joint.dot(centre);
  input.axis_half_span = std::max(0.05, 0.5 * box_link.diagonal().norm());

  // Initial estimate.
  const double q_initial = motion.Clamp(state->q);
  Pose T_world_link = motion.constrained() ? motion.PoseAt(q_initial) : state->T_world_link;
  IcpParameters parameters;
  parameters.q = q_initial;
  SetPoseParameters(T_world_link, &parameters);

  Eigen::AlignedBox3d crop_world;
  for (int i = 0; i < 8; ++i)
    crop_world.extend(T_world_link * corners_link[static_cast<size_t>(i)]);
  const double grow = options.correspondence.max_distance + options.crop_margin;
  crop_world.min().array() -= grow;
  crop_world.max().array() += grow;

  CorrespondenceOptions gated = options.correspondence;
  const double final_gate = std::min(options.final_gate, options.correspondence.max_distance);
  summary->stop_reason = IcpStopReason::kMaxIterations;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    SelectAndPose(samples, T_world_link, options.visibility, gated.max_distance, 0.0);
    search_->Find(q_world_, crop_world, gated, &correspondences_);
    if (correspondences_.size() < static_cast<size_t>(options.min_correspondences)) {
      summary->stop_reason = IcpStopReason::kTooFewCorrespondences;
      break;
    }
    input.R_world_link = T_world_link.linear();
    if (!SolveIcpStep(input, &parameters, &summary->final_cost)) {
      summary->stop_reason = IcpStopReason::kSolverFailed;
      break;
    }
    ++summary->iterations;
    const Pose T_next = joint_space ? motion.PoseAt(parameters.q) : PoseFromParameters(parameters);
    const double displacement = MaxDisplacement(corners_link, T_world_link, T_next);
    T_world_link = T_next;
    const bool at_final_gate = gated.max_distance <= final_gate;
    gated.max_distance = std::max(final_gate, 0.5 * gated.max_distance);
    if (at_final_gate && displacement <= options.convergence_displacement) {
      summary->stop_reason = IcpStopReason::kConverged;
      break;
    }
  }

  // The paper's projection onto the joint (Sec. 5.2.2, 6.2.2).
  double q = parameters.q;
  if (motion.constrained() && !joint_space) {
    q = motion.Project(T_world_link, q_initial);
    const Pose T_projected = motion.PoseAt(q);
    summary->projection_shift = MaxDisplacement(corners_link, T_world_link, T_projected);
    T_world_link = T_projected;
  }

  // Quality at the returned pose.
  Measure(samples, T_world_link, options, final_gate, crop_world, summary);

  state->T_world_link = T_world_link;
  state->q = motion.constrained() ? q : 0.0;
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

void WeightedIcp::Measure(const SurfaceSamples& samples, const Pose& T_world_link,
                          const WeightedIcpOptions& options, double gate,
                          const Eigen::AlignedBox3d& crop_world, WeightedIcpSummary* summary) {
  const bool plane =
      options.point_to_plane && options.plane_normals == WeightedIcpOptions::PlaneNormals::kModel &&
      samples.normals.size() == samples.points.size() && options.quality_reach > gate;
  CorrespondenceOptions gated = options.correspondence;
  gated.max_distance = plane ? options.quality_reach : gate;
  summary->occluded_points =
      SelectAndPose(samples, T_world_link, options.visibility, gate, options.quality_max_view_gap);
  summary->visible_points = q_world_.size();
  search_->Find(q_world_, crop_world, gated, &correspondences_);
  const Eigen::Matrix3d R = T_world_link.linear();
  double sum_squared = 0.0;
  size_t inliers = 0;
  std::vector<double> distances;
  distances.reserve(correspondences_.size());
  for (const Correspondence& m : correspondences_) {
    double d = m.distance;
    if (plane) {
      const size_t k = static_cast<size_t>(m.source);
      const Eigen::Vector3d n = R * n_used_link_[k].cast<double>();
      const Eigen::Vector3d target =
          scans_->scans[static_cast<size_t>(m.scan)].PointWorld(static_cast<size_t>(m.cell));
      d = std::abs(n.dot(target - q_world_[k].cast<double>()));
      if (d > gate) continue;
    }
    sum_squared += d * d;
    distances.push_back(d);
    ++inliers;
  }
  summary->inliers = inliers;
  if (!distances.empty()) summary->median_distance = MedianInPlace(&distances);
  summary->inlier_share =
      summary->visible_points > 0
          ? static_cast<double>(summary->inliers) / static_cast<double>(summary->visible_points)
          : 0.0;
  summary->rms =
      summary->inliers > 0 ? std::sqrt(sum_squared / static_cast<double>(summary->inliers)) : 0.0;
}

Status WeightedIcp::Evaluate(const SurfaceSamples& samples, const Pose& T_world_link,
                             const WeightedIcpOptions& options, WeightedIcpSummary* summary) {
  CHECK(summary != nullptr);
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("weighted ICP: " + error);
  if (samples.points.empty()) return Status::Error("weighted ICP: the link has no CAD samples");
  *summary = WeightedIcpSummary();
  summary->source_points = samples.points.size();
  const double gate = std::min(options.final_gate, options.correspondence.max_distance);
  Eigen::AlignedBox3d crop_world;
  for (const Eigen::Vector3f& p : samples.points) {
    crop_world.extend(T_world_link * p.cast<double>());
  }
  crop_world.min().array() -= gate + options.crop_margin;
  crop_world.max().array() += gate + options.crop_margin;
  Measure(samples, T_world_link, options, gate, crop_world, summary);
  summary->stop_reason = IcpStopReason::kConverged;
  return Status::Ok();
}

}  // namespace edgefit
