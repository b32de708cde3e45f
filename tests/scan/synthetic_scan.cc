#include "scan/synthetic_scan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

namespace edgefit {
namespace testing {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Slab test: entry and exit ray parameters of an axis-aligned box.
bool SlabInterval(const SyntheticScene::Box& box, const Eigen::Vector3d& o,
                  const Eigen::Vector3d& d, double* t_in, double* t_out) {
  double lo = -kInf, hi = kInf;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (o[k] < box.min[k] || o[k] > box.max[k]) return false;
      continue;
    }
    double a = (box.min[k] - o[k]) / d[k], b = (box.max[k] - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
  *t_in = lo;
  *t_out = hi;
  return lo <= hi;
}

// Nearest hit along the ray; returns the object id (0 floor, 1 room,
// 2+ boxes, 100+ cylinders) or -1 for no return.
int CastRay(const SyntheticScene& scene, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
            double* t_hit) {
  double best = kInf;
  int id = -1;
  auto consider = [&](double t, int object) {
    if (t > 1e-6 && t < best) {
      best = t;
      id = object;
    }
  };
  if (scene.has_floor && d.z() < -1e-12) consider(-o.z() / d.z(), 0);
  double t_in, t_out;
  if (scene.has_room && SlabInterval(scene.room, o, d, &t_in, &t_out)) consider(t_out, 1);
  for (size_t b = 0; b < scene.boxes.size(); ++b) {
    if (SlabInterval(scene.boxes[b], o, d, &t_in, &t_out)) consider(t_in, 2 + static_cast<int>(b));
  }
  for (size_t c = 0; c < scene.cylinders.size(); ++c) {
    const auto& cyl = scene.cylinders[c];
    const int object = 100 + static_cast<int>(c);
    const Eigen::Vector2d q = o.head<2>() - cyl.center, v = d.head<2>();
    const double a = v.squaredNorm(), b = 2.0 * q.dot(v), cc = q.squaredNorm() - cyl.radius * cyl.radius;
    const double disc = b * b - 4.0 * a * cc;
    if (a > 1e-15 && disc >= 0.0) {
      const double t = (-b - std::sqrt(disc)) / (2.0 * a);
      const double z = o.z() + t * d.z();
      if (z >= cyl.z_min && z <= cyl.z_max) consider(t, object);
    }
    if (d.z() < -1e-12) {  // top cap
      const double t = (cyl.z_max - o.z()) / d.z();
      if ((q + t * v).squaredNorm() <= cyl.radius * cyl.radius) consider(t, object);
    }
  }
  if (id < 0 || best > scene.max_range) return -1;
  *t_hit = best;
  return id;
}

}  // namespace

SyntheticScene DefaultScene() {
  SyntheticScene scene;
  scene.boxes.push_back({Eigen::Vector3d(0.5, -0.6, 0.0), Eigen::Vector3d(1.5, 0.4, 1.2)});
  scene.cylinders.push_back({Eigen::Vector2d(-0.8, 1.2), 0.3, 0.0, 2.0});
  return scene;
}

SyntheticScene RoomScene() {
  SyntheticScene scene = DefaultScene();
  scene.has_room = true;
  return scene;
}

OrganizedScan MakeSyntheticScan(const SyntheticScene& scene, const SyntheticScanOptions& options,
                                ScanLattice* truth) {
  std::vector<double> elevations(static_cast<size_t>(options.rows));
  std::vector<double> azimuths(static_cast<size_t>(options.cols));
  for (int r = 0; r < options.rows; ++r) elevations[r] = options.elevation_first + r * options.elevation_step;
  for (int c = 0; c < options.cols; ++c) azimuths[c] = options.azimuth_first + c * options.azimuth_step;
  const ScanLattice lattice(elevations, azimuths, options.R_scanner_lattice);
  if (truth != nullptr) *truth = lattice;

  OrganizedScan scan(options.rows, options.cols);
  scan.set_T_world_scanner(options.T_world_scanner);
  if (options.color) scan.EnableColor();
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const Eigen::Vector3d origin = options.T_world_scanner.translation();
  const Eigen::Matrix3d R_world_scanner = options.T_world_scanner.linear();
  for (int c = 0; c < options.cols; ++c) {
    for (int r = 0; r < options.rows; ++r) {
      // Always draw both numbers, so one cell's fate never shifts another's.
      const double n = noise(rng) * options.range_noise_m;
      const bool dropped = uniform(rng) < options.missing_fraction;
      const bool line_missing =
          std::count(options.missing_rows.begin(), options.missing_rows.end(), r) > 0 ||
          std::count(options.missing_cols.begin(), options.missing_cols.end(), c) > 0;
      if (dropped || line_missing) continue;
      const Eigen::Vector3d d_scanner = lattice.Direction(r, c);
      double t;
      const int object = CastRay(scene, origin, R_world_scanner * d_scanner, &t);
      if (object < 0) continue;
      const size_t i = scan.Index(r, c);
      const float albedo = object == 0 ? 0.35f : object == 1 ? 0.5f : object < 100 ? 0.8f : 0.65f;
      scan.SetPoint(i, ((t + n) * d_scanner).cast<float>(),
                    albedo / (1.0f + 0.02f * static_cast<float>(t)));
      if (options.color) {
        const uint8_t k = static_cast<uint8_t>(object % 7);
        scan.SetColor(i, {static_cast<uint8_t>(40 + 30 * k), static_cast<uint8_t>(200 - 20 * k),
                          static_cast<uint8_t>(90 + 10 * (object % 5))});
      }
    }
  }
  return scan;
}

ScanSet MakeSampleScanSet() {
  ScanSet set;
  const SyntheticScene scene = DefaultScene();
  SyntheticScanOptions options;
  options.rows = 120;
  options.cols = 300;
  options.elevation_first = -55.0 * M_PI / 180.0;
  options.elevation_step = 0.75 * M_PI / 180.0;
  options.azimuth_first = 0.0;
  options.azimuth_step = 2.0 * M_PI / options.cols;
  options.range_noise_m = 0.001;
  options.seed = 7;
  options.T_world_scanner = PoseFromXyzRpy(Eigen::Vector3d(-3.0, -2.0, 1.5),
                                           Eigen::Vector3d(0.0, 0.0, 20.0 * M_PI / 180.0));
  set.scans.push_back(MakeSyntheticScan(scene, options));
  set.sources.push_back("synthetic scanner 1");
  options.seed = 8;
  options.T_world_scanner = PoseFromXyzRpy(
      Eigen::Vector3d(3.5, 1.5, 1.2),
      Eigen::Vector3d(0.01, -0.015, -150.0 * M_PI / 180.0));  // slightly tilted
  set.scans.push_back(MakeSyntheticScan(scene, options));
  set.sources.push_back("synthetic scanner 2");
  return set;
}

}  // namespace testing
}  // namespace edgefit
