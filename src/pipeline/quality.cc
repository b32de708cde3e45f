// The quality verdict of every body at the final values (stages.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "edgefit/pipeline/joint_trust.h"
#include "stages.h"

namespace edgefit {

BodyQuality Quality(const KinematicModel& model, const Body& body, const SurfaceSamples& samples,
                    const WeightedIcpSummary& summary, const QualityOptions& options) {
  BodyQuality quality;
  quality.link = model.links()[static_cast<size_t>(body.link)].name;
  if (body.joint >= 0) quality.joint = model.joints()[static_cast<size_t>(body.joint)].name;
  quality.samples = samples.size();
  quality.visible = summary.visible_points;
  quality.occluded = summary.occluded_points;
  quality.inlier_share = summary.inlier_share;
  quality.rms = summary.rms;
  quality.icp_iterations = summary.iterations;
  quality.ok = summary.inlier_share >= options.min_inlier_share && summary.rms <= options.max_rms;
  quality.verdict = quality.ok ? JointVerdict::kOk : JointVerdict::kMismatch;
  if (body.joint < 0 && quality.SeenShare() < options.min_base_seen_share) {
    quality.ok = false;
    quality.verdict = JointVerdict::kNotSeen;
  }
  return quality;
}

const char* JointVerdictName(JointVerdict verdict) {
  switch (verdict) {
    case JointVerdict::kOk:
      return "ok";
    case JointVerdict::kAmbiguous:
      return "ambiguous";
    case JointVerdict::kUnobservable:
      return "unobservable";
    case JointVerdict::kNotSeen:
      return "not_seen";
    case JointVerdict::kMismatch:
      return "mismatch";
    case JointVerdict::kGiven:
      return "given";
  }
  return "mismatch";
}

namespace {

// Why body b (not ok) is not: one clause of result->message.
std::string WhyNotOk(const KinematicModel& model, const BodyQuality& b, const FitResult& result,
                     const FitOptions& options) {
  const double value =
      b.joint.empty() ? 0.0 : result.q[static_cast<size_t>(model.JointIndex(b.joint))];
  char line[512];
  if (b.verdict == JointVerdict::kNotSeen && b.joint.empty()) {
    std::snprintf(line, sizeof(line),
                  "%s is not seen: %zu of its %zu samples facing the stations are in view "
                  "(%.0f%%, need %.0f%%); the others lie behind scanned surfaces: hidden, or "
                  "fitted inside or behind something that is not it",
                  b.link.c_str(), b.visible, b.visible + b.occluded, 100.0 * b.SeenShare(),
                  100.0 * options.quality.min_base_seen_share);
  } else if (b.verdict == JointVerdict::kNotSeen) {
    std::snprintf(line, sizeof(line),
                  "%s is not seen: %zu of its %zu samples are visible from the stations at the "
                  "fitted pose (need %zu); %s = %.4f is a guess",
                  b.link.c_str(), b.visible, b.samples, options.quality.min_visible_samples,
                  b.joint.c_str(), value);
  } else if (b.verdict != JointVerdict::kAmbiguous && b.inlier_share == 0.0) {
    std::snprintf(line, sizeof(line),
                  "%s does not match the scan: none of its %zu visible samples has a scan point "
                  "within %.1f mm; the stations saw past where it is fitted",
                  b.link.c_str(), b.visible, 1e3 * options.chain.joint_icp.final_gate);
  } else if (b.verdict != JointVerdict::kAmbiguous) {
    std::snprintf(line, sizeof(line),
                  "%s does not match the scan: %.0f%% of its visible samples within %.1f mm "
                  "of the scanned surface (need %.0f%%), RMS %.2f mm (at most %.2f)",
                  b.link.c_str(), 100.0 * b.inlier_share, 1e3 * options.chain.joint_icp.final_gate,
                  100.0 * options.quality.min_inlier_share, 1e3 * b.rms,
                  1e3 * options.quality.max_rms);
  } else if (b.unpinned) {
    const bool prismatic = model.joints()[static_cast<size_t>(model.JointIndex(b.joint))].type ==
                           JointType::kPrismatic;
    const double scale = prismatic ? 1e3 : 180.0 / M_PI;
    if (!std::isfinite(b.joint_std)) {
      std::snprintf(line, sizeof(line),
                    "%s is not pinned: %s = %.4f has no standard deviation (the covariance "
                    "failed) on a scan this noisy",
                    b.link.c_str(), b.joint.c_str(), value);
      return line;
    }
    std::snprintf(line, sizeof(line),
                  "%s is not pinned: %s = %.4f has a standard deviation of %.3f %s (at most %.3f); "
                  "the scan's noise leaves it uncertain",
                  b.link.c_str(), b.joint.c_str(), value, b.joint_std * scale,
                  prismatic ? "mm" : "deg",
                  (prismatic ? options.quality.max_joint_std_prismatic
                             : options.quality.max_joint_std_revolute) *
                      scale);
  } else if (b.chain_unmatched) {
    std::snprintf(line, sizeof(line),
                  "%s is not trusted: %s = %.4f fits its link, but a body between the base and "
                  "it does not match the scan",
                  b.link.c_str(), b.joint.c_str(), value);
  } else if (b.partner_torn) {
    std::snprintf(line, sizeof(line),
                  "%s is not trusted: %s = %.4f was fitted with %s, which has two values that "
                  "fit the scan about as well",
                  b.link.c_str(), b.joint.c_str(), value, b.torn_partner.c_str());
  } else if (b.better_elsewhere) {
    std::snprintf(line, sizeof(line),
                  "%s is in a wrong basin: %s = %.4f, with the joints below it fitted again "
                  "there, fits the scan better than the reported %.4f (Eq. 9 loss %.3f mm lower "
                  "per sample)",
                  b.link.c_str(), b.joint.c_str(), b.alternative_value, value,
                  1e3 * b.ambiguity_margin);
  } else if (DecidedByCoverings(b.covered_margin, options.chain)) {
    std::snprintf(line, sizeof(line),
                  "%s is ambiguous: %s = %.4f fits the scan better without the parts found "
                  "covered (Eq. 9 loss %.3f mm lower per sample), %.4f with them (%.3f mm "
                  "lower); the coverings were found at the first estimate and may hide either "
                  "value's surfaces",
                  b.link.c_str(), b.joint.c_str(), value, 1e3 * b.ambiguity_margin,
                  b.alternative_value, -1e3 * b.covered_margin);
  } else {
    std::snprintf(line, sizeof(line),
                  "%s is ambiguous: %s = %.4f and %.4f fit the scan about equally well (Eq. 9 "
                  "loss %.3f mm apart per sample); an attached end effector or more scan "
                  "coverage would tell them apart",
                  b.link.c_str(), b.joint.c_str(), value, b.alternative_value,
                  1e3 * b.ambiguity_margin);
  }
  return line;
}

}  // namespace

Status JudgeQuality(const KinematicModel& model, WeightedIcp* icp, const CadSamples& cad,
                    const std::vector<JointRecord>& records, const Status& resolved,
                    const FitOptions& options, FitResult* result) {
  // The reporting conventions first (each places every link as the fitted
  // value does): a base that looks the same turned (observability.h) turned
  // so that its joint reads the value nearest zero, a joint no scan can pin
  // at its zero (or the limit nearest it), a joint with a range beyond a
  // full turn at its whole turn nearest zero.
  result->base_symmetry = FindBaseSymmetry(model, cad.icp, options.samples.icp_spacing,
                                           options.quality.observability);
  if (result->base_symmetry.joint >= 0) {
    const size_t j1 = static_cast<size_t>(result->base_symmetry.joint);
    const Joint& joint = model.joints()[j1];
    const double q1 = result->q[j1];
    double best = q1;
    std::vector<double> turns = result->base_symmetry.turns;
    turns.push_back(0.0);
    if (result->base_symmetry.round) turns.push_back(q1);  // any turn: zero
    for (const double t : turns) {
      for (int k = -2; k <= 2; ++k) {
        const double v = q1 - t + 2.0 * M_PI * k;
        const bool within = joint.type == JointType::kContinuous
                                ? std::abs(v) <= M_PI
                                : v >= joint.lower - 1e-9 && v <= joint.upper + 1e-9;
        if (within && std::abs(v) < std::abs(best) - 1e-9) best = v;
      }
    }
    result->T_world_base = TurnBaseForJoint(model, static_cast<int>(j1), result->T_world_base, q1, best);
    result->q[j1] = best;
  }
  std::vector<bool> unobservable(model.joints().size(), false);
  std::vector<double> off_share(model.joints().size(), std::nan(""));
  for (const JointRecord& record : records) {
    const size_t jj = static_cast<size_t>(record.joint);
    const Joint& j = model.joints()[jj];
    unobservable[jj] =
        TurnIsUnobservable(model, record.joint, result->q, cad.icp, options.samples.icp_spacing,
                           options.quality.observability, &off_share[jj]) ||
        (result->base_symmetry.round && record.joint == result->base_symmetry.joint);
    result->q[jj] = unobservable[jj] ? ZeroOrNearestLimit(j) : NearestZeroTurn(j, result->q[jj]);
  }
  (void)model.ResolveDependentJoints(&result->q);

  WeightedIcpSummary summary;
  const std::vector<Pose> T_world_link = model.ForwardKinematics(result->q, result->T_world_base);
  for (const JointRecord& record : records) {
    const size_t jj = static_cast<size_t>(record.joint);
    const Body body = MakeBody(model, model.joints()[jj].child_link, record.joint);
    const SurfaceSamples samples = BodySamples(body, cad.icp, options.samples.max_icp_samples);
    if (samples.points.empty()) continue;  // an empty link: nothing to judge
    EDGEFIT_RETURN_IF_ERROR(icp->Evaluate(samples, T_world_link[static_cast<size_t>(body.link)],
                                          options.chain.joint_icp, &summary));
    BodyQuality quality = Quality(model, body, samples, summary, options.quality);
    quality.icp_iterations = record.icp_iterations;
    quality.symmetric = record.symmetric;
    quality.sweep_value = record.sweep.q;
    quality.ambiguous = record.ambiguous;
    quality.better_elsewhere = record.better_elsewhere;
    quality.alternative_value = record.alternative;
    quality.ambiguity_margin = record.margin;
    quality.covered_margin = record.covered_margin;
    quality.turned_off_share = off_share[jj];
    for (const double v : WholeTurns(model.joints()[jj], result->q[jj])) {
      if (v != result->q[jj]) quality.whole_turns.push_back(v);
    }
    const bool matches = quality.ok;
    if (quality.visible < options.quality.min_visible_samples) {
      quality.verdict = JointVerdict::kNotSeen;
    } else if (!matches) {
      quality.verdict = JointVerdict::kMismatch;
    } else if (unobservable[jj]) {
      quality.verdict = JointVerdict::kUnobservable;
    } else if (quality.ambiguous) {
      quality.verdict = JointVerdict::kAmbiguous;
    } else {
      quality.verdict = JointVerdict::kOk;
    }
    const std::vector<double>& stds = result->chain_refinement.joint_std;
    quality.joint_std = jj < stds.size() ? stds[jj] : std::nan("");
    const double max_std = model.joints()[jj].type == JointType::kPrismatic
                               ? options.quality.max_joint_std_prismatic
                               : options.quality.max_joint_std_revolute;
    // On noisy scans (a depth camera) a joint without a spread (the
    // covariance failed) is no more pinned than one with a wide one.
    const bool no_std = !std::isfinite(quality.joint_std) && result->noise_scale > 1.0;
    if (quality.verdict == JointVerdict::kOk && (quality.joint_std > max_std || no_std)) {
      quality.verdict = JointVerdict::kAmbiguous;
      quality.unpinned = true;
    }
    quality.ok =
        quality.verdict == JointVerdict::kOk || quality.verdict == JointVerdict::kUnobservable;
    result->bodies.push_back(quality);
  }
  DistrustBelowUnmatched(model, result);
  DistrustTornPairs(model, result);
  SayWhyNotOk(model, resolved, options, result);
  return Status::Ok();
}

void SayWhyNotOk(const KinematicModel& model, const Status& resolved, const FitOptions& options,
                 FitResult* result) {
  result->ok = resolved.ok();
  result->message = resolved.ok() ? "" : resolved.message();
  for (const BodyQuality& b : result->bodies) {
    if (b.ok) continue;
    result->message += (result->ok ? "" : "; ") + WhyNotOk(model, b, *result, options);
    result->ok = false;
  }
}

void MarkBasinChanges(const KinematicModel& model, const ChainFitter& chain,
                      const std::vector<double>& q_first, const FitOptions& options,
                      const ProgressFn& say, FitResult* result) {
  std::vector<bool> unobservable(model.joints().size(), false);  // reported by convention
  for (const BodyQuality& body : result->bodies) {
    if (body.verdict == JointVerdict::kUnobservable) {
      unobservable[static_cast<size_t>(model.JointIndex(body.joint))] = true;
    }
  }
  auto changed = [&](size_t j) {
    const Joint& joint = model.joints()[j];
    return joint.IsIndependent() && joint.type != JointType::kPrismatic && !unobservable[j] &&
           std::abs(std::remainder(result->q[j] - q_first[j], 2.0 * M_PI)) >
               options.refinement.coverings.basin_change;
  };
  for (size_t j = 0; j < model.joints().size(); ++j) {
    if (!changed(j)) continue;
    const Joint& joint = model.joints()[j];
    bool above = false;  // a joint above it changed: compared there
    for (int a = model.links()[static_cast<size_t>(joint.parent_link)].parent_joint; a >= 0;
         a = model.links()[static_cast<size_t>(model.joints()[static_cast<size_t>(a)].parent_link)]
                 .parent_joint) {
      above = above || changed(static_cast<size_t>(a));
    }
    if (above) continue;
    // Scored on the scan without the coverings and on the scan with them
    // (their shape still tells a wrist's cover): the value without them is
    // told when either prefers it.
    const double gain =
        chain.BranchGain(result->T_world_base, result->q, q_first, joint.child_link);
    const double covered_gain =
        -chain.CoveredMargin(result->T_world_base, result->q, q_first, joint.child_link);
    const double margin = options.chain.ambiguity_mean_loss;
    const bool told = gain < -margin || covered_gain < -margin;
    char line[400];
    std::snprintf(line, sizeof(line),
                  "coverings: %s = %.4f without them, %.4f with them; the first fits %.3f "
                  "mm/sample %s on the scan without them, %.3f mm/sample %s on the scan with "
                  "them%s",
                  joint.name.c_str(), result->q[j], q_first[j], 1e3 * std::abs(gain),
                  gain < 0.0 ? "better" : "worse", 1e3 * std::abs(covered_gain),
                  covered_gain < 0.0 ? "better" : "worse", told ? "" : ": AMBIGUOUS");
    say(line);
    if (told) continue;
    for (BodyQuality& body : result->bodies) {
      if (body.joint != joint.name) continue;
      body.ambiguous = true;
      body.ok = false;
      if (body.verdict == JointVerdict::kOk) body.verdict = JointVerdict::kAmbiguous;
      std::snprintf(line, sizeof(line),
                    "coverings (jackets, covers) hide much of the arm: %s = %.4f without them "
                    "and %.4f with them; the scan cannot tell which",
                    joint.name.c_str(), result->q[j], q_first[j]);
      result->message += (result->ok ? "" : "; ") + std::string(line);
      result->ok = false;
    }
  }
}

}  // namespace edgefit
