// edgefit edges: fast edge detection on the scan lattice and edge weights
// (paper Sec. 4): weights file for the fit, JSON summary with timings, and a
// PLY coloured by weight for CloudCompare or MeshLab.
//   edgefit edges --scan=F[,F...] [--w_high=10 ...] --out_weights=F.bin
//                 --out_json=F.json [--out_ply=F.ply] [--labels=L.bin]
//                 [--remove_mixed_pixels]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "fit_flags.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/scan/mixed_pixels.h"
#include "edgefit/scene/scene.h"
#include "edgefit/scanner/edge_metrics.h"
#include "edgefit/scanner/label_file.h"

DEFINE_string(out_weights, "",
              "Output: one float32 w_edge per grid cell, scans in file order, each scan in its "
              "file's point order, 0 for missing cells.");
DEFINE_double(normal_radius_mm, 5.0, "Sec. 4.1: physical radius of the normal window [mm].");
DEFINE_double(tau_align, 0.866, "Eq. (2): neighbours whose first normals agree, |n_k.n| > tau_align.");
DEFINE_double(r_min_mm, 5.0, "Eq. (3): inner radius of the scoring annulus [mm].");
DEFINE_double(r_max_mm, 10.0, "Eq. (3): outer radius of the scoring annulus [mm].");
DEFINE_double(tau_dot, edgefit::EdgeDetectionOptions().tau_dot,
              "Sec. 4.2: edge score S_i below this makes a candidate.");
DEFINE_double(region_radius_mm, 4.0, "Sec. 4.3: neighbour radius of region growing [mm].");
DEFINE_double(tau_region, 0.95, "Eq. (5): normal agreement when growing a region.");
DEFINE_int32(tau_min, 300, "Sec. 4.3: regions with fewer points are noise.");

namespace edgefit::tools {
namespace {

EdgeDetectionOptions OptionsFromFlags() {
  EdgeDetectionOptions o;
  o.normal_radius = FLAGS_normal_radius_mm * 1e-3;
  o.tau_align = FLAGS_tau_align;
  o.r_min = FLAGS_r_min_mm * 1e-3;
  o.r_max = FLAGS_r_max_mm * 1e-3;
  o.tau_dot = FLAGS_tau_dot;
  o.region_radius = FLAGS_region_radius_mm * 1e-3;
  o.tau_region = FLAGS_tau_region;
  o.tau_min = FLAGS_tau_min;
  o.w_high = FLAGS_w_high;
  return o;
}

// Per scan, w_edge in the scan file's point order.
std::vector<std::vector<float>> WeightsInFileOrder(const ScanSet& set,
                                                   const EdgeDetectionResult& result) {
  std::vector<std::vector<float>> out(set.scans.size());
  for (size_t s = 0; s < set.scans.size(); ++s) {
    const OrganizedScan& scan = set.scans[s];
    out[s].resize(scan.size());
    for (size_t i = 0; i < scan.size(); ++i) out[s][scan.FileIndex(i)] = result.w_edge[s][i];
  }
  return out;
}

Status WriteWeights(const std::string& path, const std::vector<std::vector<float>>& weights) {
  return WriteFileAtomically(path, [&weights](std::ostream& out) {
    for (const std::vector<float>& w : weights) {  // little-endian float32 on x86-64
      out.write(reinterpret_cast<const char*>(w.data()),
                static_cast<std::streamsize>(w.size() * sizeof(float)));
    }
    return Status::Ok();
  });
}

Status WriteWeightPly(const std::string& path, const ScanSet& set,
                      const EdgeDetectionResult& result, float tau_dot) {
  ScanSet coloured = set;
  for (size_t s = 0; s < coloured.scans.size(); ++s) {
    OrganizedScan& scan = coloured.scans[s];
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i)) continue;
      std::array<uint8_t, 3> rgb = {170, 170, 170};
      if (result.w_edge[s][i] > 1.0f) {
        rgb = {220, 30, 30};
      } else if (result.scores[s][i] < tau_dot) {
        rgb = {240, 160, 40};
      }
      scan.SetColor(i, rgb);
    }
  }
  return WriteScans(path, coloured, WriteOptions());
}

Status Validate(const EdgeDetectionOptions& options) {
  if (FLAGS_scan.empty()) return Status::Error("--scan is required");
  if (FLAGS_out_weights.empty()) return Status::Error("--out_weights is required");
  if (FLAGS_out_json.empty()) return Status::Error("--out_json is required");
  std::string error;
  if (!options.IsValid(&error)) return Status::Error(error);
  return Status::Ok();
}

int RunEdges(const Command& command) {
  const EdgeDetectionOptions options = OptionsFromFlags();
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, Validate(options));
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  const auto start = std::chrono::steady_clock::now();
  ScanSet set;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadScanList(FLAGS_scan, true, &set));
  LabelFile labels;
  if (!FLAGS_labels.empty()) {
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadLabels(FLAGS_labels, &labels));
    bool match = labels.labels.size() == set.scans.size();
    for (size_t s = 0; match && s < set.scans.size(); ++s) {
      match = labels.labels[s].size() == set.scans[s].size();
    }
    if (!match) {
      return BadInput(command, FLAGS_labels + ": its scans and grid sizes do not match --scan");
    }
  }
  const double load_seconds = SecondsSince(start);

  // Mixed pixels: found (and removed with --remove_mixed_pixels), and
  // scored against the labels' mixed-pixel flag.
  MixedPixelOptions mixed_options;
  mixed_options.tolerance = 1e-3 * FLAGS_mixed_pixel_tolerance_mm;
  mixed_options.min_lines = FLAGS_mixed_pixel_lines;
  mixed_options.neighbour_lines = FLAGS_mixed_pixel_neighbour_lines;
  std::string error;
  if (!mixed_options.IsValid(&error)) return BadInput(command, error);
  size_t mixed_found = 0, mixed_labelled = 0, mixed_right = 0;
  for (size_t s = 0; s < set.scans.size(); ++s) {
    const std::vector<uint8_t> mixed = FindMixedPixels(set.scans[s], mixed_options);
    for (size_t i = 0; i < mixed.size(); ++i) {
      const bool labelled = !FLAGS_labels.empty() && set.scans[s].IsValid(i) &&
                            (labels.labels[s][set.scans[s].FileIndex(i)] & kMixedPixelFlag) != 0;
      mixed_found += mixed[i];
      mixed_labelled += labelled;
      mixed_right += mixed[i] && labelled;
      if (mixed[i] && FLAGS_remove_mixed_pixels) set.scans[s].SetMissing(i);
    }
  }

  Progress("edges: " + std::to_string(set.TotalValid()) + " points in " +
           std::to_string(set.scans.size()) + " scans");
  EdgeDetectionResult result;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, DetectEdges(set, options, &result));
  const std::vector<std::vector<float>> weights = WeightsInFileOrder(set, result);

  nlohmann::json scans = nlohmann::json::array();
  for (size_t s = 0; s < set.scans.size(); ++s) {
    size_t points = 0, edges = 0;
    for (float w : result.w_edge[s]) {
      points += w > 0.0f;
      edges += w > 1.0f;
    }
    scans.push_back({{"source", set.sources[s]},
                     {"rows", set.scans[s].rows()},
                     {"cols", set.scans[s].cols()},
                     {"points", points},
                     {"edge_points", edges}});
  }
  nlohmann::json json = {
      {"points", result.points},
      {"candidates", result.candidates},
      {"edge_points", result.edge_points},
      {"regions", result.regions},
      {"scans", scans},
      {"timing_s",
       {{"load", load_seconds},
        {"normals", result.timings.normals},
        {"scores", result.timings.scores},
        {"region_growing", result.timings.region_growing},
        {"edges", result.timings.total}}},
      {"options",
       {{"normal_radius_mm", FLAGS_normal_radius_mm}, {"tau_align", options.tau_align},
        {"r_min_mm", FLAGS_r_min_mm}, {"r_max_mm", FLAGS_r_max_mm},
        {"tau_dot", options.tau_dot}, {"region_radius_mm", FLAGS_region_radius_mm},
        {"tau_region", options.tau_region}, {"tau_min", options.tau_min},
        {"w_high", options.w_high}}},
      {"threads", omp_get_max_threads()}};
  json["mixed_pixels"] = {{"found", mixed_found}, {"removed", FLAGS_remove_mixed_pixels}};
  auto ratio = [](size_t a, size_t b) {
    return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b);
  };
  if (!FLAGS_labels.empty()) {
    json["mixed_pixels"]["labelled"] = mixed_labelled;
    json["mixed_pixels"]["precision"] = ratio(mixed_right, mixed_found);
    json["mixed_pixels"]["recall"] = ratio(mixed_right, mixed_labelled);
  }
  EdgeMetrics metrics;
  if (!FLAGS_labels.empty()) {
    metrics = EvaluateEdgeWeights(labels.labels, weights);
    json["metrics"] = {{"precision", metrics.precision()},
                       {"recall", metrics.recall()},
                       {"accessory_share", metrics.accessory_share()},
                       {"accessory_share_of_high", metrics.accessory_share_of_high()},
                       {"link_points", metrics.link_points},
                       {"true_edges", metrics.true_edges},
                       {"accessory_points", metrics.accessory_points}};
  }

  // Outputs: each atomic; a later failure removes the earlier ones.
  std::vector<std::string> written;
  auto fail = [&](const Status& status) {
    for (const std::string& path : written) std::remove(path.c_str());
    return BadInput(command, status);
  };
  Status status = WriteWeights(FLAGS_out_weights, weights);
  if (!status.ok()) return fail(status);
  written.push_back(FLAGS_out_weights);
  if (!FLAGS_out_ply.empty()) {
    status = WriteWeightPly(FLAGS_out_ply, set, result, static_cast<float>(options.tau_dot));
    if (!status.ok()) return fail(status);
    written.push_back(FLAGS_out_ply);
  }
  json["timing_s"]["total"] = SecondsSince(start);
  status = WriteStringAtomically(FLAGS_out_json, json.dump(2) + "\n");
  if (!status.ok()) return fail(status);

  std::printf("%zu points, %zu candidates, %zu edge points in %zu regions; edges %.2f s "
              "(normals %.2f, scores %.2f, regions %.2f), total %.2f s\n",
              result.points, result.candidates, result.edge_points, result.regions,
              result.timings.total, result.timings.normals, result.timings.scores,
              result.timings.region_growing, json["timing_s"]["total"].get<double>());
  std::printf("mixed pixels: %zu found%s", mixed_found,
              FLAGS_remove_mixed_pixels ? " and removed before the edges" : "");
  if (!FLAGS_labels.empty()) {
    std::printf("; against the labels (%zu flagged): precision %.3f, recall %.3f", mixed_labelled,
                ratio(mixed_right, mixed_found), ratio(mixed_right, mixed_labelled));
  }
  std::printf("\n");
  if (!FLAGS_labels.empty()) std::printf("against %s: %s\n", FLAGS_labels.c_str(),
                                         metrics.BriefReport().c_str());
  return kExitOk;
}

}  // namespace

Command EdgesCommand() {
  return {"edges",
          "edge detection on the scan lattice and edge weights (paper Sec. 4)",
          "Usage:\n"
          "  edgefit edges --scan=F[,F...] --out_weights=W.bin --out_json=E.json [--out_ply=E.ply]\n"
          "                [--labels=L.bin] [--w_high=10] [--tau_dot=...] [--r_min_mm=5] "
          "[--r_max_mm=10] ...\n"
          "Example:\n"
          "  edgefit edges --scan=robot.ptx --labels=robot_labels.bin --out_weights=w.bin \\\n"
          "    --out_json=edges.json --out_ply=edges.ply",
          {"scan", "camera_info", "depth_scale", "out_weights", "out_json", "out_ply", "labels", "w_high", "normal_radius_mm",
           "tau_align", "r_min_mm", "r_max_mm", "tau_dot", "region_radius_mm", "tau_region",
           "tau_min", "remove_mixed_pixels", "mixed_pixel_tolerance_mm",
           "mixed_pixel_lines", "mixed_pixel_neighbour_lines", "threads"},
          &RunEdges};
}

}  // namespace edgefit::tools
