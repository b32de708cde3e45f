// ChainFitter's ambiguity checks (extensions of Sec. 5.2): a joint whose
// sweep found a near-equal runner-up, or whose sweep at the final values
// prefers another basin, is fitted from there too as a branch, and the
// lower Eq. (9) loss of the bodies the two place apart wins (at the final
// basins, a branch better only by showing more of surface both values
// explain is none); a joint the scan does not pin down is flagged.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "solvers/joints/chain_fitter.h"

namespace edgefit {
namespace {

// How far apart two values of joint j are: along a prismatic joint, or the
// shorter way round a revolute one [m], [rad].
double Apart(const Joint& j, double a, double b) {
  return j.type == JointType::kPrismatic ? std::abs(a - b)
                                         : std::abs(std::remainder(a - b, 2.0 * M_PI));
}

// The sweep's distinct-basin distance of joint j [m], [rad].
double Distinct(const Joint& j, const JointSweepOptions& sweep) {
  return j.type == JointType::kPrismatic ? sweep.distinct_prismatic : sweep.distinct_revolute;
}

}  // namespace

std::vector<bool> ChainFitter::PlacedApart(const Pose& T_world_base, const std::vector<double>& q,
                                           const std::vector<double>& q_other,
                                           const std::vector<bool>& in) const {
  const std::vector<Pose> T = model_.ForwardKinematics(q, T_world_base);
  const std::vector<Pose> T_other = model_.ForwardKinematics(q_other, T_world_base);
  std::vector<double> moved(in.size(), 0.0);  // the farthest any sample moves [m]
  double most = 0.0;
  for (size_t l = 0; l < in.size(); ++l) {
    if (!in[l]) continue;
    for (const Eigen::Vector3f& p : sweep_samples_[l].points) {
      const Eigen::Vector3d x = p.cast<double>();
      moved[l] = std::max(moved[l], (T[l] * x - T_other[l] * x).norm());
    }
    most = std::max(most, moved[l]);
  }
  std::vector<bool> apart(in.size(), false);
  for (size_t l = 0; l < in.size(); ++l) {
    apart[l] =
        in[l] && !sweep_samples_[l].points.empty() && moved[l] >= options_.alike_share * most;
  }
  return apart;
}

bool ChainFitter::LinkMoved(const Pose& then, const Pose& now) const {
  const Eigen::AngleAxisd turned(then.rotation().transpose() * now.rotation());
  return std::abs(turned.angle()) > options_.resweep_tolerance_rad ||
         (now.translation() - then.translation()).norm() > options_.resweep_tolerance_m;
}

Status ChainFitter::FitBranch(const Pose& T_world_base, size_t i, double value,
                              const std::vector<double>& q, const std::vector<JointRecord>& records,
                              std::vector<double>* q_other,
                              std::vector<JointRecord>* other_records) {
  const Joint& j = model_.joints()[static_cast<size_t>(records[i].joint)];
  *q_other = q;
  *other_records = records;
  (*q_other)[static_cast<size_t>(records[i].joint)] = value;
  (void)model_.ResolveDependentJoints(q_other);
  const std::vector<bool> below = SubtreeMask(j.child_link);
  for (size_t k = i + 1; k < records.size(); ++k) {
    const int link = model_.joints()[static_cast<size_t>(records[k].joint)].child_link;
    if (below[static_cast<size_t>(link)]) {
      EDGEFIT_RETURN_IF_ERROR(FitJoint(T_world_base, q_other, &(*other_records)[k]));
    }
  }
  // The subtree pass again while it still moves the joint: an ICP that ran
  // out of iterations on its way back to the other value is no second
  // basin (a bare FANUC's forearm roll went 15 deg of the 22 in one pass
  // and was called ambiguous).
  const size_t jj = static_cast<size_t>(records[i].joint);
  for (int pass = 0; pass < options_.branch_passes; ++pass) {
    const double before = (*q_other)[jj];
    EDGEFIT_RETURN_IF_ERROR(RefineSubtrees(T_world_base, i, j.child_link, other_records, q_other));
    if (Apart(j, (*q_other)[jj], before) < options_.branch_settled * Distinct(j, options_.sweep)) {
      break;
    }
  }
  return Status::Ok();
}

double ChainFitter::BranchGain(const Pose& T_world_base, const std::vector<double>& q,
                               const std::vector<double>& q_other, int link,
                               const JointSweep* sweep) const {
  const std::vector<bool> below = SubtreeMask(link);
  size_t samples = 0, placed_apart_samples = 0;  // the subtree's, the scored bodies'
  for (size_t l = 0; l < below.size(); ++l) samples += below[l] ? sweep_samples_[l].size() : 0;
  const std::vector<bool> apart = PlacedApart(T_world_base, q, q_other, below);
  const double loss = LinksLoss(T_world_base, q, apart, &placed_apart_samples, sweep);
  const double other_loss = LinksLoss(T_world_base, q_other, apart, &placed_apart_samples, sweep);
  return (loss - other_loss) / static_cast<double>(std::max<size_t>(samples, 1));
}

namespace {

// Whether p lies within `reach` [m] of one of `points`.
bool Near(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& points, double reach) {
  const double reach2 = reach * reach;
  for (const Eigen::Vector3d& x : points) {
    if ((p - x).squaredNorm() < reach2) return true;
  }
  return false;
}

}  // namespace

ChainFitter::ViewComparison ChainFitter::CompareViews(const Pose& T_world_base,
                                                     const std::vector<double>& q,
                                                     const std::vector<double>& q_other,
                                                     int link) const {
  const std::vector<bool> below = SubtreeMask(link);
  const std::vector<bool> apart = PlacedApart(T_world_base, q, q_other, below);
  const std::vector<Pose> T[2] = {model_.ForwardKinematics(q, T_world_base),
                                  model_.ForwardKinematics(q_other, T_world_base)};
  const double tight = options_.explained_distance;
  const double hidden_loss = options_.sweep.occluded_loss;
  // Per value: the model's samples matched within `tight` (world), and the
  // bodies placed apart's samples matched there but hidden at the other
  // value, with the loss each saves against a hidden one.
  std::vector<Eigen::Vector3d> matched[2], shown[2];
  std::vector<double> saved[2];
  size_t samples = 0;
  double evidence = 0.0;  // the samples seen at both, then those shown at one only
  std::vector<float> loss[2];
  for (size_t l = 0; l < T[0].size(); ++l) {
    const SurfaceSamples& body = sweep_samples_[l];
    if (below[l]) samples += body.size();
    if (body.points.empty()) continue;
    sweep_->LossAt(body, T[0][l], options_.sweep, &loss[0]);
    if (below[l]) {
      sweep_->LossAt(body, T[1][l], options_.sweep, &loss[1]);
    } else {
      loss[1] = loss[0];  // placed alike by both values
    }
    for (size_t i = 0; i < body.points.size(); ++i) {
      const bool seen[2] = {loss[0][i] >= 0.0f, loss[1][i] >= 0.0f};
      for (int v = 0; v < 2; ++v) {
        if (!seen[v] || !(loss[v][i] < tight)) continue;
        const Eigen::Vector3d p = T[v][l] * body.points[i].cast<double>();
        matched[v].push_back(p);
        if (below[l] && apart[l] && !seen[1 - v]) {
          shown[v].push_back(p);
          saved[v].push_back(hidden_loss - loss[v][i]);
        }
      }
      if (below[l] && apart[l] && seen[0] && seen[1]) evidence += loss[0][i] - loss[1][i];
    }
  }
  // A sample shown at one value only is evidence for it when no matched
  // sample of the model at the other value lies near it (1.5 sweep
  // spacings: the samples' gaps): surface the other leaves unmatched.
  const double reach = 1.5 * samples_.sweep_spacing;
  ViewComparison out;
  out.shown = shown[1].size();
  for (int v = 0; v < 2; ++v) {
    for (size_t k = 0; k < shown[v].size(); ++k) {
      if (Near(shown[v][k], matched[1 - v], reach)) continue;
      evidence += v == 1 ? saved[v][k] : -saved[v][k];
      if (v == 1) ++out.new_surface;
    }
  }
  const double per_sample = 1.0 / static_cast<double>(std::max<size_t>(samples, 1));
  out.evidence_gain = evidence * per_sample;
  return out;
}

double ChainFitter::CoveredMargin(const Pose& T_world_base, const std::vector<double>& q,
                                  const std::vector<double>& q_other, int link) const {
  if (covered_scan_ == nullptr) return 0.0;
  return -BranchGain(T_world_base, q, q_other, link, covered_scan_);
}

Status ChainFitter::CheckAlternatives(const Pose& T_world_base, std::vector<JointRecord>* records,
                                      std::vector<double>* q, bool* switched) {
  *switched = false;
  for (size_t i = 0; i < records->size(); ++i) {
    const JointRecord& record = (*records)[i];
    if (!(record.sweep_margin < options_.ambiguity_check_loss)) continue;
    const Joint& j = model_.joints()[static_cast<size_t>(record.joint)];
    std::vector<double> q_other;
    std::vector<JointRecord> other_records;
    EDGEFIT_RETURN_IF_ERROR(FitBranch(T_world_base, i, record.sweep.runner_up_q, *q, *records,
                                      &q_other, &other_records));
    const size_t jj = static_cast<size_t>(record.joint);
    if (Apart(j, q_other[jj], (*q)[jj]) < 0.5 * Distinct(j, options_.sweep)) {
      continue;  // back in the same basin: no alternative
    }
    const double gain = BranchGain(T_world_base, *q, q_other, j.child_link);
    const bool take_other = gain > 0.0;
    const double alternative = take_other ? (*q)[jj] : q_other[jj];
    // The same pair on the scan with the coverings: how much better the
    // value taken fits there (negative: the other fits better).
    const double covered_margin = take_other
                                      ? CoveredMargin(T_world_base, q_other, *q, j.child_link)
                                      : CoveredMargin(T_world_base, *q, q_other, j.child_link);
    if (take_other) {
      *switched = true;
      *q = std::move(q_other);
      *records = std::move(other_records);
    }
    JointRecord& checked = (*records)[i];
    checked.alternative = alternative;
    checked.margin = std::abs(gain);
    checked.covered_margin = covered_margin;
    // A close pair is told by the scan with the coverings; a pair the two
    // scans decide each their own way is decided by the coverings, which
    // were found at the first estimate and can hide the other value's
    // surfaces (a jaw slid along itself: the part of it beyond the jaw's
    // end there lies off the CAD): ambiguous.
    const double bound = options_.ambiguity_mean_loss;
    const bool told_by_coverings = checked.margin < bound && covered_margin > bound;
    const bool coverings_decide = DecidedByCoverings(covered_margin, options_);
    checked.ambiguous = (checked.margin < bound && !told_by_coverings) || coverings_decide;
    char told[96] = "";
    if (told_by_coverings || coverings_decide) {
      std::snprintf(told, sizeof(told), " (with the coverings %.3f mm/sample %s)",
                    1e3 * std::abs(covered_margin), covered_margin > 0.0 ? "worse" : "better");
    }
    char line[400];
    std::snprintf(line, sizeof(line),
                  "alternatives: %s = %.5f, other value %.5f is %.3f mm/sample worse%s%s%s",
                  j.name.c_str(), (*q)[jj], alternative, 1e3 * checked.margin, told,
                  take_other ? " (the first fit's value)" : "",
                  checked.ambiguous ? ": AMBIGUOUS" : "");
    say_(line);
  }
  return Status::Ok();
}

Status ChainFitter::CheckFinalBasins(const Pose& T_world_base, bool take, std::vector<double>* q,
                                     std::vector<JointRecord>* records, bool* moved) {
  *moved = false;
  for (size_t i = 0; i < records->size(); ++i) {
    JointRecord& record = (*records)[i];
    const Joint& j = model_.joints()[static_cast<size_t>(record.joint)];
    const size_t jj = static_cast<size_t>(record.joint);
    const std::vector<Pose> T_world_link = model_.ForwardKinematics(*q, T_world_base);
    const bool prismatic = j.type == JointType::kPrismatic;
    const double basin = prismatic ? options_.final_basin_prismatic : options_.final_basin_revolute;
    if (record.full_sweep &&
        !LinkMoved(record.T_world_parent_swept, T_world_link[static_cast<size_t>(j.parent_link)]) &&
        Apart(j, record.full_sweep_q, (*q)[jj]) < basin) {
      continue;  // swept where it hangs now, and its best was this basin
    }
    const LinkMotion motion =
        LinkMotion::FromJoint(j, T_world_link[static_cast<size_t>(j.parent_link)]);
    const Body body = MakeBody(model_, j.child_link, record.joint);
    SurfaceSamples body_sweep;
    AppendBodySamples(body, sweep_samples_, Pose::Identity(), &body_sweep);
    if (record.symmetric) AddChildren(record.joint, T_world_link, nullptr, &body_sweep);
    ThinSamples(samples_.max_sweep_samples, &body_sweep);
    if (body_sweep.points.empty()) continue;
    JointSweepSummary best;
    EDGEFIT_RETURN_IF_ERROR(sweep_->Sweep(body_sweep, motion, options_.sweep, &best));
    if (Apart(j, best.q, (*q)[jj]) < basin) continue;
    const double better = (sweep_->Loss(body_sweep, motion, (*q)[jj], options_.sweep) - best.loss) /
                          static_cast<double>(body_sweep.points.size());
    if (!(better > options_.ambiguity_mean_loss)) continue;
    std::vector<double> q_other;
    std::vector<JointRecord> other_records;
    EDGEFIT_RETURN_IF_ERROR(
        FitBranch(T_world_base, i, best.q, *q, *records, &q_other, &other_records));
    const double gain = BranchGain(T_world_base, *q, q_other, j.child_link);
    // Better only by showing more of surface both values explain (a jaw
    // sliding along its own scanned shaft, its end hidden): the scan does not
    // pin the joint between the two.
    const ViewComparison views = CompareViews(T_world_base, *q, q_other, j.child_link);
    const bool bound_exceeded = gain > options_.ambiguity_mean_loss;
    const bool not_pinned = bound_exceeded && !(views.evidence_gain > options_.ambiguity_mean_loss);
    const bool elsewhere = bound_exceeded && !not_pinned;
    char line[480];
    std::snprintf(line, sizeof(line),
                  "final basins: %s = %.5f, but swept at the final values of the others %.5f "
                  "fits %.3f mm/sample better; with the joints below fitted again there (%s = "
                  "%.5f) %.3f mm/sample %s; %.3f on the samples seen at both and those on "
                  "surface the other leaves unmatched (%zu of the %zu it shows there only)%s",
                  j.name.c_str(), (*q)[jj], best.q, 1e3 * better, j.name.c_str(), q_other[jj],
                  1e3 * std::abs(gain), gain > 0.0 ? "better" : "worse",
                  1e3 * views.evidence_gain, views.new_surface, views.shown,
                  not_pinned  ? ": NOT PINNED"
                  : !elsewhere ? ": kept"
                  : take       ? ": taken"
                               : ": NOT OK");
    say_(line);
    if (not_pinned) {
      record.ambiguous = true;
      record.alternative = q_other[jj];
      record.margin = std::abs(views.evidence_gain);
      continue;
    }
    if (!elsewhere) continue;
    if (take) {
      // The branch's joints were fitted anew: what the earlier checks said
      // of their old values no longer holds (CheckPinning again after the
      // refinement), except an alternative of this joint that is another
      // basin from the new value as well.
      const bool keep = record.ambiguous && Apart(j, record.alternative, q_other[jj]) >=
                                                0.5 * Distinct(j, options_.sweep);
      const JointRecord kept = record;
      const std::vector<bool> below = SubtreeMask(j.child_link);
      for (JointRecord& r : other_records) {
        if (!below[static_cast<size_t>(model_.joints()[static_cast<size_t>(r.joint)].child_link)])
          continue;
        r.ambiguous = r.better_elsewhere = false;
        r.alternative = 0.0;
        r.margin = std::numeric_limits<double>::infinity();
        if (keep && r.joint == kept.joint) {
          r.ambiguous = true;
          r.alternative = kept.alternative;
          r.margin = kept.margin;
          r.covered_margin = kept.covered_margin;
        }
      }
      *q = std::move(q_other);
      *records = std::move(other_records);
      *moved = true;
      continue;
    }
    record.ambiguous = true;
    record.better_elsewhere = true;
    record.alternative = q_other[jj];
    record.margin = gain;
  }
  return Status::Ok();
}

void ChainFitter::CheckPinning(const Pose& T_world_base, std::vector<JointRecord>* records,
                               const std::vector<double>& q) const {
  for (JointRecord& record : *records) {
    const Joint& j = model_.joints()[static_cast<size_t>(record.joint)];
    if (j.type == JointType::kPrismatic) continue;  // see ChainOptions::pinning_mean_loss
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

}  // namespace edgefit
