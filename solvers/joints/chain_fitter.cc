#include "solvers/joints/chain_fitter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "solvers/joints/pair_sweep.h"

namespace edgefit {

WeightedIcpOptions ChainOptions::DefaultJointIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.03;
  options.max_iterations = 60;
  options.point_to_plane = true;
  return options;
}

WeightedIcpOptions ChainOptions::DefaultSubtreeIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.01;  // starts at the chain's fit
  options.max_iterations = 30;
  options.point_to_plane = true;
  return options;
}

bool ChainOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (max_resweeps < 0 || !(resweep_tolerance_rad > 0.0) || !(resweep_tolerance_m > 0.0) ||
      !(resweep_window_rad > 0.0)) {
    return fail("max_resweeps must be >= 0 and the resweep tolerances and window > 0");
  }
  if (!sweep.IsValid(error) || !joint_icp.IsValid(error) || !subtree_icp.IsValid(error)) {
    return false;
  }
  if (!(pinning_revolute > 0.0) || !(pinning_mean_loss >= 0.0)) {
    return fail("pinning_revolute must be > 0 and pinning_mean_loss >= 0");
  }
  if (!(alike_share >= 0.0 && alike_share <= 1.0)) return fail("alike_share must be in [0, 1]");
  if (branch_passes < 1) return fail("branch_passes must be at least 1");
  if (!(branch_settled > 0.0)) return fail("branch_settled must be positive");
  if (!(final_basin_revolute > 0.0) || !(final_basin_prismatic > 0.0)) {
    return fail("final_basin_revolute and final_basin_prismatic must be > 0");
  }
  if (final_basin_rounds < 0) return fail("final_basin_rounds must be >= 0");
  if (!(pair_sweep_step >= 0.0)) return fail("pair_sweep_step must be >= 0");
  if (!(explained_distance >= 0.0)) return fail("explained_distance must be >= 0");
  if (max_passes_after_switch < 0 || !(settle_tolerance_rad > 0.0) || !(settle_tolerance_m > 0.0)) {
    return fail("max_passes_after_switch must be >= 0 and the settle tolerances > 0");
  }
  return true;
}

namespace {

// A joint with more than a turn of range has several values for one pose
// (the sweep keeps the lowest): the one nearest zero when the limits allow.
double NearestZeroTurn(const LinkMotion& motion, double q) {
  if (motion.type != LinkMotion::Type::kRevolute) return q;
  const double nearest_zero = std::remainder(q, 2.0 * M_PI);
  return motion.Clamp(nearest_zero) == nearest_zero ? nearest_zero : q;
}

// Whether a joint moved from `before` to `after` by more than tolerance_rad
// (revolute, modulo a turn) or tolerance_m (prismatic).
bool AnyJointMoved(const KinematicModel& model, const std::vector<double>& before,
                   const std::vector<double>& after, double tolerance_rad, double tolerance_m) {
  for (size_t k = 0; k < after.size(); ++k) {
    const double change = after[k] - before[k];
    const bool moved = model.joints()[k].type == JointType::kPrismatic
                           ? std::abs(change) > tolerance_m
                           : std::abs(std::remainder(change, 2.0 * M_PI)) > tolerance_rad;
    if (moved) return true;
  }
  return false;
}

// The ICP of one body on its joint, under the stage's options. A part
// sliding along its axis (a gun's jaw) shows few faces across the axis:
// from its sweep, point-to-plane residuals leave it free to slide, so it
// first converges with point-to-point ones, slowly (only its tip and
// shoulder pull along the axis): four times the iterations (the bundled
// `home` posture's jaw stopped 10.9 mm off at 60, 0.9 mm at 240). Then it
// settles with the stage's point-to-plane residuals: point-to-point ones
// hold it where its samples sit best on the scan's lattice, and branches
// compared there misjudged right jaws on 4 mm scans.
Status FitOnJoint(WeightedIcp* icp, const SurfaceSamples& samples, const LinkMotion& motion,
                  const WeightedIcpOptions& options, LinkState* state,
                  WeightedIcpSummary* summary) {
  if (motion.type != LinkMotion::Type::kPrismatic) {
    return icp->Fit(samples, motion, options, state, summary);
  }
  WeightedIcpOptions converge = options;
  converge.point_to_plane = false;
  converge.max_iterations *= 4;
  EDGEFIT_RETURN_IF_ERROR(icp->Fit(samples, motion, converge, state, summary));
  if (!options.point_to_plane) return Status::Ok();
  const int iterations = summary->iterations;
  EDGEFIT_RETURN_IF_ERROR(icp->Fit(samples, motion, options, state, summary));
  summary->iterations += iterations;
  return Status::Ok();
}

}  // namespace

ChainFitter::ChainFitter(const KinematicModel& model, const ChainOptions& options,
                         const CadSampleOptions& samples,
                         const std::vector<SurfaceSamples>& icp_samples,
                         const std::vector<SurfaceSamples>& sweep_samples, WeightedIcp* icp,
                         const JointSweep* sweep, std::function<void(const std::string&)> say)
    : model_(model),
      options_(options),
      samples_(samples),
      icp_samples_(icp_samples),
      sweep_samples_(sweep_samples),
      icp_(icp),
      sweep_(sweep),
      say_(std::move(say)) {}

Status ChainFitter::Fit(const Pose& T_world_base, std::vector<double>* q,
                        std::vector<JointRecord>* records, double* loss) {
  EDGEFIT_RETURN_IF_ERROR(FitJoints(T_world_base, q, records));
  if (options_.refine_subtrees) {
    const std::vector<double> swept = *q;
    EDGEFIT_RETURN_IF_ERROR(RefineSubtrees(T_world_base, 0, -1, records, q));
    bool reswept = false;
    EDGEFIT_RETURN_IF_ERROR(ResweepMoved(T_world_base, swept, records, q, &reswept));
    if (reswept) EDGEFIT_RETURN_IF_ERROR(RefineSubtrees(T_world_base, 0, -1, records, q));
    bool switched = false;
    EDGEFIT_RETURN_IF_ERROR(CheckAlternatives(T_world_base, records, q, &switched));
    for (int pass = 0; switched && pass < options_.max_passes_after_switch; ++pass) {
      const std::vector<double> before = *q;
      EDGEFIT_RETURN_IF_ERROR(RefineSubtrees(T_world_base, 0, -1, records, q));
      switched = AnyJointMoved(model_, before, *q, options_.settle_tolerance_rad,
                               options_.settle_tolerance_m);
    }
  }
  size_t samples = 0;
  *loss = SubtreeLoss(T_world_base, *q, model_.root_link(), &samples);
  return Status::Ok();
}

Status ChainFitter::FitJoints(const Pose& T_world_base, std::vector<double>* q,
                              std::vector<JointRecord>* records) {
  *q = model_.ZeroJoints();
  (void)model_.ResolveDependentJoints(q);  // best effort until every joint is fitted
  records->clear();
  for (const int joint : model_.joint_order()) {
    const Joint& j = model_.joints()[static_cast<size_t>(joint)];
    if (!j.IsIndependent()) continue;
    JointRecord record;
    record.joint = joint;
    EDGEFIT_RETURN_IF_ERROR(FitJoint(T_world_base, q, &record));
    records->push_back(record);
  }
  // A symmetric body was swept with its children at values not fitted
  // yet: it and every joint after it are swept again near their values
  // (ChainOptions::max_resweeps) until none moves (a round wrist, then
  // the flange and the gun settle together).
  const auto first_symmetric = std::find_if(records->begin(), records->end(),
                                            [](const JointRecord& r) { return r.symmetric; });
  for (int pass = 0; pass < options_.max_resweeps && first_symmetric != records->end(); ++pass) {
    const std::vector<double> before = *q;
    for (auto it = first_symmetric; it != records->end(); ++it) {
      EDGEFIT_RETURN_IF_ERROR(FitJoint(T_world_base, q, &*it, /*resweep=*/true));
    }
    if (!AnyJointMoved(model_, before, *q, options_.resweep_tolerance_rad,
                       options_.resweep_tolerance_m)) {
      break;
    }
  }
  return Status::Ok();
}

Status ChainFitter::ResweepMoved(const Pose& T_world_base, const std::vector<double>& swept,
                                 std::vector<JointRecord>* records, std::vector<double>* q,
                                 bool* reswept) {
  *reswept = false;
  const std::vector<Pose> T_swept = model_.ForwardKinematics(swept, T_world_base);
  for (JointRecord& record : *records) {
    const Joint& j = model_.joints()[static_cast<size_t>(record.joint)];
    const size_t parent = static_cast<size_t>(j.parent_link);
    if (!LinkMoved(T_swept[parent], model_.ForwardKinematics(*q, T_world_base)[parent])) continue;
    say_("chain: " + j.name + " again: the subtree pass moved the link it hangs from");
    EDGEFIT_RETURN_IF_ERROR(FitJoint(T_world_base, q, &record, /*resweep=*/true));
    *reswept = true;
  }
  return Status::Ok();
}

Status ChainFitter::RefineSubtrees(const Pose& T_world_base, size_t first, int only_below,
                                   std::vector<JointRecord>* records, std::vector<double>* q) {
  const std::vector<bool> in_scope = SubtreeMask(only_below);
  for (size_t i = first; i < records->size(); ++i) {
    const JointRecord& record = (*records)[i];
    const Joint& j = model_.joints()[static_cast<size_t>(record.joint)];
    if (!in_scope[static_cast<size_t>(j.child_link)]) continue;
    const std::vector<Pose> T_world_link = model_.ForwardKinematics(*q, T_world_base);
    const LinkMotion motion =
        LinkMotion::FromJoint(j, T_world_link[static_cast<size_t>(j.parent_link)]);
    const Body subtree = MakeSubtree(model_, j.child_link, record.joint, T_world_link);
    const SurfaceSamples subtree_icp =
        BodySamples(subtree, icp_samples_, samples_.max_subtree_icp_samples);
    if (subtree_icp.points.empty()) continue;
    const double before = (*q)[static_cast<size_t>(record.joint)];
    LinkState state;
    state.q = before;
    WeightedIcpSummary summary;
    EDGEFIT_RETURN_IF_ERROR(
        FitOnJoint(icp_, subtree_icp, motion, options_.subtree_icp, &state, &summary));
    (*q)[static_cast<size_t>(record.joint)] = NearestZeroTurn(motion, state.q);
    (void)model_.ResolveDependentJoints(q);
    char line[320];
    std::snprintf(line, sizeof(line), "subtrees: %s %.5f -> %.5f, %s", j.name.c_str(), before,
                  (*q)[static_cast<size_t>(record.joint)], summary.BriefReport().c_str());
    say_(line);
  }
  return Status::Ok();
}

void ChainFitter::AddChildren(int joint, const std::vector<Pose>& T_world_link, SurfaceSamples* icp,
                              SurfaceSamples* sweep) const {
  const Joint& j = model_.joints()[static_cast<size_t>(joint)];
  const Body body = MakeBody(model_, j.child_link, joint);
  for (const int link : body.links) {
    for (const int child_joint : model_.links()[static_cast<size_t>(link)].child_joints) {
      const Joint& c = model_.joints()[static_cast<size_t>(child_joint)];
      if (c.type == JointType::kFixed) continue;
      const Body child = MakeBody(model_, c.child_link, child_joint);
      const Pose T_body_child = T_world_link[static_cast<size_t>(j.child_link)].inverse() *
                                T_world_link[static_cast<size_t>(c.child_link)];
      SurfaceSamples child_sweep, child_icp;
      AppendBodySamples(child, sweep_samples_, Pose::Identity(), &child_sweep);
      if (icp != nullptr) AppendBodySamples(child, icp_samples_, Pose::Identity(), &child_icp);
      if (c.type != JointType::kPrismatic) {
        SurfaceSamples round_sweep = RoundPart(child_sweep, c.axis);
        if (static_cast<double>(round_sweep.size()) >=
            options_.min_round_child_share * static_cast<double>(child_sweep.size())) {
          child_sweep = std::move(round_sweep);
          if (icp != nullptr) child_icp = RoundPart(child_icp, c.axis);
        }
      }
      AppendPosedSamples(child_sweep, T_body_child, sweep);
      if (icp != nullptr) AppendPosedSamples(child_icp, T_body_child, icp);
    }
  }
}

Status ChainFitter::FitJoint(const Pose& T_world_base, std::vector<double>* q, JointRecord* record,
                             bool resweep) {
  const Joint& j = model_.joints()[static_cast<size_t>(record->joint)];
  const std::vector<Pose> T_world_link = model_.ForwardKinematics(*q, T_world_base);
  const LinkMotion motion =
      LinkMotion::FromJoint(j, T_world_link[static_cast<size_t>(j.parent_link)]);
  const Body body = MakeBody(model_, j.child_link, record->joint);
  SurfaceSamples body_icp, body_sweep;
  AppendBodySamples(body, icp_samples_, Pose::Identity(), &body_icp);
  AppendBodySamples(body, sweep_samples_, Pose::Identity(), &body_sweep);
  // A symmetric (or empty) body cannot fix its angle: the sweep and the
  // ICP add its children at their current values (Sec. 5.2.1). So does a
  // body whose own sweep finds a second value nearly as good (a round
  // wrist with a small boss: the ring test passes it, the scan cannot).
  const bool revolute = motion.type == LinkMotion::Type::kRevolute;
  const bool local = resweep && revolute;
  if (!local) {
    record->symmetric =
        body_icp.points.empty() ||
        (revolute && IsRotationallySymmetric(body_icp, j.axis, options_.symmetric_share));
  }
  auto add_children = [&] { AddChildren(record->joint, T_world_link, &body_icp, &body_sweep); };
  if (record->symmetric) add_children();
  ThinSamples(samples_.max_icp_samples, &body_icp);
  ThinSamples(samples_.max_sweep_samples, &body_sweep);
  if (body_icp.points.empty()) {
    return Status::Error("robot fit: joint '" + j.name + "' moves no mesh");
  }
  auto sweep = [&] {
    if (local) {
      LinkMotion window = motion;
      const double q0 = (*q)[static_cast<size_t>(record->joint)];
      window.lower = q0 - options_.resweep_window_rad;
      window.upper = q0 + options_.resweep_window_rad;
      if (motion.has_limits) {
        window.lower = std::max(window.lower, motion.lower);
        window.upper = std::min(window.upper, motion.upper);
      }
      window.has_limits = true;
      JointSweepSummary summary;
      EDGEFIT_RETURN_IF_ERROR(sweep_->Sweep(body_sweep, window, options_.sweep, &summary));
      record->sweep.q = summary.q;
      record->sweep.loss = summary.loss;
      record->sweep.seconds = summary.seconds;
      return Status::Ok();
    }
    EDGEFIT_RETURN_IF_ERROR(sweep_->Sweep(body_sweep, motion, options_.sweep, &record->sweep));
    record->sweep_margin = record->sweep.has_runner_up
                               ? (record->sweep.runner_up_loss - record->sweep.loss) /
                                     static_cast<double>(body_sweep.points.size())
                               : std::numeric_limits<double>::infinity();
    return Status::Ok();
  };
  EDGEFIT_RETURN_IF_ERROR(sweep());
  if (!record->symmetric && revolute && record->sweep_margin < options_.flat_sweep_loss) {
    record->symmetric = true;
    add_children();
    ThinSamples(samples_.max_icp_samples, &body_icp);
    ThinSamples(samples_.max_sweep_samples, &body_sweep);
    EDGEFIT_RETURN_IF_ERROR(sweep());
  }
  if (!local) {
    record->full_sweep = revolute && !record->symmetric;
    record->full_sweep_q = record->sweep.q;
    record->T_world_parent_swept = T_world_link[static_cast<size_t>(j.parent_link)];
  }
  if (record->symmetric && revolute && !local && options_.pair_sweep_step > 0.0 &&
      record->sweep_margin < options_.flat_sweep_loss) {
    const int bend = BendBelow(model_, record->joint, body.links, *q);
    if (bend >= 0) {
      EDGEFIT_RETURN_IF_ERROR(SweepWithTheBend(T_world_base, body, bend, q, record, &body_icp));
    }
  }
  LinkState state;
  state.q = record->sweep.q;
  WeightedIcpSummary summary;
  EDGEFIT_RETURN_IF_ERROR(FitOnJoint(icp_, body_icp, motion, options_.joint_icp, &state, &summary));
  record->icp_iterations = summary.iterations;
  (*q)[static_cast<size_t>(record->joint)] = NearestZeroTurn(motion, state.q);
  (void)model_.ResolveDependentJoints(q);
  char line[320];
  std::snprintf(line, sizeof(line),
                "chain: %s = %.5f (sweep %.4f in %.2f s%s; runner-up %.3f mm/sample worse), %s",
                j.name.c_str(), (*q)[static_cast<size_t>(record->joint)], record->sweep.q,
                record->sweep.seconds, record->symmetric ? ", symmetric: children added" : "",
                1e3 * record->sweep_margin, summary.BriefReport().c_str());
  say_(line);
  return Status::Ok();
}

Status ChainFitter::SweepWithTheBend(const Pose& T_world_base, const Body& body, int bend,
                                     std::vector<double>* q, JointRecord* record,
                                     SurfaceSamples* body_icp) const {
  PairSweepSummary pair;
  EDGEFIT_RETURN_IF_ERROR(SweepPair(model_, *sweep_, options_.sweep, T_world_base, *q, body, bend,
                                    sweep_samples_, samples_.max_sweep_samples,
                                    options_.pair_sweep_step, &pair));
  record->sweep.q = pair.q;
  (*q)[static_cast<size_t>(bend)] = pair.q_child;
  // The joint's ICP carries the bend's whole body at its swept value.
  const Joint& c = model_.joints()[static_cast<size_t>(bend)];
  const std::vector<Pose> T = model_.ForwardKinematics(*q, T_world_base);
  *body_icp = SurfaceSamples();
  AppendBodySamples(body, icp_samples_, Pose::Identity(), body_icp);
  AppendBodySamples(
      MakeBody(model_, c.child_link, bend), icp_samples_,
      T[static_cast<size_t>(body.link)].inverse() * T[static_cast<size_t>(c.child_link)], body_icp);
  ThinSamples(samples_.max_icp_samples, body_icp);
  char line[240];
  std::snprintf(line, sizeof(line),
                "chain: %s flat with its children: swept with %s, %.4f and %.4f (%d pairs, %.2f s)",
                model_.joints()[static_cast<size_t>(record->joint)].name.c_str(), c.name.c_str(),
                pair.q, pair.q_child, pair.evaluations, pair.seconds);
  say_(line);
  return Status::Ok();
}

double ChainFitter::SubtreeLoss(const Pose& T_world_base, const std::vector<double>& q, int link,
                                size_t* samples) const {
  return LinksLoss(T_world_base, q, SubtreeMask(link), samples);
}

double ChainFitter::LinksLoss(const Pose& T_world_base, const std::vector<double>& q,
                              const std::vector<bool>& in, size_t* samples,
                              const JointSweep* sweep) const {
  if (sweep == nullptr) sweep = sweep_;
  const std::vector<Pose> T_world_link = model_.ForwardKinematics(q, T_world_base);
  double loss = 0.0;
  *samples = 0;
  for (size_t l = 0; l < in.size(); ++l) {
    const SurfaceSamples& s = sweep_samples_[l];
    if (!in[l] || s.points.empty()) continue;
    loss += sweep->LossAt(s, T_world_link[l], options_.sweep);
    *samples += s.size();
  }
  return loss;
}

std::vector<bool> ChainFitter::SubtreeMask(int link) const {
  std::vector<bool> in(model_.links().size(), link < 0);
  if (link >= 0) {
    for (const int l : SubtreeLinks(model_, link)) in[static_cast<size_t>(l)] = true;
  }
  return in;
}

}  // namespace edgefit
