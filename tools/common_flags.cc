#include "common_flags.h"

#include "command_line.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/scanner/asset_scan.h"

DEFINE_string(result, "",
              "report: result.json of edgefit fit; world: the result.json files of edgefit fit, "
              "one per machine (comma list).");
DEFINE_string(out_dir, "",
              "cell: a folder for one result JSON per instance (NAME_K.json); world: the folder "
              "to write (replaced whole when it exists).");
DEFINE_string(scan, "",
              "Scan file(s): .ptx, .pcd, .ply or .e57, or a depth camera's 16-bit depth .png "
              "(with --camera_info); several as a comma list.");
DEFINE_string(camera_info, "",
              "A depth camera's intrinsics, a ROS camera_info YAML file (sensor_msgs/CameraInfo "
              "or camera_calibration_parsers layout): a depth PNG needs it; organized scans of "
              "its width x height take its projective lattice instead of one estimated from "
              "their points.");
DEFINE_double(depth_scale, 0.001, "Depth PNG: metres per unit of its 16-bit values (ROS: mm).");
DEFINE_string(urdf, "",
              "URDF of the equipment (meshes resolved relative to it or via package://).");
DEFINE_string(attach, "",
              "End effectors to attach: FILE.urdf@PARENT_LINK[:x,y,z,roll,pitch,yaw] "
              "(origin in metres and radians), several as a comma list.");
DEFINE_bool(json, false, "Print one JSON object on stdout instead of text.");
DEFINE_int32(threads, 0, "Worker threads (0 = all cores). Results do not depend on it.");
DEFINE_uint64(seed, 1, "Seed of every random choice; same seed and flags, same output.");
DEFINE_double(w_high, 10.0, "Eq. (6): weight of points in valid edge regions (others 1).");
DEFINE_string(labels, "",
              "Per-cell labels sidecar of a virtual scan (format: include/edgefit/scanner/"
              "label_file.h): written by scan; read by edges to score against the true edges, and "
              "by world to score the written world against the truth (include/edgefit/world/world_truth.h).");
DEFINE_string(out, "",
              "Output. scan: the scan, .ptx or .e57 (all scans in one file) or .pcd (one file per "
              "scan: F_0.pcd, ...); fit: result.json (base pose, every non-fixed joint, timing_s, "
              "quality).");
DEFINE_string(truth, "",
              "Ground truth JSON of a virtual scan (joints, T_world_base, scanners, settings). "
              "scan: written; fit: read, to print truth against fit and add \"errors\" to "
              "result.json.");
DEFINE_string(out_ply, "",
              "Optional PLY output. edges: the valid points coloured by weight (red: w_high, "
              "orange: candidates dropped by region growing, grey: others); fit: the fitted "
              "model's meshes in the world frame.");
DEFINE_string(shard, "0/1",
              "i/N: this process's share. batch: the k-th of the rows (all, or --rows) with k "
              "mod N = i; bench: the k-th of its scans (each with its fits) with k mod N = i.");
DEFINE_string(out_csv, "",
              "Optional CSV. bench: one line per fitted joint; batch --merge: one line per job "
              "and joint.");
DEFINE_string(out_json, "",
              "Output JSON. edges: a summary (points, edge_points, timing_s, options); bench: "
              "every run.");
DEFINE_string(out_report, "",
              "Optional output: a self-contained HTML report (.html). fit: the scan against the "
              "fitted model in 3D, coloured by distance, every joint's value and verdict; bench: "
              "Tables 1-2 and the ablation plots; clearance: the world and the machine's way "
              "through it in 3D, with the clearance plotted.");
DEFINE_int32(scanners, 3,
             "Number of scanners placed around the asset (2.5-5 m away, 1.2-1.8 m high).");
DEFINE_double(spacing_mm, 1.7,
              "Point spacing at the asset's distance [mm]; sets the angular step.");
DEFINE_double(noise_mm, 1.0,
              "Gaussian range noise along the laser direction, sigma [mm]; scan with --camera_info: "
              "the depth noise at 1 m, growing with depth^2 (a stereo camera: about 2.5).");
DEFINE_string(beam, "faro_focus",
              "The beam of a sensor with mixed pixels: faro_focus (2.5 mm exit, 0.19 mrad), "
              "leica_p40 (3.5 mm, 0.23 mrad), zf_5016 (0.4 mm, 0.6 mrad).");
DEFINE_bool(jackets, false,
            "Protective jackets 3-8 mm over 40-80 % of the upper arm and the forearm.");

DEFINE_string(joints, "",
              "Joint values: name=value,... in rad / m, or with a unit: joint_2=-30deg, "
              "slide=250mm. scan: the posture (joints not named stay at 0 or their nearest "
              "limit); fit: the known joints, held at these values while the others are "
              "fitted (all of them: the base alone, camera-to-robot calibration); clearance: the "
              "posture checked.");

namespace edgefit::tools {

Status ReadOptionsFromFlags(ReadOptions* options) {
  if (!FLAGS_camera_info.empty()) {
    EDGEFIT_RETURN_IF_ERROR(ReadCameraInfo(FLAGS_camera_info, &options->camera));
  }
  if (!(FLAGS_depth_scale > 0.0)) return Status::Error("--depth_scale must be > 0 [m per unit]");
  options->depth_scale = FLAGS_depth_scale;
  return Status::Ok();
}

Status ReadScanList(const std::string& list, bool intensity, ScanSet* scans) {
  ReadOptions options;
  options.intensity = intensity;
  EDGEFIT_RETURN_IF_ERROR(ReadOptionsFromFlags(&options));
  for (const std::string& path : SplitList(list)) {
    EDGEFIT_RETURN_IF_ERROR(ReadScans(path, options, scans));
  }
  return Status::Ok();
}

Status SensorOptionsFromFlags(const std::string& sensor, AssetScanOptions* options) {
  EDGEFIT_RETURN_IF_ERROR(ApplySensorPreset(sensor, options).WithContext("--sensor"));
  if (options->scan.beam.enabled()) {
    EDGEFIT_RETURN_IF_ERROR(BeamPreset(FLAGS_beam, &options->scan.beam).WithContext("--beam"));
  }
  if (FLAGS_jackets) options->jackets.enabled = true;
  return Status::Ok();
}

}  // namespace edgefit::tools
