// The quality verdict of every body at the final values (stages.h).
#include <cmath>
#include <cstdio>

#include "stages.h"

namespace edgefit {

BodyQuality Quality(const KinematicModel& model, const Body& body, const SurfaceSamples& samples,
                    const WeightedIcpSummary& summary, const QualityOptions& options) {
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

Status JudgeQuality(const KinematicModel& model, WeightedIcp* icp, const CadSamples& cad,
                    const std::vector<JointRecord>& records, const Status& resolved,
                    const FitOptions& options, FitResult* result) {
  WeightedIcpSummary summary;
  const std::vector<Pose> T_world_link = model.ForwardKinematics(result->q, result->T_world_base);
  for (const JointRecord& record : records) {
    const Body body =
        MakeBody(model, model.joints()[static_cast<size_t>(record.joint)].child_link, record.joint);
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
    quality.ok = quality.ok && !quality.ambiguous;
    result->bodies.push_back(quality);
  }

  result->ok = resolved.ok();
  if (!resolved.ok()) result->message = resolved.message();
  for (const BodyQuality& b : result->bodies) {
    if (b.ok || !result->ok) continue;
    result->ok = false;
    char line[512];
    if (b.better_elsewhere) {
      std::snprintf(line, sizeof(line),
                    "%s is in a wrong basin: %s = %.4f, with the joints below it fitted again "
                    "there, fits the scan better than the reported %.4f (Eq. 9 loss %.3f mm lower "
                    "per sample)",
                    b.link.c_str(), b.joint.c_str(), b.alternative_value,
                    result->q[static_cast<size_t>(model.JointIndex(b.joint))],
                    1e3 * b.ambiguity_margin);
    } else if (b.ambiguous && DecidedByCoverings(b.covered_margin, options.chain)) {
      std::snprintf(line, sizeof(line),
                    "%s is ambiguous: %s = %.4f fits the scan better without the parts found "
                    "covered (Eq. 9 loss %.3f mm lower per sample), %.4f with them (%.3f mm "
                    "lower); the coverings were found at the first estimate and may hide either "
                    "value's surfaces",
                    b.link.c_str(), b.joint.c_str(),
                    result->q[static_cast<size_t>(model.JointIndex(b.joint))],
                    1e3 * b.ambiguity_margin, b.alternative_value, -1e3 * b.covered_margin);
    } else if (b.ambiguous) {
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
                    b.link.c_str(), 100.0 * b.inlier_share,
                    1e3 * options.chain.joint_icp.final_gate,
                    100.0 * options.quality.min_inlier_share, 1e3 * b.rms);
    }
    result->message = line;
  }
  return Status::Ok();
}

void MarkBasinChanges(const KinematicModel& model, const ChainFitter& chain,
                      const std::vector<double>& q_first, const FitOptions& options,
                      const ProgressFn& say, FitResult* result) {
  auto changed = [&](size_t j) {
    const Joint& joint = model.joints()[j];
    return joint.IsIndependent() && joint.type != JointType::kPrismatic &&
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
    }
    if (result->ok || result->message.empty()) {
      std::snprintf(line, sizeof(line),
                    "coverings (jackets, covers) hide much of the arm: %s = %.4f without them "
                    "and %.4f with them; the scan cannot tell which",
                    joint.name.c_str(), result->q[j], q_first[j]);
      result->message = line;
    }
    result->ok = false;
  }
}

}  // namespace edgefit
