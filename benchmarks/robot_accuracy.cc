// Fit accuracy against the virtual scanner's ground truth (paper Sec. 7.3),
// for robots and conveyance systems (--kind): named postures and seeded random
// ones, each on a random base pose, scanned with and without accessories, fitted with edge and/or
// uniform weights. Prints a row per fit, then per configuration the joint
// errors (mean, 95th percentile, max), the base errors, failed fits (a
// revolute joint off by more than 0.5 degrees or a prismatic one by more
// than 5 mm) and confident wrong answers (failed, yet quality.ok).
//
//   robot_accuracy --urdf=assets/robot/robot.urdf
//       --attach=assets/robot/weld_gun.urdf@tool0
//       --postures=assets/robot/postures.json --random=20
//       [--accessories=without,with] [--weighting=edge,uniform]
//       [--spacing_mm=1.7] [--noise_mm=1] [--scanners=3] [--seed=1]
//       [--csv=F.csv]   (one line per fitted joint)
//   robot_accuracy --urdf=assets/conveyor/conveyor.urdf
//       --postures=assets/conveyor/postures.json --spacing_mm=3   (kind: auto)
// A random posture that buries a link with a mesh inside others (a
// self-collision: the generator does not check them) is redrawn
// (RandomPostureCases).
#include <gflags/gflags.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "edgefit/bench/bench_case.h"
#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/truth.h"

DEFINE_string(urdf, "", "The robot's URDF.");
DEFINE_string(attach, "", "End effectors: EEF.urdf@parent_link[,...].");
DEFINE_string(postures, "", "A postures file: every posture in it is fitted.");
DEFINE_int32(random, 20, "Random postures (RandomJointValuesAboveFloor) after the named ones.");
DEFINE_string(accessories, "without,with", "Scenes: without and/or with accessories.");
DEFINE_string(weighting, "edge,uniform", "Fits: edge and/or uniform weights.");
DEFINE_string(kind, "auto", "auto | articulated | conveyance (edgefit fit --kind).");
DEFINE_int32(base_alternatives, -1,
             "BaseHypothesesOptions::alternatives (-1: the kind's default, FitOptionsFor).");
DEFINE_string(parameterization, "joint_space",
              "Joint constraint of the precise ICPs: joint_space or pose_penalty (Eq. 10 / 14).");
DEFINE_string(refine_chain, "on",
              "Fits: without (off) and/or with (on) the whole-chain refinement (--refine_chain).");
DEFINE_int32(max_chain_samples, -1, "CadSampleOptions::max_chain_samples (-1: the default).");
DEFINE_double(w_high, 10.0, "Eq. (6): weight of points in valid edge regions (edge fits).");
DEFINE_string(icp_visibility, "seen",
              "Which CAD samples the ICPs use (WeightedIcpOptions::visibility): seen (facing a "
              "scanner and not behind the scan), facing (facing a scanner) or all.");
DEFINE_double(spacing_mm, 1.7, "Scan point spacing at the asset [mm].");
DEFINE_double(noise_mm, 1.0, "Range noise sigma [mm].");
DEFINE_int32(scanners, 3, "Scanners around the robot.");
DEFINE_double(base_range_m, 1.0, "Random base x, y in [-r, r] [m]; yaw uniform.");
DEFINE_uint64(seed, 1, "Seed of postures, base poses and scenes.");
DEFINE_string(csv, "", "Optional: one line per fitted joint.");
DEFINE_string(only, "", "Optional: fit only these cases (names, comma-separated).");
DEFINE_bool(progress, false, "Print the fit's progress lines (stderr).");

namespace edgefit {
namespace {

using Case = BenchCase;

struct FitRecord {
  std::string case_name;
  FitErrors errors;
  FitTimings timings;
  size_t points = 0;
  bool quality_ok = false;
  bool failed = false;
  std::string message;
};

std::vector<std::string> Split(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

WeightedIcpOptions::Visibility IcpVisibility(const std::string& name) {
  if (name == "all") return WeightedIcpOptions::Visibility::kAll;
  if (name == "facing") return WeightedIcpOptions::Visibility::kFacing;
  CHECK(name == "seen") << "--icp_visibility: seen, facing or all, not '" << name << "'";
  return WeightedIcpOptions::Visibility::kSeen;
}

// The scan of a case, as the flags set it.
AssetScanOptions CaseScanOptions(const Case& c, bool accessories) {
  AssetScanOptions options;
  options.accessories = accessories;
  options.scanners = FLAGS_scanners;
  options.scan.spacing = 1e-3 * FLAGS_spacing_mm;
  options.scan.noise_sigma = 1e-3 * FLAGS_noise_mm;
  options.seed = c.seed;
  return options;
}

// Named postures, then the random ones (RandomPostureCases: streams 1000..,
// so --only and --postures do not change the other cases).
std::vector<Case> MakeCases(const KinematicModel& model) {
  std::vector<Case> cases;
  if (!FLAGS_postures.empty()) {
    const Status s =
        NamedPostureCases(model, FLAGS_postures, FLAGS_seed, FLAGS_base_range_m, &cases);
    CHECK(s.ok()) << s.message();
  }
  const Status s = RandomPostureCases(
      model, FLAGS_random, FLAGS_seed, FLAGS_base_range_m, &cases,
      [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
  CHECK(s.ok()) << s.message();
  return cases;
}

void PrintSummary(const std::string& config, const std::vector<FitRecord>& records) {
  std::vector<double> revolute, prismatic, base_t, base_r, tip, total;
  std::map<std::string, std::vector<double>> per_joint;
  std::vector<std::string> joint_order;
  int failed = 0, not_ok = 0, confident_wrong = 0;
  for (const FitRecord& r : records) {
    for (const JointError& e : r.errors.joints) {
      if (!e.independent) continue;
      (e.prismatic ? prismatic : revolute).push_back(e.prismatic ? 1e3 * e.error : e.error / kDeg);
      if (per_joint.count(e.name) == 0) joint_order.push_back(e.name);
      per_joint[e.name].push_back(e.prismatic ? 1e3 * e.error : e.error / kDeg);
    }
    base_t.push_back(1e3 * r.errors.base_translation);
    tip.push_back(1e3 * r.errors.tool_tip);
    base_r.push_back(r.errors.base_rotation / kDeg);
    total.push_back(r.timings.total);
    failed += r.failed;
    not_ok += !r.quality_ok;
    confident_wrong += r.failed && r.quality_ok;
  }
  const ErrorStats rev = SummarizeErrors(revolute), pri = SummarizeErrors(prismatic);
  const ErrorStats bt = SummarizeErrors(base_t), br = SummarizeErrors(base_r);
  const ErrorStats tp = SummarizeErrors(tip);
  std::printf("\n### %s: %zu fits\n\n", config.c_str(), records.size());
  std::printf(
      "| revolute mean | p95 | max | prismatic mean | p95 | max | base mean | base max | "
      "base rot mean | max | tool tip mean | p95 | failed | not ok | failed yet ok | mean time "
      "|\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf(
      "| %.4f° | %.4f° | %.4f° | %.3f mm | %.3f mm | %.3f mm | %.3f mm | %.3f mm | %.4f° | %.4f° | "
      "%.3f mm | %.3f mm | %d | %d | %d | %.1f s |\n",
      rev.mean, rev.p95, rev.max, pri.mean, pri.p95, pri.max, bt.mean, bt.max, br.mean, br.max,
      tp.mean, tp.p95, failed, not_ok, confident_wrong, SummarizeErrors(total).mean);
  std::printf("\n| joint | mean | p95 | max |\n|---|---|---|---|\n");
  for (const std::string& name : joint_order) {
    const ErrorStats stats = SummarizeErrors(per_joint[name]);
    std::printf("| %s | %.4f | %.4f | %.4f |\n", name.c_str(), stats.mean, stats.p95, stats.max);
  }
  std::fflush(stdout);
}

int Run() {
  CHECK(!FLAGS_urdf.empty()) << "--urdf is required";
  std::vector<AttachSpec> specs;
  Status status = ParseAttachSpecList(FLAGS_attach, &specs);
  CHECK(status.ok()) << status.message();
  KinematicModel model;
  status = LoadModelWithAttachments(FLAGS_urdf, specs, ModelLoadOptions(), &model);
  CHECK(status.ok()) << status.message();
  AssetKind kind = AssetKind::kArticulated;
  status = ChooseAssetKind(FLAGS_kind, model, &kind);
  CHECK(status.ok()) << status.message();
  std::printf("kind: %s\n", AssetKindName(kind));
  const std::vector<Case> cases = MakeCases(model);

  std::ofstream csv;
  if (!FLAGS_csv.empty()) {
    csv.open(FLAGS_csv);
    CHECK(csv) << FLAGS_csv;
    csv << "accessories,weighting,case,joint,prismatic,truth,fit,error,quality_ok,total_s\n";
  }
  std::vector<std::pair<std::string, bool>> configs;  // weighting, refine_chain
  for (const std::string& weighting : Split(FLAGS_weighting)) {
    CHECK(weighting == "edge" || weighting == "uniform") << weighting;
    for (const std::string& refine : Split(FLAGS_refine_chain)) {
      CHECK(refine == "on" || refine == "off") << refine;
      configs.emplace_back(weighting, refine == "on");
    }
  }
  for (const std::string& accessories : Split(FLAGS_accessories)) {
    CHECK(accessories == "with" || accessories == "without") << accessories;
    std::map<std::string, std::vector<FitRecord>> records;  // by weighting
    std::printf(
        "\n## %s accessories\n\n| case | weighting | points | max joint error | base "
        "| ok | weakest body (inliers, RMS) | time (edges, base rough+precise, chain) "
        "|\n|---|---|---|---|---|---|---|---|\n",
        accessories.c_str());
    const std::vector<std::string> only = Split(FLAGS_only);
    for (const Case& c : cases) {
      if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
      VirtualScan scan;
      status = ScanAsset(model, c.q, c.T_world_base, CaseScanOptions(c, accessories == "with"),
                         &scan, nullptr);
      CHECK(status.ok()) << status.message();
      for (const auto& [weighting, refine] : configs) {
        const std::string config = refine ? weighting + ", refine_chain" : weighting;
        FitOptions options = FitOptionsFor(kind);
        options.refinement.chain.refine = refine;
        if (FLAGS_max_chain_samples > 0)
          options.samples.max_chain_samples = FLAGS_max_chain_samples;
        options.uniform_weights = weighting == "uniform";
        options.edges.w_high = FLAGS_w_high;
        status =
            ParseJointParameterization(FLAGS_parameterization, &options.residuals.parameterization);
        CHECK(status.ok()) << status.message();
        if (FLAGS_base_alternatives >= 0) {
          options.base.hypotheses.alternatives = FLAGS_base_alternatives;
        }
        options.base.icp.visibility = options.chain.joint_icp.visibility =
            options.chain.subtree_icp.visibility = IcpVisibility(FLAGS_icp_visibility);
        ProgressFn progress;
        if (FLAGS_progress)
          progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
        BenchResult fit;
        status = FitBenchCase(model, c, scan.scans, Pose::Identity(), options, &fit, progress);
        CHECK(status.ok()) << c.name << ": " << status.message();
        FitRecord record;
        record.case_name = c.name;
        record.timings = fit.timings;
        record.points = fit.points;
        record.quality_ok = fit.ok;
        record.message = fit.message;
        record.errors = fit.errors;
        record.failed = fit.failed;
        double worst[2] = {0.0, 0.0};  // revolute [deg], prismatic [mm]
        std::string worst_name[2];
        for (const JointError& e : record.errors.joints) {
          if (!e.independent) continue;
          const double deg_or_mm = e.prismatic ? 1e3 * e.error : e.error / kDeg;
          if (deg_or_mm > worst[e.prismatic]) {
            worst[e.prismatic] = deg_or_mm;
            worst_name[e.prismatic] = e.name;
          }
          if (csv) {
            csv << accessories << ',' << config << ',' << c.name << ',' << e.name << ','
                << e.prismatic << ',' << e.truth << ',' << e.fit << ',' << e.error << ',' << fit.ok
                << ',' << fit.timings.total << '\n';
          }
        }
        if (csv) csv.flush();  // a long run's rows are usable as they come
        const BodyQuality* weakest = nullptr;
        for (const BodyQuality& b : fit.bodies) {
          if (weakest == nullptr || b.inlier_share < weakest->inlier_share) weakest = &b;
        }
        // A fit that stopped before its bodies (no base found) has no weakest body.
        char weakest_text[256] = "none";
        if (weakest != nullptr) {
          std::snprintf(weakest_text, sizeof(weakest_text), "%.0f%% %s, %.2f mm",
                        100.0 * weakest->inlier_share, weakest->link.c_str(), 1e3 * weakest->rms);
        }
        char worst_text[160];
        if (worst_name[1].empty() || !worst_name[0].empty()) {
          std::snprintf(worst_text, sizeof(worst_text), "%.4f° (%s)", worst[0],
                        worst_name[0].c_str());
        }
        if (!worst_name[1].empty()) {  // a prismatic joint too, or only those
          const std::string revolute = worst_name[0].empty() ? "" : worst_text + std::string(", ");
          std::snprintf(worst_text, sizeof(worst_text), "%s%.3f mm (%s)", revolute.c_str(),
                        worst[1], worst_name[1].c_str());
        }
        std::printf(
            "| %s | %s | %.2f M | %s%s | %.3f mm / %.4f° | %s | %s | %.1f s (%.1f, "
            "%.1f+%.1f, %.1f) |\n",
            c.name.c_str(), config.c_str(), 1e-6 * static_cast<double>(record.points), worst_text,
            record.failed ? " FAILED" : "", 1e3 * record.errors.base_translation,
            record.errors.base_rotation / kDeg, fit.ok ? "ok" : ("not ok: " + fit.message).c_str(),
            weakest_text, fit.timings.total, fit.timings.edges, fit.timings.base_rough,
            fit.timings.base_precise, fit.timings.chain);
        std::fflush(stdout);
        records[config].push_back(record);
      }
    }
    for (const auto& [weighting, list] : records) {
      PrintSummary(accessories + " accessories, " + weighting + " weights", list);
    }
  }
  return 0;
}

}  // namespace
}  // namespace edgefit

int main(int argc, char** argv) {
  gflags::SetUsageMessage("robot fit accuracy against the virtual scanner's truth");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  FLAGS_logtostderr = true;
  return edgefit::Run();
}
