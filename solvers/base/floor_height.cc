#include "solvers/base/floor_height.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "edgefit/scan/lattice_window.h"

namespace edgefit {
namespace {

// The unit normal of the surface at (row, col) in the scanner frame from its
// four lattice neighbours; false at the grid's border, a missing neighbour
// or a depth step (a neighbour farther than 3 radius away).
bool StencilNormal(const OrganizedScan& scan, int row, int col, const FloorOptions& options,
                   Eigen::Vector3f* normal) {
  const Eigen::Vector3f& p = scan.point_scanner(scan.Index(row, col));
  const float radius = static_cast<float>(options.normal_radius), range = p.norm();
  const int dr =
      HalfWindow(radius, range, static_cast<float>(std::abs(scan.lattice().row_step())),
                 options.max_half_window);
  const int dc =
      HalfWindow(radius, range, static_cast<float>(std::abs(scan.lattice().col_step())),
                 options.max_half_window);
  if (row - dr < 0 || row + dr >= scan.rows() || col - dc < 0 || col + dc >= scan.cols()) {
    return false;
  }
  const float reach = static_cast<float>(3.0 * options.normal_radius);
  Eigen::Vector3f q[4];
  const int offsets[4][2] = {{-dr, 0}, {dr, 0}, {0, -dc}, {0, dc}};
  for (int k = 0; k < 4; ++k) {
    const size_t i = scan.Index(row + offsets[k][0], col + offsets[k][1]);
    if (!scan.IsValid(i)) return false;
    q[k] = scan.point_scanner(i);
    if (!((q[k] - p).norm() < reach)) return false;
  }
  *normal = (q[1] - q[0]).cross(q[3] - q[2]);
  const float length = normal->norm();
  if (!(length > 0.0f)) return false;
  *normal /= length;
  return true;
}

}  // namespace

bool FloorOptions::IsValid(std::string* error) const {
  if (!(normal_cos > 0.0 && normal_cos <= 1.0) || !(normal_radius > 0.0) || max_half_window < 1 ||
      stride < 1) {
    if (error != nullptr) {
      *error =
          "floor: normal_cos must be in (0, 1], normal_radius > 0, max_half_window and "
          "stride >= 1";
    }
    return false;
  }
  return true;
}

Status EstimateFloorHeight(const ScanSet& scans, const Eigen::AlignedBox3d& roi_world,
                           const FloorOptions& options, double* floor_z) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error(error);
  constexpr double kBin = 0.005;                           // [m]
  std::map<int64_t, std::pair<size_t, double>> histogram;  // bin -> (count, sum of z)
  for (const OrganizedScan& scan : scans.scans) {
    if (!scan.organized() || !scan.lattice().valid()) continue;
    const Eigen::Matrix3d R = scan.T_world_scanner().linear();
    for (int col = 0; col < scan.cols(); col += options.stride) {
      for (int row = 0; row < scan.rows(); row += options.stride) {
        const size_t i = scan.Index(row, col);
        Eigen::Vector3f n;
        if (!scan.IsValid(i) || !StencilNormal(scan, row, col, options, &n)) continue;
        if (std::abs(R.row(2).dot(n.cast<double>())) < options.normal_cos) continue;
        const Eigen::Vector3d p = scan.PointWorld(i);
        // A floor faces up, to a station above it: a ceiling faces down.
        if (!(p.z() < scan.T_world_scanner().translation().z())) continue;
        if (!roi_world.isEmpty() && !roi_world.contains(p)) continue;
        auto& bin = histogram[static_cast<int64_t>(std::floor(p.z() / kBin))];
        ++bin.first;
        bin.second += p.z();
      }
    }
  }
  if (histogram.empty()) return Status::Error("no horizontal surface (floor) in the scan");
  // The surface: the fullest window of 2 kWindow + 1 bins, not the fullest
  // bin (a depth camera's far floor spreads its level points over many
  // bins, its noise growing with range squared, where a table top near the
  // camera fills one). Its height: the mean of the window about the
  // fullest bin within it.
  constexpr int64_t kWindow = 2;
  const auto window = [&](int64_t centre, double* sum_z) {
    size_t count = 0;
    for (auto it = histogram.lower_bound(centre - kWindow);
         it != histogram.end() && it->first <= centre + kWindow; ++it) {
      count += it->second.first;
      if (sum_z != nullptr) *sum_z += it->second.second;
    }
    return count;
  };
  int64_t surface = 0;
  size_t best_count = 0;
  for (const auto& entry : histogram) {
    const size_t count = window(entry.first, nullptr);
    if (count > best_count) {
      best_count = count;
      surface = entry.first;
    }
  }
  int64_t best_bin = surface;
  best_count = 0;
  for (auto it = histogram.lower_bound(surface - kWindow);
       it != histogram.end() && it->first <= surface + kWindow; ++it) {
    if (it->second.first > best_count) {
      best_count = it->second.first;
      best_bin = it->first;
    }
  }
  double sum = 0.0;
  const size_t count = window(best_bin, &sum);
  *floor_z = sum / static_cast<double>(count);
  return Status::Ok();
}

}  // namespace edgefit
