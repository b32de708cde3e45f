#include "solvers/refinement/chain_refinement.h"

#include <ceres/ceres.h>
#include <ceres/crs_matrix.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>

#include "costs/chain_point_cost.h"
#include "costs/robust_loss.h"
#include "solvers/refinement/chain_kinematics.h"
#include "solvers/refinement/surface_patches.h"
#include "solvers/registration/scan_visibility.h"

namespace edgefit {

WeightedIcpOptions ChainRefinementOptions::DefaultIcp() {
  WeightedIcpOptions icp;
  icp.correspondence.max_distance = 0.01;  // starts at the sequential fit
  icp.max_iterations = 30;
  icp.point_to_plane = true;
  return icp;
}

bool ChainRefinementOptions::IsValid(std::string* error) const {
  if (!icp.IsValid(error)) return false;
  if (!(visibility_tolerance > 0.0)) {
    if (error != nullptr) *error = "chain refinement: visibility_tolerance must be positive";
    return false;
  }
  if (!(incidence_cosine >= 0.0 && incidence_cosine <= 1.0)) {
    if (error != nullptr) *error = "chain refinement: incidence_cosine must be in [0, 1]";
    return false;
  }
  if (!(cad_deviation >= 0.0) || !(cad_deviation_patch > 0.0)) {
    if (error != nullptr) {
      *error = "chain refinement: cad_deviation must be >= 0 and cad_deviation_patch positive";
    }
    return false;
  }
  if (icp.point_to_plane && icp.plane_normals != WeightedIcpOptions::PlaneNormals::kModel) {
    if (error != nullptr) *error = "chain refinement: point_to_plane needs model normals";
    return false;
  }
  return true;
}

namespace {

// The samples one iteration uses: those a scanner could see at the current
// pose, posed into the world.
struct PosedSamples {
  std::vector<int> link;                 // per sample
  std::vector<Eigen::Vector3d> p_link;   // link frame
  std::vector<Eigen::Vector3d> n_world;  // posed normal (zero: none)
  std::vector<Eigen::Vector3f> q_world;  // posed point
};

void SelectAndPose(const std::vector<SurfaceSamples>& link_samples,
                   const std::vector<Pose>& T_world_link, const ScanVisibility& visibility,
                   WeightedIcpOptions::Visibility mode, double gate, PosedSamples* out) {
  *out = PosedSamples();
  std::vector<uint8_t> seen;
  for (size_t l = 0; l < link_samples.size(); ++l) {
    const SurfaceSamples& samples = link_samples[l];
    const int count = static_cast<int>(samples.points.size());
    const bool has_normals = samples.normals.size() == samples.points.size();
    const bool test = has_normals && mode != WeightedIcpOptions::Visibility::kAll;
    const Eigen::Matrix3d R = T_world_link[l].linear();
    const Eigen::Vector3d& t = T_world_link[l].translation();
    // The visibility test in parallel, the samples kept in their order:
    // the same selection for any thread count.
    seen.assign(static_cast<size_t>(count), 1);
    if (test) {
#pragma omp parallel for schedule(static)
      for (int i = 0; i < count; ++i) {
        const size_t k = static_cast<size_t>(i);
        const Eigen::Vector3d q = R * samples.points[k].cast<double>() + t;
        const Eigen::Vector3d n = R * samples.normals[k].cast<double>();
        seen[k] =
            visibility.BestView(q, n, gate, mode == WeightedIcpOptions::Visibility::kFacing) ==
            ScanView::kSeen;
      }
    }
    for (size_t i = 0; i < samples.points.size(); ++i) {
      if (!seen[i]) continue;
      const Eigen::Vector3d p = samples.points[i].cast<double>();
      out->link.push_back(static_cast<int>(l));
      out->p_link.push_back(p);
      out->n_world.push_back(has_normals ? Eigen::Vector3d(R * samples.normals[i].cast<double>())
                                         : Eigen::Vector3d::Zero());
      out->q_world.push_back((R * p + t).cast<float>());
    }
  }
}

ceres::Problem::Options ProblemOptions(ceres::EvaluationCallback* callback) {
  ceres::Problem::Options options;
  options.evaluation_callback = callback;
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.disable_all_safety_checks = true;  // blocks are built right here
  return options;
}

// The problem of one iteration (or of the covariance): the parameters
// about (T_world_base, q_full) and one residual block per correspondence;
// `patches`, when given, gets the surface patch of every residual row.
struct ChainProblem {
  ChainProblem(const KinematicModel& model, const Pose& T_world_base,
               const std::vector<double>& q_full, const ScanSet& scans, const PosedSamples& posed,
               const std::vector<Correspondence>& correspondences, bool point_to_plane,
               double incidence_cosine, size_t batch, ceres::LossFunction* loss,
               SurfacePatches* patches = nullptr)
      : q_independent(std::max<size_t>(model.IndependentJoints().size(), 1), 0.0),
        kinematics(&model, T_world_base, q_full, delta_base, q_independent.data()),
        problem(ProblemOptions(&kinematics)) {
    const std::vector<int>& independent = kinematics.independent_joints();
    for (size_t k = 0; k < independent.size(); ++k) {
      q_independent[k] = q_full[static_cast<size_t>(independent[k])];
    }
    // Consecutive correspondences of one link and residual kind share a
    // block of up to `batch` samples.
    std::vector<ChainPoint> points;
    int points_link = -1;
    bool points_plane = false;
    auto flush = [&]() {
      if (points.empty()) return;
      auto* cost = new ChainPointCost(&kinematics, points_link, points_plane, std::move(points));
      points.clear();
      if (independent.empty()) {
        problem.AddResidualBlock(cost, loss, delta_base);
      } else {
        problem.AddResidualBlock(cost, loss, delta_base, q_independent.data());
      }
    };
    for (const Correspondence& m : correspondences) {
      const size_t k = static_cast<size_t>(m.source);
      const int link = posed.link[k];
      const bool plane = point_to_plane && posed.n_world[k].squaredNorm() > 0.0;
      if (link != points_link || plane != points_plane || points.size() >= batch) flush();
      points_link = link;
      points_plane = plane;
      ChainPoint point;
      point.p_link = posed.p_link[k];
      const OrganizedScan& scan = scans.scans[static_cast<size_t>(m.scan)];
      point.q_world = scan.PointWorld(static_cast<size_t>(m.cell));
      if (plane) point.n_world = posed.n_world[k];
      point.w_edge = static_cast<double>(m.weight);
      if (plane && incidence_cosine > 0.0) {
        const Eigen::Vector3d beam = point.q_world - scan.T_world_scanner().translation();
        const double cosine = std::abs(point.n_world.dot(beam)) / std::max(beam.norm(), 1e-9);
        point.w_edge *= std::clamp(cosine / incidence_cosine, 1.0 / 16.0, 1.0);
      }
      points.push_back(point);
      if (patches != nullptr && plane) {
        patches->AddPlaneRow(link, point.p_link, point.n_world, std::sqrt(point.w_edge));
      }
      if (patches != nullptr && !plane) patches->AddPointRows();
    }
    flush();
  }
  bool has_joints() const { return !kinematics.independent_joints().empty(); }

  // The parameter blocks first: the kinematics read them.
  double delta_base[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  std::vector<double> q_independent;  // at least one entry
  ChainKinematics kinematics;         // the problem's evaluation callback
  ceres::Problem problem;
};

// Joint limits as bounds of the q block.
void BoundJoints(const KinematicModel& model, const std::vector<int>& independent, double* q,
                 ceres::Problem* problem) {
  for (size_t k = 0; k < independent.size(); ++k) {
    const Joint& joint = model.joints()[static_cast<size_t>(independent[k])];
    if (!joint.has_limits) continue;
    problem->SetParameterLowerBound(q, static_cast<int>(k), joint.lower);
    problem->SetParameterUpperBound(q, static_cast<int>(k), joint.upper);
  }
}

// Largest distance a corner of any link's sample box moves between two
// sets of link poses.
double MaxDisplacement(const std::vector<Eigen::AlignedBox3d>& boxes_link,
                       const std::vector<Pose>& before, const std::vector<Pose>& after) {
  double max_distance = 0.0;
  for (size_t l = 0; l < boxes_link.size(); ++l) {
    if (boxes_link[l].isEmpty()) continue;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d p =
          boxes_link[l].corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
      max_distance = std::max(max_distance, (after[l] * p - before[l] * p).norm());
    }
  }
  return max_distance;
}

// The standard deviations of *summary from the covariance of the problem
// at its parameters, scaled by the residual variance (cost: its Ceres cost),
// plus the CAD's deviation (cad_deviation [m] per patch; chain_refinement.h).
void Covariance(double cost, double cad_deviation, const SurfacePatches& patches,
                ChainProblem* chain, ChainRefinementSummary* summary) {
  const std::vector<int>& independent = chain->kinematics.independent_joints();
  const size_t parameters = 6 + independent.size();
  const size_t residuals = static_cast<size_t>(chain->problem.NumResiduals());
  if (residuals <= parameters) return;
  summary->sigma = std::sqrt(2.0 * cost / static_cast<double>(residuals - parameters));
  const double variance = summary->sigma * summary->sigma;
  // A joint or base direction the residuals do not pin (a link seen by no
  // scanner, a round base's yaw with its first joint) makes J^T J singular:
  // the parameters in such a direction get no deviation, the others theirs
  // from the pseudo-inverse (surface_patches.h).
  ceres::CRSMatrix jacobian;
  chain->problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr, &jacobian);
  Eigen::MatrixXd H_inverse;
  std::vector<bool> estimable;
  if (!InverseNormalMatrix(jacobian, &H_inverse, &estimable)) return;
  const Eigen::MatrixXd cad = patches.Covariance(jacobian, H_inverse, cad_deviation);
  auto std_of = [&](int column) {
    return estimable[static_cast<size_t>(column)]
               ? std::sqrt(variance * H_inverse(column, column) + cad(column, column))
               : std::nan("");
  };
  for (int i = 0; i < 3; ++i) {
    summary->base_rotation_std[i] = std_of(i);
    summary->base_translation_std[i] = std_of(i + 3);
  }
  for (size_t k = 0; k < independent.size(); ++k) {
    const size_t j = static_cast<size_t>(independent[k]);
    const int column = 6 + static_cast<int>(k);
    summary->joint_std_residuals[j] =
        estimable[static_cast<size_t>(column)] ? std::sqrt(variance * H_inverse(column, column))
                                               : std::nan("");
    summary->joint_std[j] = std_of(column);
  }
  summary->covariance_ok =
      std::all_of(estimable.begin(), estimable.end(), [](bool e) { return e; });
}

}  // namespace

Status RefineChain(const KinematicModel& model, const ScanSet& scans, const CellMask* missing,
                   CorrespondenceSearch* search, const std::vector<SurfaceSamples>& link_samples,
                   const ChainRefinementOptions& options, const ResidualOptions& residuals,
                   Pose* T_world_base, std::vector<double>* q, ChainRefinementSummary* summary) {
  CHECK(search != nullptr && T_world_base != nullptr && q != nullptr && summary != nullptr);
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error) || !residuals.IsValid(&error)) {
    return Status::Error("chain refinement: " + error);
  }
  if (link_samples.size() != model.links().size() || q->size() != model.joints().size()) {
    return Status::Error("chain refinement: samples or joint values do not match the model");
  }
  std::vector<Eigen::AlignedBox3d> boxes_link(link_samples.size());
  size_t total = 0;
  for (size_t l = 0; l < link_samples.size(); ++l) {
    for (const Eigen::Vector3f& p : link_samples[l].points) boxes_link[l].extend(p.cast<double>());
    total += link_samples[l].points.size();
  }
  if (total == 0) return Status::Error("chain refinement: the model has no CAD samples");
  const WeightedIcpOptions& icp = options.icp;
  std::unique_ptr<ceres::LossFunction> loss;
  EDGEFIT_RETURN_IF_ERROR(MakeLoss(residuals.loss, residuals.loss_scale, &loss));
  // Under the trivial loss the samples of a link share blocks of 256
  // residuals (fewer, larger blocks: the same sums, a faster solve); a robust
  // loss needs one block per sample.
  const size_t batch = residuals.loss == "trivial" ? 256 : 1;

  *summary = ChainRefinementSummary();
  summary->joint_std.assign(model.joints().size(), NAN);
  summary->joint_std_residuals.assign(model.joints().size(), NAN);
  const ScanVisibility visibility(&scans, missing);
  Pose T_base = *T_world_base;
  std::vector<double> q_full = *q;
  (void)model.ResolveDependentJoints(&q_full);
  const std::vector<Pose> T_initial = model.ForwardKinematics(q_full, T_base);

  // The crop of the kd-tree: the whole model's box, grown; fixed, so the
  // tree is built once.
  Eigen::AlignedBox3d crop_world;
  for (size_t l = 0; l < boxes_link.size(); ++l) {
    if (boxes_link[l].isEmpty()) continue;
    for (int c = 0; c < 8; ++c) {
      crop_world.extend(T_initial[l] *
                        boxes_link[l].corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
    }
  }
  crop_world.min().array() -= icp.correspondence.max_distance + icp.crop_margin;
  crop_world.max().array() += icp.correspondence.max_distance + icp.crop_margin;

  ceres::Solver::Options solver_options;
  // Tens of thousands of rows and 6 + joints columns: the normal equations
  // (Levenberg-Marquardt's damping on their diagonal) are cheaper than a QR
  // of the Jacobian, for the same estimate to rounding.
  solver_options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = icp.solver_iterations;
  solver_options.num_threads = 1;  // deterministic sums
  solver_options.function_tolerance = 1e-14;
  solver_options.gradient_tolerance = 1e-16;
  solver_options.parameter_tolerance = 1e-14;
  solver_options.logging_type = ceres::SILENT;

  PosedSamples posed;
  std::vector<Correspondence> correspondences;
  CorrespondenceOptions gated = icp.correspondence;
  const double final_gate = std::min(icp.final_gate, icp.correspondence.max_distance);
  summary->stop_reason = options.refine ? IcpStopReason::kMaxIterations : IcpStopReason::kConverged;
  std::vector<std::vector<Pose>> final_gate_estimates;  // a cycle's test
  for (int iteration = 0; options.refine && iteration < icp.max_iterations; ++iteration) {
    const std::vector<Pose> T_world_link = model.ForwardKinematics(q_full, T_base);
    SelectAndPose(link_samples, T_world_link, visibility, icp.visibility,
                  std::min(options.visibility_tolerance, gated.max_distance), &posed);
    search->Find(posed.q_world, crop_world, gated, &correspondences);
    if (correspondences.size() < static_cast<size_t>(icp.min_correspondences)) {
      summary->stop_reason = IcpStopReason::kTooFewCorrespondences;
      break;
    }
    ChainProblem chain(model, T_base, q_full, scans, posed, correspondences, icp.point_to_plane,
                       options.incidence_cosine, batch, loss.get());
    if (chain.has_joints()) {
      BoundJoints(model, chain.kinematics.independent_joints(), chain.q_independent.data(),
                  &chain.problem);
    }
    ceres::Solver::Summary solve;
    ceres::Solve(solver_options, &chain.problem, &solve);
    if (!solve.IsSolutionUsable()) {
      summary->stop_reason = IcpStopReason::kSolverFailed;
      break;
    }
    ++summary->iterations;
    summary->final_cost = solve.final_cost;
    const Pose T_base_next = chain.kinematics.BasePose(chain.delta_base);
    const std::vector<double> q_next = chain.kinematics.FullJoints(chain.q_independent.data());
    const std::vector<Pose> T_world_link_next = model.ForwardKinematics(q_next, T_base_next);
    const double displacement = MaxDisplacement(boxes_link, T_world_link, T_world_link_next);
    T_base = T_base_next;
    q_full = q_next;
    const bool at_final_gate = gated.max_distance <= final_gate;
    gated.max_distance = std::max(final_gate, 0.5 * gated.max_distance);
    // Converged when nothing moved, or when the estimate came back to within
    // convergence_displacement of an earlier one at the final gate: the
    // correspondences flip between two sets, and the iterations would repeat
    // the cycle (on the demo's realistic scan, two estimates 0.02 mm apart
    // for 52 of 60 iterations).
    bool cycled = false;
    for (const std::vector<Pose>& T : final_gate_estimates) {
      cycled = cycled ||
               MaxDisplacement(boxes_link, T, T_world_link_next) <= icp.convergence_displacement;
    }
    if (at_final_gate) final_gate_estimates.push_back(T_world_link_next);
    if (at_final_gate && (displacement <= icp.convergence_displacement || cycled)) {
      summary->stop_reason = IcpStopReason::kConverged;
      break;
    }
  }
  summary->max_displacement =
      MaxDisplacement(boxes_link, T_initial, model.ForwardKinematics(q_full, T_base));

  // The covariance at the estimate, with the final gate.
  if (options.covariance) {
    gated.max_distance = final_gate;
    SelectAndPose(link_samples, model.ForwardKinematics(q_full, T_base), visibility, icp.visibility,
                  std::min(options.visibility_tolerance, final_gate), &posed);
    search->Find(posed.q_world, crop_world, gated, &correspondences);
    SurfacePatches patches(options.cad_deviation_patch);
    ChainProblem chain(model, T_base, q_full, scans, posed, correspondences, icp.point_to_plane,
                       options.incidence_cosine, batch, loss.get(), &patches);
    summary->correspondences = correspondences.size();
    double cost = 0.0;
    chain.problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr);
    if (!options.refine) summary->final_cost = cost;
    Covariance(cost, options.cad_deviation, patches, &chain, summary);
  }

  *T_world_base = T_base;
  *q = q_full;
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
