// The window of a virtual scan: options validation, the default asset box
// and the exact lattice of each scanner (virtual_scanner.h): the angular
// window around the asset, or a depth camera's pixel grid.
#include <algorithm>
#include <cmath>

#include "edgefit/core/angles.h"
#include "edgefit/scanner/virtual_scanner.h"

namespace edgefit {
bool VirtualScanOptions::IsValid(std::string* error) const {
  auto fail = [error](const char* message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!(spacing > 0.0) || !std::isfinite(spacing)) return fail("spacing must be > 0");
  if (!(noise_sigma >= 0.0) || !std::isfinite(noise_sigma)) return fail("noise must be >= 0");
  if (!(max_range > 0.0)) return fail("max_range must be > 0");
  if (!(window_margin_deg >= 0.0 && window_margin_deg < 90.0)) {
    return fail("window margin must be in [0, 90) degrees");
  }
  if (!(dome_min_elevation_deg > -90.0 && dome_min_elevation_deg < 90.0)) {
    return fail("dome minimum elevation must be in (-90, 90) degrees");
  }
  if (asset_box_world && asset_box_world->isEmpty()) return fail("asset box is empty");
  if (!(true_edge_distance > 0.0)) return fail("true edge distance must be > 0");
  if (!(sharp_edge_min_dihedral_deg > 0.0 && sharp_edge_min_dihedral_deg <= 180.0)) {
    return fail("sharp edge angle must be in (0, 180] degrees");
  }
  if (max_cells_per_scan < 1) return fail("max_cells_per_scan must be >= 1");
  std::string part;
  if (!beam.IsValid(&part) || !range_noise.IsValid(&part) || !camera.IsValid(&part)) {
    if (error != nullptr) *error = part;
    return false;
  }
  return true;
}

Eigen::AlignedBox3d DefaultAssetBox(const Scene& scene) {
  Eigen::AlignedBox3d asset, all;
  for (const SceneMesh& m : scene.meshes) {
    const Eigen::AlignedBox3d box = m.mesh_world.BoundingBox();
    if (box.isEmpty()) continue;
    all.extend(box);
    if ((m.label & kLabelMask) != kLabelBackground) asset.extend(box);
  }
  return asset.isEmpty() ? all : asset;
}

Status MakeScanLattice(const Eigen::AlignedBox3d& asset_box_world, const Pose& T_world_scanner,
                       const VirtualScanOptions& options, ScanLattice* lattice) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("virtual scan: " + error);
  if (asset_box_world.isEmpty()) return Status::Error("virtual scan: empty asset box");
  if (options.camera.enabled()) {  // a depth camera: its pixel grid, whatever it sees
    *lattice = ScanLattice(options.camera.height, options.camera.width, options.camera.camera);
    return Status::Ok();
  }
  const Pose T_scanner_world = T_world_scanner.inverse();
  const Eigen::Vector3d c_scanner = T_scanner_world * asset_box_world.center();
  const double distance = c_scanner.norm();
  if (!(distance > 1e-6)) {
    return Status::Error("virtual scan: scanner at the asset box centre (no spacing reference)");
  }
  const double step = options.spacing / distance;  // [rad], Sec. 7.3 spacing at the asset

  // Window in (elevation, azimuth). The azimuth is measured relative to the
  // box centre's so that it never wraps (|relative| < pi unless the scanner
  // is inside the box's vertical prism, which gets the full circle).
  const double centre_azimuth = std::atan2(c_scanner.y(), c_scanner.x());
  bool full_circle = options.full_dome;
  double el_lo = options.dome_min_elevation_deg * kDeg, el_hi = 90.0 * kDeg;
  double az_lo = -kPi, az_hi = kPi;
  if (!options.full_dome) {
    // The box surface sampled on a 9 x 9 x 9 lattice of its faces: extreme
    // angles of a box seen from outside lie on its faces, and samples 1/8 of
    // an edge apart stay within a fraction of the margin of them.
    constexpr int kN = 8;
    el_lo = az_lo = 1e9;
    el_hi = az_hi = -1e9;
    const Eigen::Vector3d lo = asset_box_world.min(), size = asset_box_world.sizes();
    const Eigen::Vector3d p_world_origin = T_world_scanner.translation();
    const bool inside_prism =
        p_world_origin.x() >= lo.x() && p_world_origin.x() <= lo.x() + size.x() &&
        p_world_origin.y() >= lo.y() && p_world_origin.y() <= lo.y() + size.y();
    for (int i = 0; i <= kN; ++i) {
      for (int j = 0; j <= kN; ++j) {
        for (int k = 0; k <= kN; ++k) {
          if (i != 0 && i != kN && j != 0 && j != kN && k != 0 && k != kN) continue;
          const Eigen::Vector3d p_world =
              lo + Eigen::Vector3d(i * size.x(), j * size.y(), k * size.z()) / kN;
          const Eigen::Vector3d p = T_scanner_world * p_world;
          const double el = std::atan2(p.z(), std::hypot(p.x(), p.y()));
          const double az = std::remainder(std::atan2(p.y(), p.x()) - centre_azimuth, 2.0 * kPi);
          el_lo = std::min(el_lo, el);
          el_hi = std::max(el_hi, el);
          az_lo = std::min(az_lo, az);
          az_hi = std::max(az_hi, az);
        }
      }
    }
    const double margin = options.window_margin_deg * kDeg;
    el_lo = std::max(el_lo - margin, -kPi / 2 + step);
    el_hi = std::min(el_hi + margin, kPi / 2 - step);
    az_lo = centre_azimuth + az_lo - margin;
    az_hi = centre_azimuth + az_hi + margin;
    if (inside_prism || az_hi - az_lo >= 2.0 * kPi - step) full_circle = true;
    if (full_circle) {
      az_lo = centre_azimuth - kPi;
      az_hi = centre_azimuth + kPi;
    }
  }

  // Rows: el_lo + r * step up to el_hi (dome: below +90 deg).
  const int64_t rows = static_cast<int64_t>(std::floor((el_hi - el_lo) / step)) +
                       (options.full_dome ? 0 : 1);
  int64_t cols;
  double az_step = step;
  if (full_circle) {
    // Columns close the circle: az_step = 2 pi / cols (within 1/cols of step).
    cols = std::max<int64_t>(3, std::llround(2.0 * kPi / step));
    az_step = 2.0 * kPi / static_cast<double>(cols);
  } else {
    cols = static_cast<int64_t>(std::floor((az_hi - az_lo) / step)) + 1;
  }
  if (rows < 2 || cols < 2) return Status::Error("virtual scan: window smaller than 2 x 2 cells");
  if (rows * cols > options.max_cells_per_scan || rows > (1 << 30) || cols > (1 << 30)) {
    return Status::Error("virtual scan: " + std::to_string(rows) + " x " + std::to_string(cols) +
                         " cells exceed max_cells_per_scan (spacing too small?)");
  }
  std::vector<double> elevations(rows), azimuths(cols);
  for (int64_t r = 0; r < rows; ++r) elevations[r] = el_lo + static_cast<double>(r) * step;
  for (int64_t c = 0; c < cols; ++c) azimuths[c] = az_lo + static_cast<double>(c) * az_step;
  *lattice = ScanLattice(std::move(elevations), std::move(azimuths));
  return Status::Ok();
}

}  // namespace edgefit
