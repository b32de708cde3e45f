// Virtual terrestrial laser scanner (paper Sec. 7.3): ray casts a Scene from
// each scanner pose into an organized scan, one ray per (elevation, azimuth)
// grid cell with the first hit kept, so occlusion is real. With
// VirtualScanOptions::camera, a depth camera: one ray per pixel of its
// projective lattice (depth_camera.h).
//
// Per cell (row, col) with unit direction d_scanner from the scan's exact
// ScanLattice (scanner frame, level: lattice frame = scanner frame):
//   first hit at distance t (t <= max_range, else the cell is missing);
//   range  = t + n,  n ~ N(0, noise_sigma^2), "along the laser direction"
//            (a realistic sensor: t is the footprint's mixed range and the
//            noise grows with incidence and darkness, beam_footprint.h and
//            range_noise.h; weak returns drop out);
//   point  = d_scanner * range (scanner frame, float);
//   intensity = |cos(incidence)| = |d . n_face| in [0, 1] (a Lambertian
//               return with no range fall-off);
//   label  = the hit SceneMesh's label (scene.h), | kTrueEdgeFlag when the
//            mesh is a link mesh and the noise-free hit o + t d lies within
//            true_edge_distance of one of its sharp edges (exact distance,
//            edge_proximity.h).
// The noise n is a counter-based hash of (seed, scan index, cell index), so
// a scan is bitwise identical for any thread count and schedule.
//
// Grid: the angular step is the same in azimuth and elevation,
//   step = spacing / distance(scanner origin, asset box centre) [rad],
// so neighbouring points on the asset are ~spacing apart (paper: ~1.7 mm).
// The window spans the asset box as seen from the scanner plus a margin,
// or the full dome (360 deg x [-60, +90) deg, azimuth step rounded so the
// columns close the circle).
#ifndef EDGEFIT_SCANNER_VIRTUAL_SCANNER_H_
#define EDGEFIT_SCANNER_VIRTUAL_SCANNER_H_

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/scan/organized_scan.h"
#include "edgefit/scanner/beam_footprint.h"
#include "edgefit/scanner/depth_camera.h"
#include "edgefit/scanner/range_noise.h"
#include "edgefit/scene/scene.h"

namespace edgefit {

struct VirtualScanOptions {
  // Point spacing on the asset [m]: angular step = spacing / distance from
  // the scanner to the asset box centre. Paper Sec. 7.3: ~1.7 mm.
  double spacing = 0.0017;
  // Gaussian range noise along the ray, standard deviation [m] (paper: 1 mm).
  // 0 gives noise-free points.
  double noise_sigma = 0.001;
  // Rays with no hit closer than this are missing cells [m].
  double max_range = 60.0;
  // false: the window covers the asset box plus window_margin_deg;
  // true: 360 deg azimuth x [dome_min_elevation_deg, 90) deg elevation.
  bool full_dome = false;
  double window_margin_deg = 5.0;         // [deg] added on every side of the asset's window
  double dome_min_elevation_deg = -60.0;  // [deg] lowest row of a full dome
  // Box the window covers and the spacing refers to (world frame). Unset:
  // the box of every non-background mesh (links and accessories), or of the
  // whole scene when there are none.
  std::optional<Eigen::AlignedBox3d> asset_box_world;
  // kTrueEdgeFlag: distance of the noise-free hit to a sharp edge [m], and
  // the face-normal angle that makes a mesh edge sharp [deg].
  double true_edge_distance = 0.0015;
  double sharp_edge_min_dihedral_deg = 30.0;
  // A grid larger than this fails (a mistyped spacing would exhaust memory).
  int64_t max_cells_per_scan = 200'000'000;
  // The beam's footprint and mixed pixels (beam_footprint.h); default: an
  // ideal ray per cell.
  BeamOptions beam;
  // Range noise and dropouts by incidence and reflectance (range_noise.h);
  // default: noise_sigma everywhere, no dropouts.
  RangeNoiseOptions range_noise;
  // A depth camera instead of the laser scanner (depth_camera.h): one ray
  // per pixel, the scanner pose is the camera's optical frame, spacing,
  // noise_sigma, full_dome and the window are unused; its depth noise
  // replaces the range noise. Set beam to camera.FlyingPixelBeam() for
  // its flying pixels.
  DepthCameraOptions camera;
  // Embree RTC_SCENE_FLAG_ROBUST (slower; avoids rare misses on shared edges).
  bool robust = false;
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

struct VirtualScan {
  ScanSet scans;  // one organized scan per scanner pose, in pose order
  // Per scan, per cell in cell index order (col * rows + row): the label of
  // scene.h (0 missing, 1 background, 2 accessory, 3 + k link k, | kTrueEdgeFlag).
  std::vector<std::vector<uint16_t>> labels;
  std::vector<double> ray_seconds;  // per scan: wall time of the ray casting [s]
  size_t rays = 0;                  // rays cast over all scans
};

// The angular window of one scan (exposed for tests and the command line):
// the exact lattice ScanScene uses for a scanner at T_world_scanner.
Status MakeScanLattice(const Eigen::AlignedBox3d& asset_box_world, const Pose& T_world_scanner,
                       const VirtualScanOptions& options, ScanLattice* lattice);

// The asset box ScanScene uses when options.asset_box_world is unset.
Eigen::AlignedBox3d DefaultAssetBox(const Scene& scene);

// Holds an Embree device and the committed scene of one Scene, plus the
// sharp-edge indices of its link meshes, so several scans (or benchmark
// repetitions) reuse one BVH. Not copyable; Scan may be called from one
// thread at a time (it parallelises internally with OpenMP over columns).
class VirtualScanner {
 public:
  ~VirtualScanner();
  VirtualScanner(const VirtualScanner&) = delete;
  VirtualScanner& operator=(const VirtualScanner&) = delete;

  // Builds the BVH (Embree, high build quality) and the true-edge indices.
  // Fails on an empty scene, non-finite vertices or any Embree error.
  static Status Create(const Scene& scene, const VirtualScanOptions& options,
                       std::unique_ptr<VirtualScanner>* scanner);

  // Scans from every pose; replaces *out. Options that shape the BVH or the
  // edge indices (robust, true_edge_distance, sharp_edge_min_dihedral_deg)
  // are those given to Create.
  Status Scan(const std::vector<Pose>& T_world_scanner, const VirtualScanOptions& options,
              VirtualScan* out) const;

  size_t triangle_count() const;

 private:
  struct Impl;
  explicit VirtualScanner(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Create + Scan in one call.
Status ScanScene(const Scene& scene, const std::vector<Pose>& T_world_scanner,
                 const VirtualScanOptions& options, VirtualScan* out);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_VIRTUAL_SCANNER_H_
