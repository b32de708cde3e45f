// edgefit scan: the virtual TLS scanner (paper Sec. 7.3). Poses a URDF model
// (optionally with attachments and accessories) on the floor, adds a floor and
// clutter, places scanners around it and casts one ray per grid cell; with
// --camera_info, a depth camera at each place (depth_camera.h).
//   edgefit scan --urdf=F [--attach=...] (--joints=... | --posture=P.json:NAME |
//                --random_pose) [--seed=N] [--base=x,y,yaw_deg] [--accessories]
//                [--scanners=N] [--spacing_mm=1.7] [--noise_mm=1]
//                --out=F.ptx|F.e57|F.pcd --truth=F.json [--labels=F.bin]
//   edgefit scan --scene=cell.json [same options] : several assets in one cell
#include <omp.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <cstdio>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/core/split_mix64.h"
#include "edgefit/io/camera_info.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/scanner/random_joints.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/cell_scene.h"
#include "edgefit/scanner/label_file.h"
#include "edgefit/scanner/truth.h"
#include "edgefit/scanner/virtual_scanner.h"

DEFINE_string(posture, "", "A named posture: POSTURES.json:NAME (e.g. assets/robot/postures.json:home).");
DEFINE_bool(random_pose, false, "Draw the independent joints uniformly inside their limits (--seed).");
DEFINE_string(base, "0,0,0", "Base pose on the floor: x,y in m, yaw in degrees.");
DEFINE_bool(accessories, false, "Add non-modelled accessories: harnesses, hoses, covers, brackets.");
DEFINE_string(scanner_at, "",
              "Explicit scanner positions instead of --scanners: x,y,z[,yaw_deg] in m, several "
              "separated by ':'. Without a yaw the scanner faces the asset.");
DEFINE_double(max_range_m, 60.0, "Maximum range [m]; farther rays are misses.");
DEFINE_bool(full_dome, false, "Scan 360 degrees in azimuth instead of a window around the asset.");
DEFINE_string(sensor, "ideal",
              "ideal, realistic (mixed pixels, incidence noise and dropouts, station residuals, "
              "as-built surfaces), or effects joined by '+': mixed_pixels, incidence, stations, "
              "as_built, jackets.");
DEFINE_int32(clutter, 4, "Clutter objects (pillars, boxes, a fence panel) away from the asset.");
DEFINE_string(scene, "",
              "A cell: several assets from a scene file (include/edgefit/scanner/cell_scene.h) "
              "instead of --urdf, --attach, --joints, --posture, --random_pose, --base; the truth "
              "holds every asset, the labels number the assets' links in order.");

namespace edgefit::tools {
namespace {

// "x,y,z[,yaw_deg]:..." -> level scanner poses; a missing yaw faces the asset.
Status ParseScannerPositions(const std::string& text, const Eigen::AlignedBox3d& asset_box,
                             std::vector<Pose>* T_world_scanners) {
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(':', start);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(start, end - start);
    start = end + 1;
    const std::vector<std::string> parts = SplitList(item);
    if (parts.size() != 3 && parts.size() != 4) {
      return Status::Error("--scanner_at: expected x,y,z[,yaw_deg], got '" + item + "'");
    }
    double v[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < parts.size(); ++i) {
      char* rest = nullptr;
      v[i] = std::strtod(parts[i].c_str(), &rest);
      if (*rest != '\0' || !std::isfinite(v[i])) {
        return Status::Error("--scanner_at: '" + parts[i] + "' is not a number");
      }
    }
    const Eigen::Vector3d to_asset = asset_box.center() - Eigen::Vector3d(v[0], v[1], v[2]);
    const double yaw =
        parts.size() == 4 ? v[3] * M_PI / 180.0 : std::atan2(to_asset.y(), to_asset.x());
    Pose T = PoseFromXyYaw(v[0], v[1], yaw);
    T.translation().z() = v[2];
    T_world_scanners->push_back(T);
  }
  return Status::Ok();
}

Status ChooseJoints(const KinematicModel& model, const Pose& T_world_base,
                    std::vector<double>* q) {
  const int sources = !FLAGS_joints.empty() + !FLAGS_posture.empty() + FLAGS_random_pose;
  if (sources > 1) return Status::Error("give at most one of --joints, --posture, --random_pose");
  *q = model.ZeroJoints();
  if (FLAGS_random_pose) {
    // The floor of the scene is z = 0 (EnvironmentOptions::floor_z).
    if (!RandomJointValuesAboveFloor(model, T_world_base, /*floor_z=*/0.0,
                                     SplitMix64::StreamSeed(FLAGS_seed, 0), q)) {
      return Status::Error(FLAGS_urdf + ": no random posture of this model stays above the floor "
                           "(is the base below z = 0?)");
    }
    return Status::Ok();
  }
  if (!FLAGS_posture.empty()) {
    const size_t colon = FLAGS_posture.rfind(':');
    if (colon == std::string::npos) return Status::Error("--posture: expected FILE.json:NAME");
    EDGEFIT_RETURN_IF_ERROR(LoadNamedPosture(FLAGS_posture.substr(0, colon),
                                             FLAGS_posture.substr(colon + 1), model, q));
  }
  EDGEFIT_RETURN_IF_ERROR(ParseJointAssignments(FLAGS_joints, model, q));
  return model.ResolveDependentJoints(q).WithContext("joint values");
}

Status ValidateFlags() {
  if (FLAGS_scene.empty() && FLAGS_urdf.empty()) return Status::Error("--urdf (or --scene) is required");
  if (!FLAGS_scene.empty() && (!FLAGS_urdf.empty() || !FLAGS_attach.empty() || !FLAGS_joints.empty() ||
                               !FLAGS_posture.empty() || FLAGS_random_pose || FLAGS_base != "0,0,0")) {
    return Status::Error("--scene names the assets: drop --urdf, --attach, --joints, --posture, "
                         "--random_pose and --base");
  }
  if (FLAGS_out.empty()) return Status::Error("--out is required (.ptx, .e57 or .pcd)");
  if (FLAGS_truth.empty()) return Status::Error("--truth is required");
  const std::string ext = FLAGS_out.size() >= 4 ? FLAGS_out.substr(FLAGS_out.size() - 4) : "";
  if (ext != ".ptx" && ext != ".e57" && ext != ".pcd") {
    return Status::Error("--out must end in .ptx, .e57 or .pcd");
  }
  if (FLAGS_scanners < 1 || FLAGS_scanners > 64) return Status::Error("--scanners must be 1..64");
  if (!(FLAGS_spacing_mm > 0.05 && FLAGS_spacing_mm < 1000)) {
    return Status::Error("--spacing_mm must be in (0.05, 1000)");
  }
  if (!(FLAGS_noise_mm >= 0 && FLAGS_noise_mm < 100)) return Status::Error("--noise_mm must be in [0, 100)");
  if (!(FLAGS_max_range_m > 0)) return Status::Error("--max_range_m must be positive");
  if (FLAGS_clutter < 0 || FLAGS_clutter > 100) return Status::Error("--clutter must be 0..100");
  return CheckOutputPaths({FLAGS_out, FLAGS_truth, FLAGS_labels});
}

// Writes the scan(s), the truth and the labels. Each file is atomic; if a
// later one fails, the earlier ones are removed: no partial output.
Status WriteOutputs(const std::function<Status()>& write_truth, const VirtualScan& result) {
  std::vector<std::string> written;
  auto fail = [&written](const Status& status) {
    for (const std::string& path : written) std::remove(path.c_str());
    return status;
  };
  const bool pcd = FLAGS_out.substr(FLAGS_out.size() - 4) == ".pcd";
  if (pcd && result.scans.scans.size() > 1) {
    // A PCD file holds one scan: F.pcd -> F_0.pcd, F_1.pcd, ...
    const std::string stem = FLAGS_out.substr(0, FLAGS_out.size() - 4);
    for (size_t i = 0; i < result.scans.scans.size(); ++i) {
      ScanSet one;
      one.scans.push_back(result.scans.scans[i]);
      const std::string path = stem + "_" + std::to_string(i) + ".pcd";
      const Status s = WriteScans(path, one, WriteOptions());
      if (!s.ok()) return fail(s);
      written.push_back(path);
    }
  } else {
    const Status s = WriteScans(FLAGS_out, result.scans, WriteOptions());
    if (!s.ok()) return fail(s);
    written.push_back(FLAGS_out);
  }
  Status s = write_truth();
  if (!s.ok()) return fail(s);
  written.push_back(FLAGS_truth);
  if (!FLAGS_labels.empty()) {
    s = WriteLabels(FLAGS_labels, result, FLAGS_out);
    if (!s.ok()) return fail(s);
  }
  return Status::Ok();
}

// The scan options of the flags; scanners placed around `box` (every asset).
Status ScanOptionsFromFlags(const Eigen::AlignedBox3d& box, AssetScanOptions* options) {
  options->accessories = FLAGS_accessories;
  options->clutter = FLAGS_clutter;
  options->scanners = FLAGS_scanners;
  if (!FLAGS_scanner_at.empty()) {
    EDGEFIT_RETURN_IF_ERROR(ParseScannerPositions(FLAGS_scanner_at, box, &options->T_world_scanners));
  }
  options->scan.spacing = FLAGS_spacing_mm * 1e-3;
  options->scan.noise_sigma = FLAGS_noise_mm * 1e-3;
  options->scan.max_range = FLAGS_max_range_m;
  options->scan.full_dome = FLAGS_full_dome;
  options->seed = FLAGS_seed;
  EDGEFIT_RETURN_IF_ERROR(SensorOptionsFromFlags(FLAGS_sensor, options));
  if (!FLAGS_camera_info.empty()) {  // a depth camera looking at the asset
    CameraInfo info;
    EDGEFIT_RETURN_IF_ERROR(ReadCameraInfo(FLAGS_camera_info, &info));
    DepthCameraOptions& camera = options->scan.camera;
    camera.width = info.width;
    camera.height = info.height;
    camera.camera = info.camera;
    camera.sigma_at_1m = FLAGS_noise_mm * 1e-3;
    options->scan.beam = camera.FlyingPixelBeam();
    options->station_residuals.enabled = false;  // one camera, one frame
  }
  return Status::Ok();
}

// The truth of one asset of a scan made with `options`.
Truth AssetTruth(const std::string& urdf, const std::vector<AttachSpec>& specs,
                 const KinematicModel& model, const std::vector<double>& q, const Pose& T_world_base,
                 double x, double y, double yaw, int first_link, const AssetScanOptions& options,
                 const std::vector<Pose>& T_world_scanners, const VirtualScan& result) {
  Truth truth;
  truth.urdf = urdf;
  for (const AttachSpec& spec : specs) truth.attachments.push_back(spec.path + "@" + spec.parent_link);
  truth.joints = NamedJointValues(model, q);
  truth.T_world_base = T_world_base;
  truth.base_x = x;
  truth.base_y = y;
  truth.base_yaw = yaw;
  truth.T_world_scanners = T_world_scanners;
  truth.seed = FLAGS_seed;
  VirtualScanOptions scan_options = options.scan;
  scan_options.seed = AssetScanSeed(FLAGS_seed, AssetScanStream::kNoise);
  truth.settings = MakeTruthSettings(scan_options, static_cast<int>(T_world_scanners.size()),
                                     FLAGS_accessories, FLAGS_random_pose);
  truth.sensor.name = FLAGS_sensor + (FLAGS_jackets ? "+jackets" : "");
  truth.sensor.beam = options.scan.beam;
  truth.sensor.range_noise = options.scan.range_noise;
  truth.sensor.as_built = options.as_built;
  truth.sensor.station_residuals = options.station_residuals;
  if (options.jackets.enabled) {
    for (int link : JacketLinks(model, options.jackets)) {
      truth.sensor.jackets.push_back(model.links()[link].name);
    }
  }
  for (const OrganizedScan& scan : result.scans.scans) {
    truth.sensor.T_world_scanners_written.push_back(scan.T_world_scanner());
  }
  truth.counts = CountLabels(result, model, first_link);
  return truth;
}

void PrintSummary(const VirtualScan& result, size_t scanners, double cast_seconds,
                  std::chrono::steady_clock::time_point start) {
  const size_t valid = result.scans.TotalValid();
  std::printf("scanned %zu rays from %zu scanners: %zu points (%.1f%%) in %.2f s (%.1f M rays/s); "
              "total %.2f s\n",
              result.rays, scanners, valid,
              100.0 * static_cast<double>(valid) / std::max<size_t>(1, result.rays), cast_seconds,
              static_cast<double>(result.rays) / std::max(1e-9, cast_seconds) * 1e-6,
              SecondsSince(start));
  std::printf("wrote %s, %s%s%s\n", FLAGS_out.c_str(), FLAGS_truth.c_str(),
              FLAGS_labels.empty() ? "" : ", ", FLAGS_labels.c_str());
}

int RunCellScan(const Command& command, std::chrono::steady_clock::time_point start) {
  std::vector<CellSceneAsset> scene;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, LoadCellScene(FLAGS_scene, FLAGS_seed, &scene));
  std::vector<CellAsset> assets;
  Eigen::AlignedBox3d cell_box;
  for (const CellSceneAsset& a : scene) {
    assets.push_back({&a.model, a.q, a.T_world_base});
    cell_box.extend(a.model.BoundingBox(a.q, a.T_world_base));
  }
  AssetScanOptions options;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ScanOptionsFromFlags(cell_box, &options));
  Progress("scan: a cell of " + std::to_string(scene.size()) + " assets");
  VirtualScan result;
  std::vector<Pose> T_world_scanners;
  std::vector<int> first_link;
  const auto cast_start = std::chrono::steady_clock::now();
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ScanCell(assets, options, &result, &T_world_scanners, &first_link));
  const double cast_seconds = SecondsSince(cast_start);
  std::vector<CellTruthAsset> truth;
  for (size_t a = 0; a < scene.size(); ++a) {
    const CellSceneAsset& s = scene[a];
    truth.push_back({s.name, first_link[a],
                     AssetTruth(s.urdf, s.attachments, s.model, s.q, s.T_world_base, s.base_x, s.base_y,
                                s.base_yaw, first_link[a], options, T_world_scanners, result)});
  }
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, WriteOutputs([&truth] { return WriteCellTruthJson(FLAGS_truth, truth); }, result));
  PrintSummary(result, T_world_scanners.size(), cast_seconds, start);
  return kExitOk;
}

int RunScan(const Command& command) {
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ValidateFlags());
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  const auto start = std::chrono::steady_clock::now();
  if (!FLAGS_scene.empty()) return RunCellScan(command, start);

  std::vector<AttachSpec> specs;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseAttachSpecList(FLAGS_attach, &specs));
  KinematicModel model;
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, LoadModelWithAttachments(FLAGS_urdf, specs, ModelLoadOptions(), &model));
  double x = 0.0, y = 0.0, yaw = 0.0;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseXyYawDeg("--base", FLAGS_base, &x, &y, &yaw));
  const Pose T_world_base = PoseFromXyYaw(x, y, yaw);
  std::vector<double> q;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ChooseJoints(model, T_world_base, &q));
  const Eigen::AlignedBox3d asset_box = model.BoundingBox(q, T_world_base);
  if (asset_box.isEmpty()) return BadInput(command, FLAGS_urdf + ": the model has no geometry to scan");

  AssetScanOptions options;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ScanOptionsFromFlags(asset_box, &options));
  // The window covers every non-background mesh: the model and its accessories.
  Progress("scan: casting rays from " +
           std::to_string(options.T_world_scanners.empty() ? FLAGS_scanners
                                                           : options.T_world_scanners.size()) +
           " scanners");
  VirtualScan result;
  std::vector<Pose> T_world_scanners;
  const auto cast_start = std::chrono::steady_clock::now();
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, ScanAsset(model, q, T_world_base, options, &result, &T_world_scanners));
  const double cast_seconds = SecondsSince(cast_start);
  const Truth truth = AssetTruth(FLAGS_urdf, specs, model, q, T_world_base, x, y, yaw, 0, options,
                                 T_world_scanners, result);
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, WriteOutputs([&truth] { return WriteTruthJson(FLAGS_truth, truth); }, result));
  PrintSummary(result, T_world_scanners.size(), cast_seconds, start);
  return kExitOk;
}

}  // namespace

Command ScanCommand() {
  return {"scan",
          "virtual TLS scanner: a posed model, accessories and a scene to PTX/PCD + truth JSON",
          "Usage:\n"
          "  edgefit scan --urdf=F [--attach=eef.urdf@link] (--joints=j=v,... | "
          "--posture=P.json:NAME | --random_pose --seed=N)\n"
          "               [--base=x,y,yaw_deg] [--accessories] [--scanners=3 | --scanner_at=x,y,z[,yaw]:...]\n"
          "               [--spacing_mm=1.7]"
          " [--noise_mm=1] [--sensor=ideal|realistic] [--beam=faro_focus] [--jackets]\n"
          "               [--camera_info=C.yaml: a depth camera at each scanner place, looking at the asset;\n"
          "                --noise_mm is then its depth noise at 1 m, growing with depth^2]\n"
          "               --out=F.ptx|F.e57|F.pcd --truth=F.json [--labels=F.bin]\n"
          "  edgefit scan --scene=cell.json [the options above but the model's] --out=cell.e57 "
          "--truth=cell_truth.json\n"
          "Example:\n"
          "  edgefit scan --urdf=assets/robot/robot.urdf --attach=assets/robot/weld_gun.urdf@tool0 \\\n"
          "    --posture=assets/robot/postures.json:weld_low --accessories --seed=7 \\\n"
          "    --out=robot.ptx --truth=robot_truth.json --labels=robot_labels.bin",
          {"urdf", "scene", "attach", "joints", "posture", "random_pose", "seed", "base", "accessories",
           "scanners", "scanner_at", "camera_info", "spacing_mm", "noise_mm", "sensor", "beam", "jackets", "max_range_m", "full_dome", "clutter", "out",
           "truth", "labels", "threads"},
          &RunScan};
}

}  // namespace edgefit::tools
