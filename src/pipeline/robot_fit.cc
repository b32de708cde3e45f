#include "edgefit/pipeline/robot_fit.h"

#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "edgefit/correspondence/correspondence_search.h"
#include "edgefit/model/surface_sampler.h"
#include "robot_bodies.h"
#include "solvers/scan_visibility.h"

namespace edgefit {

WeightedIcpOptions RobotFitOptions::DefaultBaseIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.05;  // the rough stage's error
  options.max_iterations = 60;
  options.point_to_plane = true;
  return options;
}

WeightedIcpOptions RobotFitOptions::DefaultJointIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.03;
  options.max_iterations = 60;
  options.point_to_plane = true;
  return options;
}

WeightedIcpOptions RobotFitOptions::DefaultSubtreeIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.01;  // starts at the chain's fit
  options.max_iterations = 30;
  options.point_to_plane = true;
  return options;
}

bool RobotFitOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!edges.IsValid(error)) return false;
  if (!(icp_spacing > 0.0) || !(sweep_spacing > 0.0)) return fail("sample spacings must be > 0");
  if (max_resweeps < 0 || !(resweep_tolerance_rad > 0.0) || !(resweep_tolerance_m > 0.0) ||
      !(resweep_window_rad > 0.0)) {
    return fail("max_resweeps must be >= 0 and the resweep tolerances and window > 0");
  }
  if (!(slide_elongation > 0.0) || !(slide_step > 0.0)) {
    return fail("slide_elongation and slide_step must be > 0");
  }
  if (base_alternatives < 0 || !(base_alternative_loss >= 0.0)) {
    return fail("base_alternatives and base_alternative_loss must be >= 0");
  }
  if (max_icp_samples < 100 || max_sweep_samples < 100 || max_subtree_icp_samples < 100 ||
      max_chain_samples < 100)
    return fail("sample budgets must be >= 100");
  if (!base_rough.IsValid(error) || !conveyance_base_rough.IsValid(error) ||
      !base_icp.IsValid(error) || !sweep.IsValid(error) || !joint_icp.IsValid(error) ||
      !subtree_icp.IsValid(error) || !chain_refinement.IsValid(error)) {
    return false;
  }
  if (!(min_inlier_share >= 0.0 && min_inlier_share <= 1.0)) {
    return fail("min_inlier_share must be in [0, 1]");
  }
  if (!(max_rms > 0.0)) return fail("max_rms must be > 0");
  if (!(pinning_revolute > 0.0) || !(pinning_mean_loss >= 0.0)) {
    return fail("pinning_revolute must be > 0 and pinning_mean_loss >= 0");
  }
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

// Two rough base poses are different answers when they differ by more than
// 5 degrees in yaw or 5 cm in position (the precise ICP's reach).
bool IsDistinctPose(const Pose& a, const Pose& b) {
  const Pose d = a.inverse() * b;
  return Eigen::AngleAxisd(d.linear()).angle() > 5.0 * M_PI / 180.0 ||
         d.translation().norm() > 0.05;
}

// T_world_base moved along its own axis `axis_base` by up to +-range [m]
// to the lowest loss: a coarse pass at `step`, then step / 5 around it.
Pose SlideAlong(const Pose& T_world_base, const Eigen::Vector3d& axis_base, double range,
                double step, const BasePoseLoss& loss) {
  const Eigen::Vector3d axis_world = T_world_base.linear() * axis_base;
  auto moved = [&](double d) {
    Pose T = T_world_base;
    T.translation() += d * axis_world;
    return T;
  };
  auto best_of = [&](double from, double to, double by) {
    const int n = static_cast<int>(std::ceil((to - from) / by));
    std::vector<double> losses(static_cast<size_t>(n) + 1);
#pragma omp parallel for schedule(dynamic, 8)
    for (int k = 0; k <= n; ++k) losses[static_cast<size_t>(k)] = loss(moved(from + k * by));
    const size_t best =
        static_cast<size_t>(std::min_element(losses.begin(), losses.end()) - losses.begin());
    return from + static_cast<double>(best) * by;
  };
  const double coarse = best_of(-range, range, step);
  return moved(best_of(coarse - step, coarse + step, 0.2 * step));
}

// What the chain pass found for one independent joint.
struct JointRecord {
  int joint = -1;
  bool symmetric = false;  // the sweep and ICP carried the children
  JointSweepSummary sweep;
  double sweep_margin = std::numeric_limits<double>::infinity();  // runner-up, per sample [m]
  int icp_iterations = 0;
  // ChainFitter::CheckAlternatives (RobotFitOptions::ambiguity_*).
  bool ambiguous = false;
  double alternative = 0.0;
  double margin = std::numeric_limits<double>::infinity();
};

// Sec. 5.2-5.3 over the joints of one model, parents first.
class ChainFitter {
 public:
  ChainFitter(const KinematicModel& model, const RobotFitOptions& options,
              const std::vector<SurfaceSamples>& icp_samples,
              const std::vector<SurfaceSamples>& sweep_samples, WeightedIcp* icp,
              const JointSweep* sweep, std::function<void(const std::string&)> say)
      : model_(model),
        options_(options),
        icp_samples_(icp_samples),
        sweep_samples_(sweep_samples),
        icp_(icp),
        sweep_(sweep),
        say_(std::move(say)),
        joint_icp_(options.joint_icp),
        subtree_icp_(options.subtree_icp),
        sweep_options_(options.sweep) {
    joint_icp_.uniform_weights = subtree_icp_.uniform_weights = sweep_options_.uniform_weights =
        options.uniform_weights;
  }

  // The chain pass: per joint the Eq. (9) sweep and the joint ICP; *q gets
  // every joint (dependent ones resolved as far as possible).
  Status FitJoints(const Pose& T_world_base, std::vector<double>* q,
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
    // (RobotFitOptions::max_resweeps) until none moves (a round wrist, then
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

  // Extension of Sec. 5.2.2: each joint once more, parents first, with all
  // it carries (its subtree at the fitted values): a nearly round link (a
  // wrist) fits its angle poorly alone; its children's lever fixes it.
  // Only the joints of records from `first` on that lie in `only_below`'s
  // subtree (a link; -1: all).
  Status RefineSubtrees(const Pose& T_world_base, size_t first, int only_below,
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
      SurfaceSamples subtree_icp;
      AppendBodySamples(subtree, icp_samples_, Pose::Identity(), &subtree_icp);
      ThinSamples(options_.max_subtree_icp_samples, &subtree_icp);
      if (subtree_icp.points.empty()) continue;
      const double before = (*q)[static_cast<size_t>(record.joint)];
      LinkState state;
      state.q = before;
      WeightedIcpSummary summary;
      EDGEFIT_RETURN_IF_ERROR(
          icp_->Fit(subtree_icp, motion, ForMotion(subtree_icp_, motion), &state, &summary));
      (*q)[static_cast<size_t>(record.joint)] = NearestZeroTurn(motion, state.q);
      (void)model_.ResolveDependentJoints(q);
      char line[320];
      std::snprintf(line, sizeof(line), "subtrees: %s %.5f -> %.5f, %s", j.name.c_str(), before,
                    (*q)[static_cast<size_t>(record.joint)], summary.BriefReport().c_str());
      say_(line);
    }
    return Status::Ok();
  }

  // A joint whose sweep found a runner-up nearly as good (a wrist turned
  // half a turn, a bare flange) is fitted again from the runner-up, with
  // every joint below it fitted anew (a wrist flip changes them too), and
  // the subtree's Eq. (9) losses are compared: the lower wins; a margin
  // below RobotFitOptions::ambiguity_mean_loss per sample makes the joint
  // ambiguous. *switched: some joint took its other value (the joints
  // above it were refined with the old subtree: refine them again).
  Status CheckAlternatives(const Pose& T_world_base, std::vector<JointRecord>* records,
                           std::vector<double>* q, bool* switched) {
    *switched = false;
    for (size_t i = 0; i < records->size(); ++i) {
      const JointRecord& record = (*records)[i];
      if (!(record.sweep_margin < options_.ambiguity_check_loss)) continue;
      const Joint& j = model_.joints()[static_cast<size_t>(record.joint)];
      std::vector<double> q_other = *q;
      std::vector<JointRecord> other_records = *records;
      q_other[static_cast<size_t>(record.joint)] = record.sweep.runner_up_q;
      (void)model_.ResolveDependentJoints(&q_other);
      const std::vector<bool> below = SubtreeMask(j.child_link);
      for (size_t k = i + 1; k < records->size(); ++k) {
        const int link = model_.joints()[static_cast<size_t>((*records)[k].joint)].child_link;
        if (below[static_cast<size_t>(link)]) {
          EDGEFIT_RETURN_IF_ERROR(FitJoint(T_world_base, &q_other, &other_records[k]));
        }
      }
      EDGEFIT_RETURN_IF_ERROR(
          RefineSubtrees(T_world_base, i, j.child_link, &other_records, &q_other));
      const size_t jj = static_cast<size_t>(record.joint);
      const double separation = j.type == JointType::kPrismatic
                                    ? std::abs(q_other[jj] - (*q)[jj])
                                    : std::abs(std::remainder(q_other[jj] - (*q)[jj], 2.0 * M_PI));
      const double distinct = j.type == JointType::kPrismatic ? sweep_options_.distinct_prismatic
                                                              : sweep_options_.distinct_revolute;
      if (separation < 0.5 * distinct) continue;  // back in the same basin: no alternative
      size_t samples = 0;
      const double loss = SubtreeLoss(T_world_base, *q, j.child_link, &samples);
      const double other_loss = SubtreeLoss(T_world_base, q_other, j.child_link, &samples);
      const bool take_other = other_loss < loss;
      const double alternative = take_other ? (*q)[jj] : q_other[jj];
      if (take_other) {
        *switched = true;
        *q = std::move(q_other);
        *records = std::move(other_records);
      }
      JointRecord& checked = (*records)[i];
      checked.alternative = alternative;
      checked.margin =
          std::abs(other_loss - loss) / static_cast<double>(std::max<size_t>(samples, 1));
      checked.ambiguous = checked.margin < options_.ambiguity_mean_loss;
      char line[320];
      std::snprintf(line, sizeof(line),
                    "alternatives: %s = %.5f, other value %.5f is %.3f mm/sample worse%s%s",
                    j.name.c_str(), (*q)[jj], alternative, 1e3 * checked.margin,
                    take_other ? " (the first fit's value)" : "",
                    checked.ambiguous ? ": AMBIGUOUS" : "");
      say_(line);
    }
    return Status::Ok();
  }

  // Whether the scan pins each revolute joint down: its subtree's Eq. (9)
  // loss at the joint's value moved by the failure bound (RobotFitOptions::
  // pinning_revolute) must rise by at least pinning_mean_loss per sample,
  // on average over the two sides within the limits; else the joint is
  // ambiguous with the moved value as its alternative (a round link that
  // nothing below it tells).
  void CheckPinning(const Pose& T_world_base, std::vector<JointRecord>* records,
                    const std::vector<double>& q) const {
    for (JointRecord& record : *records) {
      const Joint& j = model_.joints()[static_cast<size_t>(record.joint)];
      if (j.type == JointType::kPrismatic) continue;  // see RobotFitOptions::pinning_mean_loss
      const size_t jj = static_cast<size_t>(record.joint);
      const double step = options_.pinning_revolute;
      size_t samples = 0;
      const double loss = SubtreeLoss(T_world_base, q, j.child_link, &samples);
      if (samples == 0) continue;
      // The mean rise of the two sides: a tilted valley (the ICP's value a
      // little off the Eq. 9 minimum) still rises on average; a flat one
      // does not.
      double rise_sum = 0.0, lowest = std::numeric_limits<double>::infinity();
      double moved_to = q[jj];
      int sides = 0;
      for (const double sign : {-1.0, 1.0}) {
        std::vector<double> q_moved = q;
        q_moved[jj] += sign * step;
        if (j.has_limits && (q_moved[jj] < j.lower || q_moved[jj] > j.upper)) continue;
        (void)model_.ResolveDependentJoints(&q_moved);
        const double r = (SubtreeLoss(T_world_base, q_moved, j.child_link, &samples) - loss) /
                         static_cast<double>(samples);
        rise_sum += r;
        ++sides;
        if (r < lowest) {
          lowest = r;
          moved_to = q_moved[jj];
        }
      }
      if (sides == 0) continue;
      const double rise = rise_sum / sides;
      char line[200];
      std::snprintf(line, sizeof(line), "pinning: %s moved by %g costs %.3f mm/sample more%s",
                    j.name.c_str(), step, 1e3 * rise,
                    rise < options_.pinning_mean_loss ? ": AMBIGUOUS" : "");
      say_(line);
      if (rise < options_.pinning_mean_loss && rise < record.margin) {
        record.ambiguous = true;
        record.alternative = moved_to;
        record.margin = rise;
      }
    }
  }

  // The Eq. (9) loss of every link at or below `link` at joint values q;
  // *samples counts the sweep samples scored.
  double SubtreeLoss(const Pose& T_world_base, const std::vector<double>& q, int link,
                     size_t* samples) const {
    const std::vector<Pose> T_world_link = model_.ForwardKinematics(q, T_world_base);
    double loss = 0.0;
    *samples = 0;
    for (const int l : SubtreeLinks(model_, link)) {
      const SurfaceSamples& s = sweep_samples_[static_cast<size_t>(l)];
      if (s.points.empty()) continue;
      loss += sweep_->LossAt(s, T_world_link[static_cast<size_t>(l)], sweep_options_);
      *samples += s.size();
    }
    return loss;
  }

 private:
  // in[l]: link l is `link` or below it (link -1: every link).
  std::vector<bool> SubtreeMask(int link) const {
    std::vector<bool> in(model_.links().size(), link < 0);
    if (link >= 0) {
      for (const int l : SubtreeLinks(model_, link)) in[static_cast<size_t>(l)] = true;
    }
    return in;
  }

  // Prismatic joints keep point-to-point residuals: a part sliding along
  // its axis (a gun's jaw) shows few faces across the axis, and
  // point-to-plane leaves it free to slide. Only its tip and shoulder pull
  // along the axis, so it converges slowly: four times the iterations (the
  // bundled `home` posture's jaw stopped 10.9 mm off at 60, 0.9 mm at 240;
  // measured at da5178d).
  static WeightedIcpOptions ForMotion(WeightedIcpOptions options, const LinkMotion& motion) {
    if (motion.type == LinkMotion::Type::kPrismatic) {
      options.point_to_plane = false;
      options.max_iterations *= 4;
    }
    return options;
  }

  // resweep: the joint was fitted before; a revolute joint is swept only
  // within RobotFitOptions::resweep_window_rad of its value and keeps its
  // symmetry decision and runner-up.
  Status FitJoint(const Pose& T_world_base, std::vector<double>* q, JointRecord* record,
                  bool resweep = false) {
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
    // A revolute child adds only its round part about its own axis when it
    // has one (a flange): that part is where it is whatever the child's
    // value, while the rest, at a value not fitted yet, could pull this
    // joint into a wrong basin it would not leave (a wrist under a gun).
    auto add_children = [&] {
      for (const int link : body.links) {
        for (const int child_joint : model_.links()[static_cast<size_t>(link)].child_joints) {
          const Joint& c = model_.joints()[static_cast<size_t>(child_joint)];
          if (c.type == JointType::kFixed) continue;
          const Body child = MakeBody(model_, c.child_link, child_joint);
          const Pose T_body_child = T_world_link[static_cast<size_t>(j.child_link)].inverse() *
                                    T_world_link[static_cast<size_t>(c.child_link)];
          SurfaceSamples child_sweep, child_icp;
          AppendBodySamples(child, sweep_samples_, Pose::Identity(), &child_sweep);
          AppendBodySamples(child, icp_samples_, Pose::Identity(), &child_icp);
          if (c.type != JointType::kPrismatic) {
            SurfaceSamples round_sweep = RoundPart(child_sweep, c.axis);
            if (static_cast<double>(round_sweep.size()) >=
                options_.min_round_child_share * static_cast<double>(child_sweep.size())) {
              child_sweep = std::move(round_sweep);
              child_icp = RoundPart(child_icp, c.axis);
            }
          }
          AppendPosedSamples(child_sweep, T_body_child, &body_sweep);
          AppendPosedSamples(child_icp, T_body_child, &body_icp);
        }
      }
    };
    if (record->symmetric) add_children();
    ThinSamples(options_.max_icp_samples, &body_icp);
    ThinSamples(options_.max_sweep_samples, &body_sweep);
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
        EDGEFIT_RETURN_IF_ERROR(sweep_->Sweep(body_sweep, window, sweep_options_, &summary));
        record->sweep.q = summary.q;
        record->sweep.loss = summary.loss;
        record->sweep.seconds = summary.seconds;
        return Status::Ok();
      }
      EDGEFIT_RETURN_IF_ERROR(sweep_->Sweep(body_sweep, motion, sweep_options_, &record->sweep));
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
      ThinSamples(options_.max_icp_samples, &body_icp);
      ThinSamples(options_.max_sweep_samples, &body_sweep);
      EDGEFIT_RETURN_IF_ERROR(sweep());
    }
    LinkState state;
    state.q = record->sweep.q;
    WeightedIcpSummary summary;
    EDGEFIT_RETURN_IF_ERROR(
        icp_->Fit(body_icp, motion, ForMotion(joint_icp_, motion), &state, &summary));
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

  const KinematicModel& model_;
  const RobotFitOptions& options_;
  const std::vector<SurfaceSamples>& icp_samples_;
  const std::vector<SurfaceSamples>& sweep_samples_;
  WeightedIcp* icp_;
  const JointSweep* sweep_;
  std::function<void(const std::string&)> say_;
  WeightedIcpOptions joint_icp_, subtree_icp_;
  JointSweepOptions sweep_options_;
};

// The base's rough stage by options.base_rough_method into
// result->base_rough (and result->arm_tips); arm tips that find no
// placement fall back to the cross sections.
Status RoughBase(const ScanSet& scans, const std::vector<std::vector<Eigen::Vector3f>>& normals,
                 const KinematicModel& model, const TriangleMesh& base_mesh,
                 const RobotFitOptions& options, const BasePoseLoss& base_loss,
                 const std::function<void(const std::string&)>& say, RobotFitResult* result) {
  using Method = RobotFitOptions::BaseRoughMethod;
  if (options.base_rough_method == Method::kArmTips) {
    say("base: rough registration (arm tips in a height map, symmetry axis)");
    ConveyanceBaseRoughOptions tips = options.conveyance_base_rough;
    tips.symmetry.seed = options.seed;
    const Status status = FitConveyanceBaseRough(scans, normals, model, base_mesh, tips, base_loss,
                                                 &result->arm_tips);
    if (status.ok()) {
      result->base_rough_method = Method::kArmTips;
      result->base_rough.T_world_base = result->arm_tips.T_world_base;
      result->base_rough.candidates = result->arm_tips.candidates;
      result->base_rough.floor_z = result->arm_tips.floor_z;
      result->base_rough.seconds = result->arm_tips.seconds;
      char line[200];
      std::snprintf(line, sizeof(line),
                    "base: %zu scan tips (%d paired), %zu model tips, %d matches, %d poses scored",
                    result->arm_tips.scan_tips.size(), result->arm_tips.symmetric_scan_tips,
                    result->arm_tips.model_tips.size(), result->arm_tips.matches,
                    result->arm_tips.scored);
      say(line);
      return Status::Ok();
    }
    say("base: " + status.message() + "; trying cross-section corners (Sec. 5.1.1)");
  }
  say("base: rough registration (cross-section corners, RANSAC)");
  BaseRoughOptions rough = options.base_rough;
  rough.seed = options.seed;
  result->base_rough_method = Method::kCrossSections;
  return FitBaseRough(scans, normals, base_mesh, rough, &result->base_rough);
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
  const JointSweep sweep(&search.lattice(), &visibility);
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
  std::vector<Pose> roughs;  // the rough base poses fitted on, best first
  if (options.has_initial_base) {
    Pose T_world_base = options.T_world_base_initial;
    double floor_z = 0.0;
    const Status status = EstimateFloorHeight(scans, edges.normals, Eigen::AlignedBox3d(),
                                              options.base_rough.floor_normal_cos, &floor_z);
    if (!status.ok()) {
      result->ok = false;
      result->message = "base hint: " + status.message();
      result->q = model.ZeroJoints();
      result->timings.total = Since(start);
      return Status::Ok();
    }
    T_world_base.translation().z() += floor_z;
    roughs.push_back(T_world_base);
  } else {
    TriangleMesh base_mesh;
    for (size_t k = 0; k < base.links.size(); ++k) {
      base_mesh.Append(model.links()[static_cast<size_t>(base.links[k])].mesh, base.T_body_link[k]);
    }
    // The Eq. (9) loss of the base alone, with the scan's visibility: it
    // tells a symmetric base's turns apart (parts seen, or space seen empty,
    // on one side), which the 2D scores cannot.
    SurfaceSamples base_sweep;
    AppendBodySamples(base, sweep_samples, Pose::Identity(), &base_sweep);
    ThinSamples(options.max_sweep_samples, &base_sweep);
    auto base_loss = [&](const Pose& T) { return sweep.LossAt(base_sweep, T, sweep_options); };
    const Status status =
        RoughBase(scans, edges.normals, model, base_mesh, options, base_loss, say, result);
    if (!status.ok()) {
      result->ok = false;
      result->message = status.message();
      result->q = model.ZeroJoints();
      result->timings.total = Since(start);
      return Status::Ok();
    }
    // An elongated base (a linear track's rail) scores about alike anywhere
    // along its length in the 2D sections: each candidate slides along it.
    if (result->base_rough_method == RobotFitOptions::BaseRoughMethod::kCrossSections) {
      const Eigen::Vector3d size = base_mesh.BoundingBox().sizes();
      const int along = size.x() >= size.y() ? 0 : 1;
      if (size[along] > options.slide_elongation * std::max(size[1 - along], 1e-9)) {
        say("base: elongated; each candidate slides along its length (Eq. 9 loss of the base)");
        for (Pose& candidate : result->base_rough.candidates) {
          candidate = SlideAlong(candidate, Eigen::Vector3d::Unit(along), 0.5 * size[along],
                                 options.slide_step, base_loss);
        }
      }
    }
    // Candidates by the base's loss, best first.
    std::vector<std::pair<double, Pose>> by_loss;
    for (const Pose& candidate : result->base_rough.candidates) {
      by_loss.emplace_back(base_loss(candidate), candidate);
    }
    std::stable_sort(by_loss.begin(), by_loss.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [loss, candidate] : by_loss) {
      const double margin = (loss - by_loss.front().first) / static_cast<double>(base_sweep.size());
      bool distinct = true;
      for (const Pose& kept : roughs) distinct = distinct && IsDistinctPose(kept, candidate);
      if (!roughs.empty() && (!distinct || margin >= options.base_alternative_loss)) continue;
      if (static_cast<int>(roughs.size()) > options.base_alternatives) break;
      if (!roughs.empty()) {
        char line[160];
        std::snprintf(line, sizeof(line),
                      "base: a distinct rough pose only %.3f mm/sample worse: fitted too",
                      1e3 * margin);
        say(line);
      }
      roughs.push_back(candidate);
    }
    result->base_rough.T_world_base = roughs.front();
    result->timings.base_rough = Since(stage);
  }

  // Sec. 5.1.2 and 5.2-5.3 from each rough base pose kept: the base's
  // precise ICP, then the joints, parents first.
  ChainFitter chain(model, options, icp_samples, sweep_samples, &icp, &sweep, say);
  struct Attempt {
    Pose T_world_base = Pose::Identity();
    WeightedIcpSummary base;
    std::vector<double> q;
    std::vector<JointRecord> records;
    double loss = 0.0;  // Eq. (9) of the whole model
  };
  auto fit_from = [&](const Pose& T_rough, Attempt* attempt) -> Status {
    auto stage = std::chrono::steady_clock::now();
    say("base: precise weighted ICP");
    LinkState base_state;
    base_state.T_world_link = T_rough;
    EDGEFIT_RETURN_IF_ERROR(
        icp.Fit(base_samples, LinkMotion::Free(), base_icp, &base_state, &attempt->base));
    attempt->T_world_base = base_state.T_world_link;
    result->timings.base_precise += Since(stage);
    stage = std::chrono::steady_clock::now();
    const Pose& T = attempt->T_world_base;
    std::vector<double>& q = attempt->q;
    std::vector<JointRecord>& records = attempt->records;
    EDGEFIT_RETURN_IF_ERROR(chain.FitJoints(T, &q, &records));
    if (options.refine_subtrees) {
      EDGEFIT_RETURN_IF_ERROR(chain.RefineSubtrees(T, 0, -1, &records, &q));
      bool switched = false;
      EDGEFIT_RETURN_IF_ERROR(chain.CheckAlternatives(T, &records, &q, &switched));
      for (int pass = 0; switched && pass < options.max_passes_after_switch; ++pass) {
        const std::vector<double> before = q;
        EDGEFIT_RETURN_IF_ERROR(chain.RefineSubtrees(T, 0, -1, &records, &q));
        switched = AnyJointMoved(model, before, q, options.settle_tolerance_rad,
                                 options.settle_tolerance_m);
      }
    }
    chain.CheckPinning(T, &records, q);
    size_t samples = 0;
    attempt->loss = chain.SubtreeLoss(T, q, model.root_link(), &samples);
    result->timings.chain += Since(stage);
    return Status::Ok();
  };
  Attempt best;
  EDGEFIT_RETURN_IF_ERROR(fit_from(roughs.front(), &best));
  for (size_t k = 1; k < roughs.size(); ++k) {
    say("base: the whole chain from alternative rough pose " + std::to_string(k));
    Attempt other;
    EDGEFIT_RETURN_IF_ERROR(fit_from(roughs[k], &other));
    char line[240];
    std::snprintf(line, sizeof(line),
                  "base: alternative rough pose %zu: whole model Eq. 9 loss %.1f against %.1f%s", k,
                  other.loss, best.loss, other.loss < best.loss ? ": taken" : "");
    say(line);
    if (other.loss < best.loss) {
      best = std::move(other);
      result->base_rough.T_world_base = roughs[k];
    }
  }
  result->T_world_base = best.T_world_base;
  result->bodies.push_back(Quality(model, base, base_samples, best.base, options));
  std::vector<double>& q = best.q;
  const std::vector<JointRecord>& records = best.records;
  const Status resolved = model.ResolveDependentJoints(&q);
  result->q = q;

  // The whole-chain refinement (or the covariance alone) at the final values.
  stage = std::chrono::steady_clock::now();
  if (options.refine_chain) say("chain: whole-chain refinement (base and every joint at once)");
  std::vector<SurfaceSamples> chain_samples(model.links().size());
  std::vector<bool> point_to_point(model.links().size(), false);
  for (size_t j = 0; j <= model.joints().size(); ++j) {
    const bool root = j == model.joints().size();
    if (!root && !model.joints()[j].IsMoving()) continue;
    const Body body =
        root ? base : MakeBody(model, model.joints()[j].child_link, static_cast<int>(j));
    SurfaceSamples& samples = chain_samples[static_cast<size_t>(body.link)];
    AppendBodySamples(body, icp_samples, Pose::Identity(), &samples);
    ThinSamples(options.max_chain_samples, &samples);
    point_to_point[static_cast<size_t>(body.link)] =
        !root && model.joints()[j].type == JointType::kPrismatic;
  }
  ChainRefinementOptions chain_options = options.chain_refinement;
  chain_options.refine = options.refine_chain;
  chain_options.icp.uniform_weights = options.uniform_weights;
  EDGEFIT_RETURN_IF_ERROR(RefineChain(model, scans, &search, chain_samples, point_to_point,
                                      chain_options, &result->T_world_base, &result->q,
                                      &result->chain_refinement));
  q = result->q;
  result->timings.refine = Since(stage);
  if (options.refine_chain) {
    char line[200];
    std::snprintf(line, sizeof(line),
                  "chain: refined in %d iterations (%s), samples moved up to %.3f mm, %.2f s",
                  result->chain_refinement.iterations,
                  IcpStopReasonName(result->chain_refinement.stop_reason),
                  1e3 * result->chain_refinement.max_displacement, result->timings.refine);
    say(line);
  }

  // Quality of every body alone at the final values.
  WeightedIcpSummary summary;
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, result->T_world_base);
  for (const JointRecord& record : records) {
    const Body body =
        MakeBody(model, model.joints()[static_cast<size_t>(record.joint)].child_link, record.joint);
    SurfaceSamples samples;
    AppendBodySamples(body, icp_samples, Pose::Identity(), &samples);
    ThinSamples(options.max_icp_samples, &samples);
    if (samples.points.empty()) continue;  // an empty link: nothing to judge
    EDGEFIT_RETURN_IF_ERROR(
        icp.Evaluate(samples, T_world_link[static_cast<size_t>(body.link)], joint_icp, &summary));
    BodyQuality quality = Quality(model, body, samples, summary, options);
    quality.icp_iterations = record.icp_iterations;
    quality.symmetric = record.symmetric;
    quality.sweep_value = record.sweep.q;
    quality.ambiguous = record.ambiguous;
    quality.alternative_value = record.alternative;
    quality.ambiguity_margin = record.margin;
    quality.ok = quality.ok && !quality.ambiguous;
    result->bodies.push_back(quality);
  }
  result->timings.total = Since(start);

  result->ok = resolved.ok();
  if (!resolved.ok()) result->message = resolved.message();
  for (const BodyQuality& b : result->bodies) {
    if (b.ok || !result->ok) continue;
    result->ok = false;
    char line[512];
    if (b.ambiguous) {
      std::snprintf(line, sizeof(line),
                    "%s is ambiguous: %s = %.4f and %.4f fit the scan about equally well (Eq. 9 "
                    "loss %.3f mm apart per sample); an attached end effector or more scan "
                    "coverage would tell them apart",
                    b.link.c_str(), b.joint.c_str(),
                    result->q[static_cast<size_t>(model.JointIndex(b.joint))], b.alternative_value,
                    1e3 * b.ambiguity_margin);
    } else {
      std::snprintf(line, sizeof(line),
                    "%s does not match the scan: %.0f%% of its visible samples within %.1f mm "
                    "of the scanned surface (need %.0f%%), RMS %.2f mm",
                    b.link.c_str(), 100.0 * b.inlier_share, 1e3 * options.joint_icp.final_gate,
                    100.0 * options.min_inlier_share, 1e3 * b.rms);
    }
    result->message = line;
  }
  return Status::Ok();
}

}  // namespace edgefit
