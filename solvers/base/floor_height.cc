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
        if (!roi_world.isEmpty() && !roi_world.contains(p)) continue;
        auto& bin = histogram[static_cast<int64_t>(std::floor(p.z() / kBin))];
        ++bin.first;
        bin.second += p.z();
      }
    }
  }
  if (histogram.empty()) return Status::Error("no horizontal surface (floor) in the scan");
  int64_t best_bin = 0;
  size_t best_count = 0;
  for (const auto& [bin, count_sum] : histogram) {
    if (count_sum.first > best_count) {
      best_count = count_sum.first;
      best_bin = bin;
    }
  }
  double sum = 0.0;
  size_t count = 0;
  for (int64_t bin = best_bin - 2; bin <= best_bin + 2; ++bin) {
    const auto it = histogram.find(bin);
    if (it == histogram.end()) continue;
    count += it->second.first;
    sum += it->second.second;
  }
  *floor_z = sum / static_cast<double>(count);
  return Status::Ok();
}

}  // namespace edgefit
