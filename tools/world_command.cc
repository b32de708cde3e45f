// edgefit world: the fitted machines as a world that motion planners load
// (include/edgefit/world/planning_world.h says what is written).
//   edgefit world --result=robot.json[,other.json] [--name=left[,right]] [--scan=F,...]
//                 [--voxel_mm=20] --out_dir=DIR
#include <gflags/gflags.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/scanner/label_file.h"
#include "edgefit/scene/scene.h"
#include "edgefit/world/planning_world.h"
#include "edgefit/world/world_background.h"
#include "edgefit/world/world_truth.h"
#include "fit_result_file.h"

DECLARE_double(background_distance_mm);
DEFINE_double(voxel_mm, 20.0,
              "world: the background's voxel [mm]: background.ply and background.bt hold the "
              "occupied voxels of this edge.");
DEFINE_double(carve_mm, 20.0,
              "world: the background's voxels within this of a machine as scanned are taken as "
              "free [mm]: what is left there of its own points would block its first motion.");
DEFINE_bool(drop_mixed_pixels, true,
            "world: mixed pixels (a beam that fell on two surfaces; scan/mixed_pixels.h) leave "
            "the background: they float in free space, where a machine's silhouette left them "
            "as its ghost.");
DEFINE_double(floating_mm, 300.0,
              "world: pieces of the background (26-connected voxels) wholly within this of a "
              "machine's links, standing on nothing, leave it [mm]: what is left there of the "
              "machine would be its ghost (include/edgefit/world/floating_voxels.h); 0: kept.");
DEFINE_string(name, "",
              "world: the machines' instance names, in --result's order (comma list); default: "
              "each URDF's robot name, or the result file's name where robots repeat. Every link "
              "and joint of a machine is prefixed '<name>_'.");

namespace edgefit::tools {
namespace {

using nlohmann::json;

// The labelled surface points of `scans` (as read, before any point is
// removed) from a virtual scan's label file (--labels).
Status ReadTruthPoints(const std::string& path, const ScanSet& scans, TruthPoints* truth) {
  LabelFile file;
  EDGEFIT_RETURN_IF_ERROR(ReadLabels(path, &file));
  if (file.labels.size() != scans.scans.size()) {
    return Status::Error(path + ": labels of " + std::to_string(file.labels.size()) + " scans for " +
                         std::to_string(scans.scans.size()));
  }
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    if (file.labels[s].size() != scan.size()) {
      return Status::Error(path + ": scan " + std::to_string(s) + "'s grid differs from the scan's");
    }
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i)) continue;
      const uint16_t label = file.labels[s][scan.FileIndex(i)];
      if ((label & kLabelMask) == kLabelMissing || (label & kMixedPixelFlag)) continue;
      truth->points.push_back(scan.PointWorld(i).cast<float>());
      truth->kinds.push_back((label & kLabelMask) == kLabelBackground  ? TruthKind::kBackground
                             : (label & kLabelMask) == kLabelAccessory ? TruthKind::kAccessory
                                                                       : TruthKind::kMachine);
    }
  }
  return Status::Ok();
}

// The truth's measures as one line.
std::string TruthLine(const WorldTruthScore& score, const WorldTruthOptions& options) {
  char text[768];
  std::snprintf(text, sizeof(text),
                "truth (--labels, mixed pixels left out): background points within %.0f mm of "
                "background.ply %.2f %%; machine and accessory points inside it or within %.0f mm "
                "%.2f %%; machine points within %.0f mm of machines_as_scanned.ply %.2f %%, accessory "
                "points within %.0f mm %.2f %%; background points farther than %.0f mm from the "
                "machines' within %.0f mm of it %.3f %% (%zu background, %zu machine, %zu accessory points)",
                1e3 * options.background_reach, 100.0 * score.background_covered, 1e3 * options.ghost_reach,
                100.0 * score.machines_in_background, 1e3 * options.machine_reach, 100.0 * score.machine_covered,
                1e3 * options.accessory_reach, 100.0 * score.accessory_covered, 1e3 * options.far,
                1e3 * options.far_reach, 100.0 * score.far_background_on_machines, score.background,
                score.machine, score.accessory);
  return text;
}

int RunWorld(const Command& command) {
  const std::vector<std::string> results = SplitList(FLAGS_result);
  const std::vector<std::string> names = SplitList(FLAGS_name);
  if (results.empty()) return BadInput(command, "--result is required");
  if (!(FLAGS_voxel_mm > 0.0)) return BadInput(command, "--voxel_mm must be > 0");
  if (!(FLAGS_carve_mm >= 0.0)) return BadInput(command, "--carve_mm must be >= 0");
  if (!(FLAGS_background_distance_mm > 0.0)) {
    return BadInput(command, "--background_distance_mm must be > 0");
  }
  if (FLAGS_out_dir.empty()) return BadInput(command, "--out_dir is required");
  if (!names.empty() && names.size() != results.size()) {
    return BadInput(command, "--name gives " + std::to_string(names.size()) + " names for " +
                                 std::to_string(results.size()) + " results");
  }
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckOutputFolder(FLAGS_out_dir));
  std::vector<KinematicModel> models(results.size());
  std::vector<WorldMachine> machines(results.size());
  std::vector<std::string> notes(results.size());
  std::vector<std::string> scan_inputs;  // the scans the fits read
  std::vector<double> removal(results.size());  // each machine's background distance [m]
  gflags::CommandLineFlagInfo distance_flag;
  const bool distance_given =
      gflags::GetCommandLineFlagInfo("background_distance_mm", &distance_flag) &&
      !distance_flag.is_default;
  for (size_t i = 0; i < results.size(); ++i) {
    std::string text;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadFileToString(results[i], &text));
    const json result = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (result.is_discarded()) return BadInput(command, results[i] + ": not JSON");
    WorldMachine& m = machines[i];
    EDGEFIT_RETURN_IF_ERROR_EXIT(
        command, ReadFittedModel(result, results[i], &models[i], &m.q, &m.T_world_base));
    m.model = &models[i];
    m.name = names.empty() ? models[i].name() : names[i];
    m.source = results[i];
    // A noisy scan's machine points lie farther off its surface: at least
    // 3 sigma of the noise the fit measured, unless the distance is given.
    const json& noise = result.value("noise", json::object());
    removal[i] = FLAGS_background_distance_mm * 1e-3;
    if (!distance_given && noise.is_object() && noise.value("sigma_m", json()).is_number()) {
      removal[i] = std::max(removal[i], 3.0 * noise["sigma_m"].get<double>());
    }
    for (const json& scan : result["inputs"].value("scan", json::array())) {
      if (scan.is_string()) scan_inputs.push_back(scan.get<std::string>());
    }
    const json& quality = result.value("quality", json::object());
    if (quality.is_object() && !quality.value("ok", true)) {
      const std::string message = quality.value("message", std::string());
      const size_t clause = message.find(';');
      notes[i] = " (the fit said not ok: " +
                 (clause == std::string::npos ? message : message.substr(0, clause) + "; ...") +
                 "; placed as fitted)";
    }
  }
  // Default names: the URDF's robot name, or the result file's name where
  // robots repeat (an instance's result of edgefit cell: robot_1, robot_2).
  if (names.empty()) {
    std::map<std::string, int> uses;
    for (const WorldMachine& m : machines) ++uses[m.name];
    for (WorldMachine& m : machines) {
      if (uses[m.name] > 1) m.name = std::filesystem::path(m.source).stem().string();
    }
  }
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckWorldMachines(machines));
  // The background: the scans (--scan, else those the fits read) less every
  // machine's points and the points attached to them.
  std::vector<std::string> scan_paths = SplitList(FLAGS_scan);
  if (scan_paths.empty()) {
    std::set<std::string> seen;
    for (const std::string& path : scan_inputs) {
      if (seen.insert(path).second) scan_paths.push_back(path);
    }
  }
  std::vector<Eigen::Vector3f> background;
  WorldBackgroundSummary summary;
  TruthPoints truth;  // with --labels
  ScanSet scans;
  if (!scan_paths.empty()) {
    ReadOptions read;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadOptionsFromFlags(&read));
    for (const std::string& path : scan_paths) {
      EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadScans(path, read, &scans));
    }
    Progress("world: the background, " + std::to_string(scans.TotalValid()) + " points less " +
             std::to_string(machines.size()) + " machines");
    if (!FLAGS_labels.empty()) {
      EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadTruthPoints(FLAGS_labels, scans, &truth));
    }
    WorldBackgroundOptions options;
    options.voxel = FLAGS_voxel_mm * 1e-3;
    options.drop_mixed_pixels = FLAGS_drop_mixed_pixels;
    options.floating = FLAGS_floating_mm * 1e-3;
    EDGEFIT_RETURN_IF_ERROR_EXIT(
        command, WorldBackground(removal, options, &scans, &machines, &background, &summary));
  }
  BackgroundOptions background_options;
  background_options.voxel = FLAGS_voxel_mm * 1e-3;
  background_options.carve_margin = FLAGS_carve_mm * 1e-3;
  std::vector<std::string> written;
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, WritePlanningWorld(machines, scan_paths.empty() ? nullptr : &background,
                                  background_options, FLAGS_out_dir, &written));
  std::string truth_line;
  if (!FLAGS_labels.empty() && !scan_paths.empty()) {
    WorldTruthScore score;
    const WorldTruthOptions options;
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ScoreWorldTruth(truth, FLAGS_out_dir, options, &score));
    truth_line = TruthLine(score, options);
  }
  for (size_t i = 0; i < machines.size(); ++i) {
    const WorldMachine& m = machines[i];
    std::printf("%s: %s, %zu links, prefixed %s_, its points within %.1f mm, %zu riding on it "
                "off its CAD%s\n",
                m.name.c_str(), m.source.c_str(), m.model->links().size(), m.name.c_str(),
                1e3 * removal[i], summary.riding.empty() ? size_t{0} : summary.riding[i],
                notes[i].c_str());
  }
  if (scan_paths.empty()) {
    std::printf("background: none (no --scan, and the results name no scans)\n");
  } else {
    std::printf("background: %zu points (%zu of the machines removed, %zu mixed pixels and %zu "
                "points in %zu voxels floating beside them left out) in %.0f mm voxels: "
                "background.ply, background.scene, background.bt\n",
                background.size(), summary.machine_points, summary.mixed_pixels,
                summary.floating_points, summary.floating_voxels, FLAGS_voxel_mm);
  }
  if (!truth_line.empty()) std::printf("%s\n", truth_line.c_str());
  std::printf("world: %s (%zu files)\n", FLAGS_out_dir.c_str(), written.size());
  return 0;
}

}  // namespace

Command WorldCommand() {
  return {"world",
          "the fitted machines as a world that motion planners load: cell.urdf (root 'world', "
          "each machine at its fitted base), cell_frozen.urdf, cell.srdf (as_scanned), "
          "joint_states.yaml, machines_as_scanned.ply, and the scan less the machines as "
          "background.ply (closed voxel mesh) and background.bt (OctoMap)",
          "Usage:\n"
          "  edgefit world --result=R.json[,R2.json] [--name=N[,N2]] [--scan=F,...] [--voxel_mm=20]\n"
          "                [--carve_mm=20] [--labels=L.bin: the virtual scan's truth, scored]\n"
          "                [--background_distance_mm=8] [--camera_info=C.yaml] --out_dir=DIR\n"
          "Example:\n"
          "  edgefit fit --urdf=assets/robot/robot.urdf --scan=robot.ptx --out=result.json\n"
          "  edgefit world --result=result.json --name=robot --out_dir=world\n"
          "  check_urdf world/cell.urdf",
          {"result", "name", "scan", "camera_info", "depth_scale", "labels", "voxel_mm", "carve_mm", "drop_mixed_pixels", "floating_mm",
           "background_distance_mm", "out_dir"},
          RunWorld};
}

}  // namespace edgefit::tools
