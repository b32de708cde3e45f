#include "edgefit/edges/edge_detector.h"

#include <glog/logging.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "edgefit/edges/edge_score.h"
#include "edgefit/edges/grid_cloud.h"
#include "edgefit/edges/grid_normals.h"
#include "edgefit/edges/region_growing.h"

namespace edgefit {
namespace {

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

bool InUnit(double v) { return v >= 0.0 && v <= 1.0; }

}  // namespace

bool EdgeDetectionOptions::IsValid(std::string* error) const {
  std::ostringstream why;
  if (!(normal_radius > 0.0) || !std::isfinite(normal_radius)) {
    why << "normal_radius must be > 0 [m], got " << normal_radius;
  } else if (max_half_window < 1 || max_half_window > 64) {
    why << "max_half_window must be in [1, 64] pixels, got " << max_half_window;
  } else if (!InUnit(tau_align)) {
    why << "tau_align must be in [0, 1], got " << tau_align;
  } else if (!(r_min >= 0.0) || !(r_max > r_min) || !std::isfinite(r_max)) {
    why << "need 0 <= r_min < r_max [m], got r_min " << r_min << ", r_max " << r_max;
  } else if (!(tau_dot > 0.0 && tau_dot <= 1.0)) {
    why << "tau_dot must be in (0, 1], got " << tau_dot;
  } else if (!(region_radius > 0.0) || !std::isfinite(region_radius)) {
    why << "region_radius must be > 0 [m], got " << region_radius;
  } else if (!InUnit(tau_region)) {
    why << "tau_region must be in [0, 1], got " << tau_region;
  } else if (tau_min < 1) {
    why << "tau_min must be >= 1 point, got " << tau_min;
  } else if (!(w_high >= 1.0) || !std::isfinite(w_high)) {
    why << "w_high must be >= 1, got " << w_high;
  } else {
    return true;
  }
  if (error != nullptr) *error = why.str();
  return false;
}

Status DetectEdges(const ScanSet& scans, const EdgeDetectionOptions& options,
                   EdgeDetectionResult* result) {
  CHECK(result != nullptr);
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("edge detection options: " + error);
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    const std::string name = "scan " + std::to_string(s) +
                             (s < scans.sources.size() ? " (" + scans.sources[s] + ")" : "");
    if (!scan.organized()) {
      return Status::Error(name + ": edge detection needs an organized scan (a lattice grid)");
    }
    if (!scan.lattice().valid() || scan.lattice().rows() != scan.rows() ||
        scan.lattice().cols() != scan.cols()) {
      return Status::Error(name + ": edge detection needs the scan's angular lattice");
    }
  }
  const auto start = std::chrono::steady_clock::now();
  *result = EdgeDetectionResult();
  const size_t scan_count = scans.scans.size();
  result->w_edge.resize(scan_count);
  result->normals.resize(scan_count);
  result->scores.resize(scan_count);

  GridNormalOptions normal_options;
  normal_options.radius = options.normal_radius;
  normal_options.max_half_window = options.max_half_window;
  normal_options.tau_align = options.tau_align;
  EdgeScoreOptions score_options;
  score_options.r_min = options.r_min;
  score_options.r_max = options.r_max;
  // The annulus window gets the normal window's cap scaled to r_max.
  score_options.max_half_window = static_cast<int>(
      std::ceil(options.max_half_window * std::max(1.0, options.r_max / options.normal_radius)));

  // 4.1 and 4.2 per scan; candidates gathered in world coordinates.
  EdgeCandidates candidates;
  std::vector<size_t> candidate_cell;  // cell of each candidate
  std::vector<size_t> candidate_scan;  // first candidate of each scan
  const float tau_dot = static_cast<float>(options.tau_dot);
  for (size_t s = 0; s < scan_count; ++s) {
    const OrganizedScan& scan = scans.scans[s];
    const GridCloud cloud = GridCloud::FromScan(scan);
    auto t = std::chrono::steady_clock::now();
    GridNormals normals;
    EstimateGridNormals(cloud, normal_options, &normals);
    result->timings.normals += Seconds(t);

    t = std::chrono::steady_clock::now();
    std::vector<float>& scores = result->scores[s];
    ComputeEdgeScores(cloud, normals, score_options, &scores);
    result->timings.scores += Seconds(t);

    t = std::chrono::steady_clock::now();
    const Eigen::Matrix3f R_world_scanner = scan.T_world_scanner().linear().cast<float>();
    const Eigen::Vector3f t_world_scanner = scan.T_world_scanner().translation().cast<float>();
    std::vector<Eigen::Vector3f>& normals_out = result->normals[s];
    normals_out.resize(cloud.size());
    candidate_scan.push_back(candidates.size());
    for (size_t i = 0; i < cloud.size(); ++i) {
      const Eigen::Vector3f n_scanner(normals.x[i], normals.y[i], normals.z[i]);
      normals_out[i] = n_scanner;
      if (cloud.IsValid(i)) ++result->points;
      if (!(scores[i] < tau_dot)) continue;  // NaN scores are no candidates
      candidates.Add(R_world_scanner * scan.point_scanner(i) + t_world_scanner,
                     R_world_scanner * n_scanner, scores[i]);
      candidate_cell.push_back(i);
    }
    result->timings.region_growing += Seconds(t);
  }
  candidate_scan.push_back(candidates.size());
  result->candidates = candidates.size();

  // 4.3 Region growing over all scans, then Eq. (6).
  auto t = std::chrono::steady_clock::now();
  RegionGrowingOptions region_options;
  region_options.radius = options.region_radius;
  region_options.tau_region = options.tau_region;
  region_options.tau_min = options.tau_min;
  RegionGrowingResult regions;
  GrowEdgeRegions(candidates, region_options, &regions);
  result->regions = regions.regions;
  result->edge_points = regions.edge_points;
  const float w_high = static_cast<float>(options.w_high);
  for (size_t s = 0; s < scan_count; ++s) {
    const OrganizedScan& scan = scans.scans[s];
    std::vector<float>& w = result->w_edge[s];
    w.resize(scan.size());
    for (size_t i = 0; i < scan.size(); ++i) w[i] = scan.IsValid(i) ? 1.0f : 0.0f;
    for (size_t c = candidate_scan[s]; c < candidate_scan[s + 1]; ++c) {
      if (regions.region[c] >= 0) w[candidate_cell[c]] = w_high;  // Eq. (6)
    }
  }
  result->timings.region_growing += Seconds(t);
  result->timings.total = Seconds(start);
  return Status::Ok();
}

}  // namespace edgefit
