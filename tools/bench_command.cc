// edgefit bench: the paper's evaluation (Sec. 7.3-7.4) in one command. The
// bundled robot (with its weld gun) and conveyor, each in its named
// postures, scanned without and with accessories and fitted with uniform and
// edge weights: Table 1 (rotation error per joint, degrees) and Table 2
// (translation error per joint, mm), then base errors and the time per
// stage, as Markdown on stdout; optionally one CSV line per joint and a JSON
// file of every run.
//   edgefit bench [--assets=robot,conveyor] [--scenes=without,with]
//                 [--weighting=uniform,edge] [--spacing_mm=1.7] [--noise_mm=1]
//                 [--scanners=3] [--seed=1] [--w_high=10] [--only=POSTURE,...]
//                 [--out_csv=F.csv] [--out_json=F.json]
#include <gflags/gflags.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/model/composition.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/bench_case.h"

DEFINE_string(assets, "robot,conveyor", "Bench: robot and/or conveyor.");
DEFINE_string(robot_urdf, "assets/robot/robot.urdf", "Bench: the robot's URDF.");
DEFINE_string(robot_attach, "assets/robot/weld_gun.urdf@tool0",
              "Bench: the robot's end effectors (as --attach).");
DEFINE_string(robot_postures, "assets/robot/postures.json", "Bench: the robot's postures.");
DEFINE_string(conveyor_urdf, "assets/conveyor/conveyor.urdf", "Bench: the conveyor's URDF.");
DEFINE_string(conveyor_postures, "assets/conveyor/postures.json",
              "Bench: the conveyor's postures.");
DEFINE_string(scenes, "without,with", "Bench: scenes without and/or with accessories.");
DEFINE_string(weightings, "uniform,edge", "Bench: fits with uniform and/or edge weights.");
DEFINE_string(only, "", "Bench: only these postures (names, comma-separated).");
DEFINE_double(base_range_m, 1.0, "Bench: random base x, y in [-r, r] [m]; yaw uniform.");
DEFINE_string(out_csv, "", "Bench: optional CSV, one line per fitted joint.");
DECLARE_string(out_json);  // edges_command.cc; bench: the JSON of every run
DECLARE_double(spacing_mm);
DECLARE_double(noise_mm);
DECLARE_int32(scanners);

namespace edgefit::tools {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct Run {
  std::string asset, posture, accessories, weighting;
  BenchResult result;
};

// Table 1 or 2 for one asset: a row per run, a column per joint of the kind.
void PrintJointTable(const std::vector<Run>& runs, const std::string& asset, bool prismatic) {
  std::vector<std::string> joints;
  for (const Run& run : runs) {
    if (run.asset != asset) continue;
    for (const JointError& e : run.result.errors.joints) {
      if (e.independent && e.prismatic == prismatic &&
          std::find(joints.begin(), joints.end(), e.name) == joints.end()) {
        joints.push_back(e.name);
      }
    }
  }
  if (joints.empty()) return;
  std::printf("\n%s (%s):\n\n| posture | accessories | weights |", asset.c_str(),
              prismatic ? "mm" : "degrees");
  for (const std::string& j : joints) std::printf(" %s |", j.c_str());
  std::printf("\n|---|---|---|");
  for (size_t k = 0; k < joints.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (const Run& run : runs) {
    if (run.asset != asset) continue;
    std::printf("| %s | %s | %s |", run.posture.c_str(), run.accessories.c_str(),
                run.weighting.c_str());
    for (const std::string& j : joints) {
      for (const JointError& e : run.result.errors.joints) {
        if (e.name == j) std::printf(" %.4f |", prismatic ? 1e3 * e.error : e.error / kDeg);
      }
    }
    std::printf("\n");
  }
}

int RunBench(const Command& command) {
  const std::vector<std::string> assets = SplitList(FLAGS_assets);
  const std::vector<std::string> sceneries = SplitList(FLAGS_scenes);
  const std::vector<std::string> weightings = SplitList(FLAGS_weightings);
  const std::vector<std::string> only = SplitList(FLAGS_only);
  for (const std::string& a : assets) {
    if (a != "robot" && a != "conveyor") return BadInput(command, "--assets: robot, conveyor");
  }
  for (const std::string& a : sceneries) {
    if (a != "with" && a != "without") return BadInput(command, "--scenes: without, with");
  }
  for (const std::string& w : weightings) {
    if (w != "uniform" && w != "edge") return BadInput(command, "--weightings: uniform, edge");
  }
  if (!(FLAGS_spacing_mm > 0.0) || !(FLAGS_noise_mm >= 0.0) || FLAGS_scanners < 1) {
    return BadInput(command, "--spacing_mm must be > 0, --noise_mm >= 0, --scanners >= 1");
  }
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);

  std::vector<Run> runs;
  for (const std::string& asset : assets) {
    const bool robot = asset == "robot";
    std::vector<AttachSpec> specs;
    if (robot)
      EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseAttachSpecList(FLAGS_robot_attach, &specs));
    KinematicModel model;
    EDGEFIT_RETURN_IF_ERROR_EXIT(
        command, LoadModelWithAttachments(robot ? FLAGS_robot_urdf : FLAGS_conveyor_urdf, specs,
                                          ModelLoadOptions(), &model));
    std::vector<BenchCase> cases;
    EDGEFIT_RETURN_IF_ERROR_EXIT(
        command, NamedPostureCases(model, robot ? FLAGS_robot_postures : FLAGS_conveyor_postures,
                                   FLAGS_seed, FLAGS_base_range_m, &cases));
    AssetKind kind = AssetKind::kArticulated;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ChooseAssetKind("auto", model, &kind));
    for (const BenchCase& c : cases) {
      if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
      for (const std::string& scenery : sceneries) {
        AssetScanOptions scan_options;
        scan_options.accessories = scenery == "with";
        scan_options.scanners = FLAGS_scanners;
        scan_options.scan.spacing = 1e-3 * FLAGS_spacing_mm;
        scan_options.scan.noise_sigma = 1e-3 * FLAGS_noise_mm;
        Progress("bench: scanning " + asset + " " + c.name + ", " + scenery + " accessories");
        VirtualScan scan;
        EDGEFIT_RETURN_IF_ERROR_EXIT(command, ScanBenchCase(model, c, scan_options, &scan));
        for (const std::string& weighting : weightings) {
          RobotFitOptions options = FitOptionsFor(kind);
          options.uniform_weights = weighting == "uniform";
          options.edges.w_high = FLAGS_w_high;
          options.seed = FLAGS_seed;
          Run run{asset, c.name, scenery, weighting, {}};
          Progress("bench: " + asset + " " + c.name + ", " + scenery + " accessories, " +
                   weighting + " weights");
          EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                                       FitBenchCase(model, c, scan.scans, options, &run.result));
          runs.push_back(std::move(run));
        }
      }
    }
  }

  std::printf("## Table 1: rotation error per joint [deg]\n");
  for (const std::string& asset : assets) PrintJointTable(runs, asset, false);
  std::printf("\n## Table 2: translation error per joint [mm]\n");
  for (const std::string& asset : assets) PrintJointTable(runs, asset, true);
  std::printf(
      "\n## Base and time per stage\n\n| asset | posture | accessories | weights | points | "
      "base [mm] | base [deg] | edges | base rough | base precise | chain | total | ok |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Run& run : runs) {
    const BenchResult& r = run.result;
    std::printf(
        "| %s | %s | %s | %s | %.2f M | %.3f | %.4f | %.2f s | %.2f s | %.2f s | %.2f s | %.2f s "
        "| %s |\n",
        run.asset.c_str(), run.posture.c_str(), run.accessories.c_str(), run.weighting.c_str(),
        1e-6 * static_cast<double>(r.points), 1e3 * r.errors.base_translation,
        r.errors.base_rotation / kDeg, r.timings.edges, r.timings.base_rough,
        r.timings.base_precise, r.timings.chain, r.timings.total,
        r.failed ? "FAILED" : (r.ok ? "ok" : "not ok"));
  }

  if (!FLAGS_out_csv.empty()) {
    std::ostringstream csv;
    csv << "asset,posture,accessories,weighting,joint,prismatic,truth,fit,error\n";
    for (const Run& run : runs) {
      for (const JointError& e : run.result.errors.joints) {
        csv << run.asset << ',' << run.posture << ',' << run.accessories << ',' << run.weighting
            << ',' << e.name << ',' << e.prismatic << ',' << e.truth << ',' << e.fit << ','
            << e.error << '\n';
      }
    }
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, WriteStringAtomically(FLAGS_out_csv, csv.str()));
  }
  if (!FLAGS_out_json.empty()) {
    nlohmann::json out = nlohmann::json::array();
    for (const Run& run : runs) {
      nlohmann::json joints = nlohmann::json::object();
      for (const JointError& e : run.result.errors.joints) joints[e.name] = e.error;
      const RobotFitTimings& t = run.result.timings;
      out.push_back({{"asset", run.asset},
                     {"posture", run.posture},
                     {"accessories", run.accessories},
                     {"weighting", run.weighting},
                     {"points", run.result.points},
                     {"joint_errors", joints},
                     {"base_translation_m", run.result.errors.base_translation},
                     {"base_rotation_rad", run.result.errors.base_rotation},
                     {"timing_s",
                      {{"edges", t.edges},
                       {"base_rough", t.base_rough},
                       {"base_precise", t.base_precise},
                       {"chain", t.chain},
                       {"total", t.total}}},
                     {"ok", run.result.ok},
                     {"failed", run.result.failed}});
    }
    EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                                 WriteStringAtomically(FLAGS_out_json, out.dump(2) + "\n"));
  }
  return kExitOk;
}

}  // namespace

Command BenchCommand() {
  return {"bench",
          "the paper's evaluation (Sec. 7.3-7.4): robot and conveyor, postures x accessories x "
          "weights, per-joint error tables",
          "Usage:\n"
          "  edgefit bench [--assets=robot,conveyor] [--scenes=without,with]\n"
          "                [--weightings=uniform,edge] [--spacing_mm=1.7] [--noise_mm=1]\n"
          "                [--scanners=3] [--seed=1] [--w_high=10] [--only=POSTURE,...]\n"
          "                [--out_csv=F.csv] [--out_json=F.json] [--threads=N]\n"
          "Run from the source folder (the defaults name assets/...).",
          {"assets", "robot_urdf", "robot_attach", "robot_postures", "conveyor_urdf",
           "conveyor_postures", "scenes", "weightings", "only", "base_range_m", "out_csv",
           "out_json", "spacing_mm", "noise_mm", "scanners", "seed", "w_high", "threads"},
          RunBench};
}

}  // namespace edgefit::tools
