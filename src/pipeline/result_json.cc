#include "edgefit/pipeline/result_json.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace edgefit {
namespace {

using nlohmann::json;

json NumberOrNull(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

// quality.base_rough: the method that gave the rough pose and what it found.
json BaseRoughJson(const FitResult& fit) {
  if (fit.base_rough_method == BaseOptions::Method::kArmTips) {
    return {{"method", "arm_tips"},
            {"floor_z", fit.arm_tips.floor_z},
            {"convex_scan_tips", fit.arm_tips.convex_scan_tips},
            {"scan_tips", fit.arm_tips.scan_tips.size()},
            {"symmetric_scan_tips", fit.arm_tips.symmetric_scan_tips},
            {"model_tips", fit.arm_tips.model_tips.size()},
            {"matches", fit.arm_tips.matches},
            {"poses_scored", fit.arm_tips.scored}};
  }
  return {{"method", "cross_sections"},
          {"floor_z", fit.base_rough.floor_z},
          {"scan_corners", fit.base_rough.scan_corners},
          {"model_corners", fit.base_rough.model_corners},
          {"hypotheses", fit.base_rough.hypotheses},
          {"inlier_share", fit.base_rough.inlier_share}};
}

json PerLinkJson(const FitResult& fit) {
  json per_link = json::object();
  for (const BodyQuality& b : fit.bodies) {
    per_link[b.link] = {{"joint", b.joint},
                        {"samples", b.samples},
                        {"visible", b.visible},
                        {"occluded", b.occluded},
                        {"inlier_share", b.inlier_share},
                        {"rms_m", b.rms},
                        {"symmetric", b.symmetric},
                        {"icp_iterations", b.icp_iterations},
                        {"verdict", JointVerdictName(b.verdict)},
                        {"ok", b.ok}};
    if (!b.joint.empty()) per_link[b.link]["sweep_value"] = b.sweep_value;
    if (std::isfinite(b.turned_off_share)) {
      per_link[b.link]["turned_off_share"] = b.turned_off_share;
    }
    per_link[b.link]["ambiguous"] = b.ambiguous;
    per_link[b.link]["better_elsewhere"] = b.better_elsewhere;
    if (std::isfinite(b.ambiguity_margin)) {  // an alternative value was fitted and compared
      per_link[b.link]["alternative_value"] = b.alternative_value;
      per_link[b.link]["alternative_margin_m"] = b.ambiguity_margin;
      if (std::isfinite(b.covered_margin)) {
        per_link[b.link]["alternative_covered_margin_m"] = b.covered_margin;
      }
    }
  }
  return per_link;
}

// joint_status: per independent joint its verdict, why, its standard
// deviation (joint_std's; null when unobservable) and the other values the
// scan or the geometry leaves open; not_seen for every joint of a fit that
// stopped before the joints (no body judged).
json JointStatusJson(const KinematicModel& model, const FitResult& fit, const json& joint_std) {
  json verdicts = json::object();
  for (const BodyQuality& b : fit.bodies) {
    if (b.joint.empty()) continue;
    json v = {{"verdict", JointVerdictName(b.verdict)}, {"link", b.link}};
    json alternatives = json::array();
    switch (b.verdict) {
      case JointVerdict::kUnobservable:
        if (fit.base_symmetry.round &&
            model.joints()[static_cast<size_t>(fit.base_symmetry.joint)].name == b.joint) {
          v["reason"] = "the base is round about its axis: its yaw and " + b.joint +
                        " are one rotation, which no scan splits; reported at 0, the base "
                        "turned to match";
          break;
        }
        v["reason"] = "the geometry it moves looks the same at every value (turned, at most " +
                      std::to_string(static_cast<int>(std::ceil(100.0 * b.turned_off_share))) +
                      "% of its samples leave the surface); reported at its zero or the limit "
                      "nearest it";
        break;
      case JointVerdict::kAmbiguous:
        v["reason"] = b.unpinned         ? "not pinned: its standard deviation is above the bar"
                      : b.chain_unmatched ? "a body between the base and it does not match the scan"
                      : b.partner_torn
                          ? "the joint swept with it has two values that fit about as well"
                      : b.better_elsewhere ? "another value fits the scan better"
                                           : "another value fits the scan about as well";
        if (!b.unpinned && !b.chain_unmatched && !b.partner_torn) {
          alternatives.push_back({{"value", b.alternative_value},
                                  {"loss_margin_m", NumberOrNull(b.ambiguity_margin)}});
        }
        if (!b.unpinned && !b.chain_unmatched && b.partner_torn) v["partner"] = b.torn_partner;
        break;
      case JointVerdict::kNotSeen:
        v["reason"] = "too few of its samples are visible at the fitted pose";
        break;
      case JointVerdict::kMismatch:
        v["reason"] = "its body does not match the scan";
        break;
      case JointVerdict::kGiven:
        v["reason"] = "held at the value given (known joints), not fitted";
        break;
      case JointVerdict::kOk:
        break;
    }
    for (const double turn : b.whole_turns) {
      alternatives.push_back({{"value", turn}, {"loss_margin_m", 0.0}, {"whole_turn", true}});
    }
    if (!b.whole_turns.empty()) {
      v["convention"] = "of the values a whole turn apart within " + b.joint +
                        "'s limits (the same geometry), the one nearest zero is reported";
    }
    const BaseSymmetry& symmetry = fit.base_symmetry;
    if (symmetry.joint >= 0 &&
        model.joints()[static_cast<size_t>(symmetry.joint)].name == b.joint) {
      const double q = fit.q[static_cast<size_t>(symmetry.joint)];
      std::string turns;
      for (const double t : symmetry.round ? std::vector<double>() : symmetry.turns) {
        const int degrees = static_cast<int>(std::lround(t * 180.0 / M_PI));
        turns += (turns.empty() ? "" : ", ") + std::to_string(degrees);
        alternatives.push_back({{"value", std::remainder(q + t, 2.0 * M_PI)},
                                {"loss_margin_m", 0.0},
                                {"base_turn_deg", -degrees}});
      }
      v["convention"] = "the base looks the same turned by " +
                        (symmetry.round ? std::string("any angle") : turns + " deg") + " about " +
                        b.joint +
                        "'s axis, so no scan tells the base's yaw from " + b.joint +
                        ": of those placements the one with " + b.joint +
                        " nearest zero is reported";
    }
    v["std"] = joint_std.contains(b.joint) ? joint_std[b.joint] : json(nullptr);
    v["alternatives"] = alternatives;
    verdicts[b.joint] = v;
  }
  for (const Joint& j : model.joints()) {  // a fit that stopped before the joints
    if (!j.IsIndependent() || verdicts.contains(j.name)) continue;
    verdicts[j.name] = {{"verdict", JointVerdictName(JointVerdict::kNotSeen)},
                        {"link", model.links()[static_cast<size_t>(j.child_link)].name},
                        {"reason", "not fitted: the fit stopped before the joints"},
                        {"std", nullptr},
                        {"alternatives", json::array()}};
  }
  return verdicts;
}

}  // namespace

json FitResultJson(const KinematicModel& model, AssetKind kind, const FitOptions& options,
                   const FitResult& fit) {
  const Eigen::Vector3d rpy = RpyFromRotation(fit.T_world_base.linear());
  const Eigen::Vector3d xyz = fit.T_world_base.translation();
  json joints = json::object(), joint_types = json::object();
  json joint_std = json::object();            // chain_refinement.h; null: not determined
  json joint_std_residuals = json::object();  // the residuals' part alone: lower bounds
  const ChainRefinementSummary& chain = fit.chain_refinement;
  for (size_t j = 0; j < model.joints().size(); ++j) {
    if (model.joints()[j].IsMoving()) {
      joints[model.joints()[j].name] = fit.q[j];
      joint_types[model.joints()[j].name] = JointTypeName(model.joints()[j].type);
    }
    if (model.joints()[j].IsIndependent()) {  // none when the fit stopped before the chain
      joint_std[model.joints()[j].name] =
          j < chain.joint_std.size() ? NumberOrNull(chain.joint_std[j]) : json(nullptr);
      joint_std_residuals[model.joints()[j].name] = j < chain.joint_std_residuals.size()
                                                        ? NumberOrNull(chain.joint_std_residuals[j])
                                                        : json(nullptr);
    }
  }
  for (const BodyQuality& b : fit.bodies) {  // no spread for what no scan decides
    if (b.verdict != JointVerdict::kUnobservable) continue;
    joint_std[b.joint] = nullptr;
    joint_std_residuals[b.joint] = nullptr;
  }
  const bool refined = options.refinement.chain.refine;
  json covered_links = json::object();
  const CoveringSummary& coverings = fit.coverings;
  for (size_t l = 0; l < coverings.link_covered.size(); ++l) {
    if (coverings.link_covered[l] == 0) continue;
    covered_links[model.links()[l].name] = {{"matched", coverings.link_matched[l]},
                                            {"covered", coverings.link_covered[l]},
                                            {"share", coverings.Share(l)}};
  }
  json left_out = json::array();
  for (size_t l = 0; l < fit.stations.links_left_out.size(); ++l) {
    if (fit.stations.links_left_out[l]) left_out.push_back(model.links()[l].name);
  }
  json stations = json::array();
  for (const StationCorrection& c : fit.stations.stations) {
    stations.push_back({{"correction_m", c.translation},
                        {"correction_rad", c.rotation},
                        {"matches", c.matches},
                        {"rms_before_m", c.rms_before},
                        {"rms_after_m", c.rms_after},
                        {"T_correction", PoseRows(c.correction)}});
  }
  return {{"kind", AssetKindName(kind)},
          {"base",
           {{"xyz", {xyz.x(), xyz.y(), xyz.z()}},
            {"rpy", {rpy.x(), rpy.y(), rpy.z()}},
            {"T_world_base", PoseRows(fit.T_world_base)}}},
          {"joints", joints},
          {"joint_types", joint_types},
          {"joint_std", joint_std},
          {"joint_status", JointStatusJson(model, fit, joint_std)},
          {"base_std", BaseStdJson(chain)},
          {"stations",
           {{"aligned", !fit.stations.stations.empty()},
            {"rounds", fit.stations.rounds},
            {"links_left_out", left_out},
            {"corrections", stations}}},
          {"timing_s", FitTimingsJson(fit.timings)},
          {"mixed_pixels_removed", fit.mixed_pixels},
          {"noise", {{"sigma_m", fit.noise_sigma}, {"scale", fit.noise_scale}}},
          {"up",
           {{"vector", {fit.up.x(), fit.up.y(), fit.up.z()}},
            {"from", fit.up_from},
            {"plane_share", fit.up_plane_share}}},
          {"coverings",
           {{"matched", coverings.matched},
            {"covered", coverings.covered},
            {"per_link", covered_links}}},
          {"quality",
           {{"per_link", PerLinkJson(fit)},
            {"ok", fit.ok},
            {"message", fit.message},
            {"base_rough", BaseRoughJson(fit)},
            {"chain_refinement",
             {{"refined", refined},
              {"iterations", chain.iterations},
              {"stop_reason", IcpStopReasonName(chain.stop_reason)},
              {"max_displacement_m", chain.max_displacement},
              {"correspondences", chain.correspondences},
              {"sigma_m", chain.sigma},
              {"joint_std_residuals", joint_std_residuals},
              {"covariance_ok", chain.covariance_ok}}}}},
          {"options", FitOptionsJson(options)},
          {"threads", omp_get_max_threads()}};
}

json FitOptionsJson(const FitOptions& options) {
  return {{"weighting", options.uniform_weights ? "uniform" : "edge"},
          {"w_high", options.edges.w_high},
          {"loss", options.residuals.loss},
          {"lambda", options.residuals.lambda},
          {"parameterization", JointParameterizationName(options.residuals.parameterization)},
          {"refine_chain", options.refinement.chain.refine},
          {"align_stations", options.stations.align},
          {"station_rounds", options.stations.rounds},
          {"station_max_covered_share", options.stations.max_covered_share},
          {"covering_rounds", options.refinement.coverings.rounds},
          {"pair_sweep_step_rad", options.chain.pair_sweep_step},
          {"visibility_tolerance_m", options.refinement.chain.visibility_tolerance},
          {"cad_deviation_m", options.refinement.chain.cad_deviation},
          {"cad_deviation_patch_m", options.refinement.chain.cad_deviation_patch},
          {"incidence_cosine", options.refinement.chain.incidence_cosine},
          {"remove_mixed_pixels", options.remove_mixed_pixels},
          {"refine_without_mixed_pixels",
           options.refine_without_mixed_pixels && !options.remove_mixed_pixels},
          {"mixed_pixels",
           {{"tolerance_m", options.mixed_pixels.tolerance},
            {"tolerance_per_spacing", options.mixed_pixels.tolerance_per_spacing},
            {"min_lines", options.mixed_pixels.min_lines},
            {"neighbour_lines", options.mixed_pixels.neighbour_lines}}},
          {"seed", options.seed}};
}

json FitTimingsJson(const FitTimings& timings) {
  return {{"edges", timings.edges},
          {"stations", timings.stations},
          {"base_rough", timings.base_rough},
          {"base_precise", timings.base_precise},
          {"chain", timings.chain},
          {"refine", timings.refine},
          {"alternatives", timings.alternatives},
          {"mixed_pixels", timings.mixed_pixels}};
}

json BaseStdJson(const ChainRefinementSummary& chain) {
  json base_std = {{"rotation_rad", json::array()}, {"xyz_m", json::array()}};
  for (int i = 0; i < 3; ++i) {
    base_std["rotation_rad"].push_back(NumberOrNull(chain.base_rotation_std[i]));
    base_std["xyz_m"].push_back(NumberOrNull(chain.base_translation_std[i]));
  }
  return base_std;
}

}  // namespace edgefit
