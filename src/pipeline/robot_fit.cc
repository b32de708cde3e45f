#include "edgefit/pipeline/robot_fit.h"

#include <glog/logging.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "edgefit/correspondence/correspondence_search.h"
#include "edgefit/model/surface_sampler.h"
#include "robot_bodies.h"
#include "solvers/scan_visibility.h"

namespace edgefit {

WeightedIcpOptions RobotFitOptions::DefaultBaseIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.05;  // the rough stage's error
  options.max_iterations = 60;
  return options;
}

WeightedIcpOptions RobotFitOptions::DefaultJointIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.03;
  options.max_iterations = 60;
  return options;
}

bool RobotFitOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!edges.IsValid(error)) return false;
  if (!(icp_spacing > 0.0) || !(sweep_spacing > 0.0)) return fail("sample spacings must be > 0");
  if (max_icp_samples < 100 || max_sweep_samples < 100) return fail("sample budgets must be >= 100");
  if (!base_rough.IsValid(error) || !base_icp.IsValid(error) || !sweep.IsValid(error) ||
      !joint_icp.IsValid(error)) {
    return false;
  }
  if (!(min_inlier_share >= 0.0 && min_inlier_share <= 1.0)) {
    return fail("min_inlier_share must be in [0, 1]");
  }
  if (!(max_rms > 0.0)) return fail("max_rms must be > 0");
  return true;
}

namespace {

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

BodyQuality Quality(const KinematicModel& model, const Body& body, const SurfaceSamples& samples,
                    const WeightedIcpSummary& summary, const RobotFitOptions& options) {
  BodyQuality quality;
  quality.link = model.links()[static_cast<size_t>(body.link)].name;
  if (body.joint >= 0) quality.joint = model.joints()[static_cast<size_t>(body.joint)].name;
  quality.samples = samples.size();
  quality.visible = summary.visible_points;
  quality.inlier_share = summary.inlier_share;
  quality.rms = summary.rms;
  quality.icp_iterations = summary.iterations;
  quality.ok = summary.inlier_share >= options.min_inlier_share && summary.rms <= options.max_rms;
  return quality;
}

}  // namespace

Status FitRobot(const KinematicModel& model, const ScanSet& scans, const RobotFitOptions& options,
                const ProgressFn& progress, RobotFitResult* result) {
  CHECK(result != nullptr);
  const auto start = std::chrono::steady_clock::now();
  auto say = [&progress](const std::string& line) {
    if (progress) progress(line);
  };
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("robot fit: " + error);
  if (model.root_link() < 0) return Status::Error("robot fit: the model has no root link");
  *result = RobotFitResult();

  // CAD samples: dense for the ICP stages, sparse for the sweeps.
  SamplingOptions sampling;
  sampling.seed = options.seed;
  sampling.spacing = options.icp_spacing;
  const std::vector<SurfaceSamples> icp_samples = SampleModelSurfaces(model, sampling);
  sampling.spacing = options.sweep_spacing;
  const std::vector<SurfaceSamples> sweep_samples = SampleModelSurfaces(model, sampling);

  // Sec. 4: edge weights and normals.
  auto stage = std::chrono::steady_clock::now();
  say("edges: detecting on " + std::to_string(scans.TotalValid()) + " points");
  EdgeDetectionResult edges;
  EDGEFIT_RETURN_IF_ERROR(DetectEdges(scans, options.edges, &edges));
  result->timings.edges = Since(stage);

  const CellWeights* weights = options.uniform_weights ? nullptr : &edges.w_edge;
  CorrespondenceSearch search(&scans, weights);
  const ScanVisibility visibility(&scans);
  WeightedIcp icp(&scans, &search, &edges.normals);
  JointSweep sweep(&search, &visibility);
  WeightedIcpOptions base_icp = options.base_icp, joint_icp = options.joint_icp;
  JointSweepOptions sweep_options = options.sweep;
  base_icp.uniform_weights = joint_icp.uniform_weights = sweep_options.uniform_weights =
      options.uniform_weights;

  // Sec. 5.1: the base body.
  const Body base = MakeBody(model, model.root_link(), -1);
  SurfaceSamples base_samples;
  AppendBodySamples(base, icp_samples, Pose::Identity(), &base_samples);
  ThinSamples(options.max_icp_samples, &base_samples);
  if (base_samples.points.empty()) {
    return Status::Error("robot fit: the base link '" +
                         model.links()[static_cast<size_t>(base.link)].name +
                         "' has no mesh to register");
  }
  stage = std::chrono::steady_clock::now();
  Pose T_world_base = options.T_world_base_initial;
  if (!options.has_initial_base) {
    TriangleMesh base_mesh;
    for (size_t k = 0; k < base.links.size(); ++k) {
      base_mesh.Append(model.links()[static_cast<size_t>(base.links[k])].mesh, base.T_body_link[k]);
    }
    BaseRoughOptions rough = options.base_rough;
    rough.seed = options.seed;
    say("base: rough registration (cross-section corners, RANSAC)");
    const Status status = FitBaseRough(scans, edges.normals, base_mesh, rough, &result->base_rough);
    if (!status.ok()) {
      result->ok = false;
      result->message = status.message();
      result->q = model.ZeroJoints();
      result->timings.total = Since(start);
      return Status::Ok();
    }
    // The 2D score cannot tell a symmetric base's turns apart; the 3D
    // Eq. (9) loss with the scan's visibility can (parts seen, or space
    // seen empty, on one side).
    SurfaceSamples base_sweep;
    AppendBodySamples(base, sweep_samples, Pose::Identity(), &base_sweep);
    ThinSamples(options.max_sweep_samples, &base_sweep);
    double best_loss = std::numeric_limits<double>::infinity();
    for (const Pose& candidate : result->base_rough.candidates) {
      const double loss = sweep.LossAt(base_sweep, candidate, sweep_options);
      if (loss < best_loss) {
        best_loss = loss;
        T_world_base = candidate;
      }
    }
    result->base_rough.T_world_base = T_world_base;
    result->timings.base_rough = Since(stage);
  }
  stage = std::chrono::steady_clock::now();
  say("base: precise weighted ICP");
  LinkState base_state;
  base_state.T_world_link = T_world_base;
  WeightedIcpSummary summary;
  EDGEFIT_RETURN_IF_ERROR(icp.Fit(base_samples, LinkMotion::Free(), base_icp, &base_state, &summary));
  result->T_world_base = base_state.T_world_link;
  result->bodies.push_back(Quality(model, base, base_samples, summary, options));
  result->timings.base_precise = Since(stage);

  // Sec. 5.2-5.3: the joints, parents first.
  stage = std::chrono::steady_clock::now();
  std::vector<double> q = model.ZeroJoints();
  (void)model.ResolveDependentJoints(&q);  // best effort until every joint is fitted
  for (const int joint : model.joint_order()) {
    const Joint& j = model.joints()[static_cast<size_t>(joint)];
    if (!j.IsIndependent()) continue;
    const std::vector<Pose> T_world_link = model.ForwardKinematics(q, result->T_world_base);
    const LinkMotion motion = LinkMotion::FromJoint(j, T_world_link[static_cast<size_t>(j.parent_link)]);
    const Body body = MakeBody(model, j.child_link, joint);
    SurfaceSamples body_icp, body_sweep;
    AppendBodySamples(body, icp_samples, Pose::Identity(), &body_icp);
    AppendBodySamples(body, sweep_samples, Pose::Identity(), &body_sweep);
    // A symmetric (or empty) body cannot fix its angle: the sweep adds its
    // children at their current values (Sec. 5.2.1).
    const bool symmetric = body_icp.points.empty() ||
                           (motion.type == LinkMotion::Type::kRevolute &&
                            IsRotationallySymmetric(body_icp, j.axis, options.symmetric_share));
    if (symmetric) {
      for (const int link : body.links) {
        for (const int child_joint : model.links()[static_cast<size_t>(link)].child_joints) {
          const Joint& c = model.joints()[static_cast<size_t>(child_joint)];
          if (c.type == JointType::kFixed) continue;
          const Body child = MakeBody(model, c.child_link, child_joint);
          const Pose T_body_child = T_world_link[static_cast<size_t>(j.child_link)].inverse() *
                                    T_world_link[static_cast<size_t>(c.child_link)];
          AppendBodySamples(child, sweep_samples, T_body_child, &body_sweep);
          if (body_icp.points.empty()) AppendBodySamples(child, icp_samples, T_body_child, &body_icp);
        }
      }
    }
    ThinSamples(options.max_icp_samples, &body_icp);
    ThinSamples(options.max_sweep_samples, &body_sweep);
    if (body_icp.points.empty()) {
      return Status::Error("robot fit: joint '" + j.name + "' moves no mesh");
    }
    JointSweepSummary sweep_summary;
    EDGEFIT_RETURN_IF_ERROR(sweep.Sweep(body_sweep, motion, sweep_options, &sweep_summary));
    LinkState state;
    state.q = sweep_summary.q;
    EDGEFIT_RETURN_IF_ERROR(icp.Fit(body_icp, motion, joint_icp, &state, &summary));
    // A joint with more than a turn of range has several values for one
    // pose (the sweep keeps the lowest): report the one nearest zero when
    // the limits allow it.
    if (motion.type == LinkMotion::Type::kRevolute) {
      const double nearest_zero = std::remainder(state.q, 2.0 * M_PI);
      if (motion.Clamp(nearest_zero) == nearest_zero) state.q = nearest_zero;
    }
    q[static_cast<size_t>(joint)] = state.q;
    (void)model.ResolveDependentJoints(&q);
    BodyQuality quality = Quality(model, body, body_icp, summary, options);
    quality.symmetric = symmetric;
    quality.sweep_value = sweep_summary.q;
    result->bodies.push_back(quality);
    char line[256];
    std::snprintf(line, sizeof(line), "chain: %s = %.5f (sweep %.4f%s), %s", j.name.c_str(),
                  state.q, sweep_summary.q, symmetric ? ", symmetric: child's loss added" : "",
                  summary.BriefReport().c_str());
    say(line);
  }
  const Status resolved = model.ResolveDependentJoints(&q);
  result->q = q;
  result->timings.chain = Since(stage);
  result->timings.total = Since(start);

  result->ok = resolved.ok();
  if (!resolved.ok()) result->message = resolved.message();
  for (const BodyQuality& b : result->bodies) {
    if (!b.ok && result->ok) {
      result->ok = false;
      char line[256];
      std::snprintf(line, sizeof(line),
                    "%s does not match the scan: %.0f%% of its visible samples within %.1f mm "
                    "(need %.0f%%), RMS %.2f mm",
                    b.link.c_str(), 100.0 * b.inlier_share, 1e3 * options.joint_icp.final_gate,
                    100.0 * options.min_inlier_share, 1e3 * b.rms);
      result->message = line;
    }
  }
  return Status::Ok();
}

}  // namespace edgefit
