// edgefit bench: the paper's evaluation (Sec. 7.3-7.4) and its ablations in
// one command. The bundled robot (with its weld gun) and conveyor, each in
// its named postures, scanned without and with accessories and fitted with
// uniform and edge weights: Table 1 (rotation error per joint, degrees) and
// Table 2 (translation error per joint, mm), then base and tool-tip errors
// and the time per stage, as Markdown on stdout (bench_tables.h); optionally
// one CSV line per joint, a JSON file of every run and an HTML report of the
// tables and the ablation plots.
//
// Ablations: every list flag below is an axis; the bench runs their product.
// Scan axes (a new virtual scan each): --noises_mm, --spacings_mm, --scanner_counts,
// --repeats (seeds seed, seed+1, ...: other base poses, scenes and fit
// seeds). Fit axes (the same scan, fitted again): --weightings, --w_highs,
// --lambdas, --losses, --sweep_steps_deg, --searches, --refine_chains.
// With any axis of more than one value, a summary per setting follows:
// mean, 95th percentile and largest error, failure rate and time.
// --shard=i/N runs the k-th scan (with all its fits) when k mod N = i: a
// Slurm array's tasks share a bench, `edgefit report --bench=F0,F1,...`
// gathers their --out_json into one report.
#include <gflags/gflags.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_runs.h"
#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "costs/robust_loss.h"
#include "edgefit/bench/bench_case.h"
#include "edgefit/bench/bench_tables.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/model/composition.h"
#include "edgefit/pipeline/asset_kind.h"
#include "fit_flags.h"

DEFINE_string(assets, "robot,conveyor", "Bench: robot and/or conveyor.");
DEFINE_string(robot_urdf, "assets/robot/robot.urdf", "Bench: the robot's URDF.");
DEFINE_string(robot_attach, "assets/robot/weld_gun.urdf@tool0",
              "Bench: the robot's end effectors (as --attach).");
DEFINE_string(robot_postures, "assets/robot/postures.json",
              "Bench: the robot's named postures (\"\": none, only --random_postures).");
DEFINE_string(conveyor_urdf, "assets/conveyor/conveyor.urdf", "Bench: the conveyor's URDF.");
DEFINE_int32(random_postures, 0,
             "Bench: seeded random postures per asset after the named ones (random_0, ...; a "
             "posture that buries a link is redrawn).");
DEFINE_string(conveyor_postures, "assets/conveyor/postures.json",
              "Bench: the conveyor's postures.");
DEFINE_string(scenes, "without,with", "Bench: scenes without and/or with accessories.");
DEFINE_string(weightings, "uniform,edge", "Bench: fits with uniform and/or edge weights.");
DEFINE_string(only, "", "Bench: only these postures (names, comma-separated).");
DEFINE_double(base_range_m, 1.0, "Bench: random base x, y in [-r, r] [m]; yaw uniform.");
DEFINE_string(w_highs, "", "Bench ablation: Eq. (6) w_high values (default: --w_high).");
DEFINE_string(lambdas, "",
              "Bench ablation: Eq. (10)/(14) penalty weights (default: --lambda); they act "
              "with --parameterization=pose_penalty.");
DEFINE_string(losses, "",
              "Bench ablation: losses of the precise stages (default: --loss): trivial, huber, "
              "cauchy, soft_l1, arctan, tukey; the sweeps keep Eq. (9).");
DEFINE_string(sweep_steps_deg, "",
              "Bench ablation: coarse step of the Eq. (9) sweep of revolute joints [deg] "
              "(default 1).");
DEFINE_string(searches, "lattice",
              "Bench ablation: correspondences of the precise stages: lattice and/or kdtree.");
DEFINE_string(refine_chains, "",
              "Bench ablation: off and/or on: the whole-chain refinement (default: "
              "--refine_chain).");
DEFINE_string(noises_mm, "", "Bench ablation: range noise sigmas [mm] (default: --noise_mm).");
DEFINE_string(spacings_mm, "",
              "Bench ablation: point spacings at the asset's distance [mm] (default: --spacing_mm).");
DEFINE_string(sensors, "ideal",
              "Bench axis: sensors (as edgefit scan --sensor): ideal, realistic, or effects "
              "joined by '+' (mixed_pixels, incidence, stations, as_built, jackets).");
DEFINE_string(scanner_counts, "", "Bench ablation: scanner counts (default: --scanners).");
DEFINE_int32(repeats, 1,
             "Bench: each scene with seeds seed .. seed+repeats-1 (other base poses, scans and "
             "fit seeds).");
DEFINE_bool(fit_progress, false,
            "Bench: pass each fit's progress lines on (stderr, as edgefit fit prints them).");

namespace edgefit::tools {
namespace {

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
  std::vector<double> w_highs, lambdas, sweep_steps, noises, spacings, scanner_counts;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                               ParseNumberList("w_highs", FLAGS_w_highs, FLAGS_w_high, &w_highs));
  EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                               ParseNumberList("lambdas", FLAGS_lambdas, FLAGS_lambda, &lambdas));
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, ParseNumberList("sweep_steps_deg", FLAGS_sweep_steps_deg, 1.0, &sweep_steps));
  EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                               ParseNumberList("noises_mm", FLAGS_noises_mm, FLAGS_noise_mm, &noises));
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, ParseNumberList("spacings_mm", FLAGS_spacings_mm, FLAGS_spacing_mm, &spacings));
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseNumberList("scanner_counts", FLAGS_scanner_counts,
                                                     FLAGS_scanners, &scanner_counts));
  std::vector<std::string> losses = SplitList(FLAGS_losses);
  if (losses.empty()) losses.push_back(FLAGS_loss);
  for (const std::string& loss : losses) {
    if (std::find(LossNames().begin(), LossNames().end(), loss) == LossNames().end()) {
      return BadInput(command, "--losses: unknown loss '" + loss + "'");
    }
  }
  const std::vector<std::string> searches = SplitList(FLAGS_searches);
  for (const std::string& s : searches) {
    if (s != "lattice" && s != "kdtree") return BadInput(command, "--searches: lattice, kdtree");
  }
  std::vector<std::string> refines = SplitList(FLAGS_refine_chains);
  if (refines.empty()) refines.push_back(FLAGS_refine_chain ? "on" : "off");
  for (const std::string& r : refines) {
    if (r != "on" && r != "off") return BadInput(command, "--refine_chains: off, on");
  }
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckFitFlags());
  int shard = 0, shards = 1;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseShard(FLAGS_shard, &shard, &shards));
  EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                               CheckOutputPaths({FLAGS_out_csv, FLAGS_out_json, FLAGS_out_report}));
  JointParameterization parameterization = JointParameterization::kJointSpace;
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, ParseJointParameterization(FLAGS_parameterization, &parameterization));
  if (lambdas.size() > 1 && parameterization != JointParameterization::kPoseWithPenalties) {
    return BadInput(command, "--lambdas acts only with --parameterization=pose_penalty");
  }
  for (const double w : w_highs) {
    if (!(w >= 1.0)) return BadInput(command, "--w_highs: w_high must be >= 1");
  }
  for (const double s : sweep_steps) {
    if (!(s > 0.0)) return BadInput(command, "--sweep_steps_deg must be > 0");
  }
  for (const double n : noises) {
    if (!(n >= 0.0)) return BadInput(command, "--noises_mm must be >= 0");
  }
  for (const double c : scanner_counts) {
    if (!(c >= 1.0) || c != std::floor(c)) {
      return BadInput(command, "--scanner_counts must be whole numbers >= 1");
    }
  }
  for (const double s : spacings) {
    if (!(s > 0.0)) return BadInput(command, "--spacing_mm and --spacings_mm must be > 0");
  }
  if (FLAGS_repeats < 1) return BadInput(command, "--repeats must be >= 1");
  const std::vector<std::string> sensors = SplitList(FLAGS_sensors);
  for (const std::string& sensor : sensors) {
    AssetScanOptions probe;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, SensorOptionsFromFlags(sensor, &probe));
  }
  if (sensors.empty()) return BadInput(command, "--sensors: give at least one sensor");
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);

  Axes axes;
  axes.sensor = sensors.size() > 1;
  axes.noise = noises.size() > 1;
  axes.spacing = spacings.size() > 1;
  axes.scanners = scanner_counts.size() > 1;
  axes.repeat = FLAGS_repeats > 1;
  axes.w_high = w_highs.size() > 1;
  axes.lambda = lambdas.size() > 1;
  axes.loss = losses.size() > 1;
  axes.sweep_step = sweep_steps.size() > 1;
  axes.search = searches.size() > 1;
  axes.refine = refines.size() > 1;
  std::vector<FitSetting> fits;
  for (const std::string& weighting : weightings)
    for (const double w_high : w_highs)
      for (const double lambda : lambdas)
        for (const std::string& loss : losses)
          for (const double step : sweep_steps)
            for (const std::string& search : searches)
              for (const std::string& refine : refines) {
                fits.push_back({weighting, w_high, lambda, loss, step, search, refine == "on"});
              }

  // The assets and, per repeat, their cases: first, so that the progress
  // can say how far the bench is.
  struct Asset {
    std::string name;
    KinematicModel model;
    AssetKind kind = AssetKind::kArticulated;
    std::vector<std::vector<BenchCase>> cases;  // per repeat, after --only
  };
  std::vector<Asset> loaded(assets.size());
  size_t cases_total = 0;
  for (size_t a = 0; a < assets.size(); ++a) {
    Asset& asset = loaded[a];
    asset.name = assets[a];
    const bool robot = asset.name == "robot";
    std::vector<AttachSpec> specs;
    if (robot)
      EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseAttachSpecList(FLAGS_robot_attach, &specs));
    EDGEFIT_RETURN_IF_ERROR_EXIT(
        command, LoadModelWithAttachments(robot ? FLAGS_robot_urdf : FLAGS_conveyor_urdf, specs,
                                          ModelLoadOptions(), &asset.model));
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ChooseAssetKind("auto", asset.model, &asset.kind));
    for (int repeat = 0; repeat < FLAGS_repeats; ++repeat) {
      const uint64_t seed = FLAGS_seed + static_cast<uint64_t>(repeat);
      std::vector<BenchCase> cases;
      const std::string& postures = robot ? FLAGS_robot_postures : FLAGS_conveyor_postures;
      if (!postures.empty()) {
        EDGEFIT_RETURN_IF_ERROR_EXIT(
            command, NamedPostureCases(asset.model, postures, seed, FLAGS_base_range_m, &cases));
      }
      EDGEFIT_RETURN_IF_ERROR_EXIT(
          command, RandomPostureCases(asset.model, FLAGS_random_postures, seed, FLAGS_base_range_m,
                                      &cases, [](const std::string& line) { Progress(line); }));
      if (cases.empty()) return BadInput(command, asset.name + ": no postures (named or random)");
      if (!only.empty()) {
        cases.erase(std::remove_if(cases.begin(), cases.end(),
                                   [&](const BenchCase& c) {
                                     return std::find(only.begin(), only.end(), c.name) ==
                                            only.end();
                                   }),
                    cases.end());
      }
      cases_total += cases.size();
      asset.cases.push_back(std::move(cases));
    }
  }
  // The scans (each with all its fits) this shard runs: the k-th with k mod N = i.
  const size_t scans_total = cases_total * sceneries.size() * sensors.size() * noises.size() *
                             spacings.size() * scanner_counts.size();
  const size_t n = static_cast<size_t>(shards), i = static_cast<size_t>(shard);
  const size_t scans_mine = scans_total / n + (i < scans_total % n ? 1 : 0);
  if (scans_total == 0) return BadInput(command, "--only: no posture of that name");

  std::vector<Run> runs;
  ProgressCounter counter(scans_mine * fits.size());
  size_t scan_index = 0;
  for (const Asset& asset : loaded) {
    const KinematicModel& model = asset.model;
    for (int repeat = 0; repeat < FLAGS_repeats; ++repeat) {
      const uint64_t seed = FLAGS_seed + static_cast<uint64_t>(repeat);
      for (const BenchCase& c : asset.cases[static_cast<size_t>(repeat)]) {
        for (const std::string& scenery : sceneries)
          for (const std::string& sensor : sensors)
            for (const double noise : noises)
              for (const double spacing : spacings)
              for (const double scanners : scanner_counts) {
                if (scan_index++ % n != i) continue;
                const ScanSetting scan_setting{scenery, noise, spacing,
                                               static_cast<int>(scanners), repeat, sensor};
                AssetScanOptions scan_options;
                EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                                             SensorOptionsFromFlags(sensor, &scan_options));
                scan_options.accessories = scenery == "with";
                scan_options.scanners = scan_setting.scanners;
                scan_options.scan.spacing = 1e-3 * spacing;
                scan_options.scan.noise_sigma = 1e-3 * noise;
                const std::string scene = asset.name + " " + c.name + ", " + scenery +
                                          " accessories, " + sensor + " sensor" +
                                          (axes.repeat ? ", seed " + std::to_string(seed) : "");
                Progress("bench: scanning " + scene + " (edgefit scan " + ScanFlagsFor(model, c) +
                         (scan_options.accessories ? " --accessories" : "") +
                         " --sensor=" + sensor + (FLAGS_jackets ? " --jackets" : "") +
                         " --spacing_mm=" + Number(spacing) +
                         " --noise_mm=" + Number(noise) +
                         " --scanners=" + std::to_string(scan_setting.scanners) + ")");
                VirtualScan scan;
                Pose T_survey_world;
                EDGEFIT_RETURN_IF_ERROR_EXIT(
                    command, ScanBenchCase(model, c, scan_options, &scan, &T_survey_world));
                for (const FitSetting& fit : fits) {
                  Run run;
                  run.asset = asset.name;
                  run.posture = c.name;
                  run.scan = scan_setting;
                  run.fit = fit;
                  run.label = Label(axes, scan_setting, fit);
                  Progress("bench: fit " + counter.Next() + ": " + scene + ", " + fit.weighting +
                           " weights, " + run.label);
                  EDGEFIT_RETURN_IF_ERROR_EXIT(
                      command, BenchFitOptions(asset.kind, fit, seed, &run.options));
                  EDGEFIT_RETURN_IF_ERROR_EXIT(
                      command,
                      FitBenchCase(model, c, scan.scans, T_survey_world, run.options, &run.result,
                                   FLAGS_fit_progress ? ProgressFn(Progress) : nullptr));
                  runs.push_back(std::move(run));
                }
              }
      }
    }
  }
  if (runs.empty()) {  // more shards than scans
    std::printf("bench: shard %d/%d has none of the %zu scans\n", shard, shards, scans_total);
    if (!FLAGS_out_json.empty()) {
      EDGEFIT_RETURN_IF_ERROR_EXIT(command, WriteStringAtomically(FLAGS_out_json, "[]\n"));
    }
    return kExitOk;
  }

  nlohmann::json runs_json = nlohmann::json::array();
  for (const Run& run : runs) runs_json.push_back(RunJson(run));
  for (const Table& table : BenchTables(runs_json)) std::printf("%s", MarkdownTable(table).c_str());
  if (!FLAGS_out_csv.empty()) {
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, WriteStringAtomically(FLAGS_out_csv, RunsCsv(runs)));
  }
  if (!FLAGS_out_json.empty()) {
    EDGEFIT_RETURN_IF_ERROR_EXIT(command,
                                 WriteStringAtomically(FLAGS_out_json, runs_json.dump(2) + "\n"));
  }
  if (!FLAGS_out_report.empty()) {
    EDGEFIT_RETURN_IF_ERROR_EXIT(
        command, WriteTablesReport(BenchReport(runs_json, CommandText(command)), FLAGS_out_report));
  }
  return kExitOk;
}

}  // namespace

Command BenchCommand() {
  return {
      "bench",
      "the paper's evaluation (Sec. 7.3-7.4) and its ablations: robot and conveyor, postures "
      "x accessories x weights x settings, per-joint error tables",
      "Usage:\n"
      "  edgefit bench [--assets=robot,conveyor] [--scenes=without,with]\n"
      "                [--weightings=uniform,edge] [--spacing_mm=1.7] [--noise_mm=1]\n"
      "                [--scanners=3] [--seed=1] [--w_high=10] [--only=POSTURE,...]\n"
      "                [--out_csv=F.csv] [--out_json=F.json] [--out_report=B.html] [--threads=N]\n"
      "Ablations (comma lists; the bench runs their product, then a summary per "
      "setting):\n"
      "                [--w_highs=1,2,5,10,20,50,100] [--lambdas=0.1,1,10 "
      "--parameterization=pose_penalty]\n"
      "                [--losses=trivial,huber,cauchy,soft_l1,tukey] [--sweep_steps_deg=0.5,1,2]\n"
      "                [--searches=lattice,kdtree] [--refine_chains=off,on]\n"
      "                [--noises_mm=0,1,2,3] [--spacings_mm=1,1.7,3] [--scanner_counts=1,2,3,4]\n"
      "                [--repeats=N] [--shard=i/N]\n"
      "                [--sensors=ideal,realistic,stations+as_built] [--jackets]\n"
      "Run from the source folder (the defaults name assets/...). "
      "--out_report writes the tables and the ablation plots (error against each axis) as one "
      "HTML page; edgefit report --bench=F.json makes it again from --out_json.",
      WithFitOptionFlags(
          {"assets",
           "robot_urdf",
           "robot_attach",
           "robot_postures",
           "random_postures",
           "fit_progress",
           "conveyor_urdf",
           "conveyor_postures",
           "scenes",
           "weightings",
           "only",
           "base_range_m",
           "w_highs",
           "lambdas",
           "losses",
           "sweep_steps_deg",
           "searches",
           "refine_chains",
           "noises_mm",
           "spacings_mm",
           "out_report",
           "shard",
           "scanner_counts",
           "repeats",
           "out_csv",
           "out_json",
           "spacing_mm",
           "noise_mm",
           "scanners",
           "seed",
           "threads",
           "sensors",
           "beam",
           "jackets"},
          /*weighting=*/false),
      RunBench};
}

}  // namespace edgefit::tools
