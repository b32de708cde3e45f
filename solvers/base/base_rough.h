// Rough registration of a robot's base link (paper Sec. 5.1.1): the base
// stands level on the floor, so its pose is (x, y, yaw) plus the floor
// height. Horizontal cross-sections of the scan's wireframe and of the base
// mesh are cut at the same heights above the floor; their corners (Eq. 7)
// are matched by RANSAC: two scan corners and two model corners at equal
// distance at one height give a hypothesis, scored by how many model
// section points land on scan section points at every height. A round
// base with few corners may show no pair: then single corners are matched
// with the yaw on a grid (BaseRoughOptions::single_corner_*). No manual
// initialisation; an optional box limits the scan to a region.
// The floor's height is given (floor_height.h).
#ifndef EDGEFIT_SOLVERS_BASE_BASE_ROUGH_H_
#define EDGEFIT_SOLVERS_BASE_BASE_ROUGH_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/scan/organized_scan.h"
#include "edgefit/scan/scan_noise.h"
#include "solvers/base/cross_sections.h"

namespace edgefit {

struct BaseRoughOptions {
  // Section heights as fractions of the base mesh's height above its lowest
  // point, each at least min_height above it (the floor touches the bottom).
  std::vector<double> height_fractions = {0.05, 0.2, 0.35, 0.5, 0.7, 0.85};
  double min_height = 0.015;  // [m]
  // Wireframe: grid neighbours farther apart are not joined [m].
  double max_edge = 0.03;
  // Model sections are sampled at this spacing [m].
  double model_spacing = 0.002;
  CornerOptions corners;
  // RANSAC: scan corner pairs drawn, model pairs whose length differs by
  // less than pair_tolerance [m] are tried in both orders; a model section
  // point is an inlier within inlier_distance [m] of a scan section point.
  int iterations = 3000;
  double pair_tolerance = 0.01;
  double min_pair_length = 0.05;  // [m]
  double inlier_distance = 0.01;
  int score_points_per_section = 400;  // model points scored per height
  uint64_t seed = 1;
  // The best hypotheses kept (distinct: yaw apart by more than 3 degrees or
  // positions by more than 2 cm), for the caller to choose from with a 3D
  // test; symmetric bases (a square plate) score alike in 2D.
  int candidates = 6;
  // Single-corner search, run when the corner pairs' best hypothesis scores
  // below this share of the model section points (few corners, one hidden):
  // each scan corner onto each model corner, the yaw on a grid of
  // single_corner_yaw_step [rad]; the single_corner_rescored best by a sparse
  // score are scored in full.
  double single_corner_below_share = 0.3;
  double single_corner_yaw_step = 1.0 * M_PI / 180.0;
  int single_corner_rescored = 200;
  // Optional region of the scan (world frame); empty: the whole scan.
  Eigen::AlignedBox3d roi_world;
  // The distances above (corners.radius, corners.separation,
  // pair_tolerance, inlier_distance) were set on laser scans. A section's
  // straight run with scatter sigma across it has the PCA curvature
  // sigma^2 / (sigma^2 + radius^2 / 3): 0.013 at 1 mm, min_curvature
  // (0.06) at 2.2 mm, 0.18 at 4 mm, where every run reads as a corner and
  // the mean hides the real ones. ScaledToNoise widens the four
  // distances by sigma / noise_reference (at most max_noise_scale), sigma
  // the scan's local noise (scan_noise.h, the median over the scan). It
  // reads 0.4 mm on a laser scan with 1 mm of range noise, 0.65 mm with
  // 2 mm, 0.75 mm with the realistic sensor, 0.8 mm on the ZED 2i frames
  // (the matcher smooths its centimetre): all at k = 1; 3-4 mm on virtual
  // depth frames at 3-4 m, where the bases of the bundled robot and a
  // KUKA KR 150 were found within 35 mm on 11 of 18 frames at k = 3-4
  // against 6 of 18 unscaled (benchmarks/results/2026-11-29-noisy-sections.md).
  double noise_reference = 0.001;
  double max_noise_scale = 6.0;
  // A depth camera's noise grows with the square of the range, and the
  // scan's median is mostly its near surfaces': the bundled robot's frame at
  // 3.9 m (B6 002 of the page below) read 1.0 mm, found no corner at k = 1,
  // and was found 12 mm off at 4 mm. NoiseLevels gives the median's sigma
  // and that of every range bin (ScanNoise::sigma) whose k is more than
  // noise_level_ratio times the nearest one kept; the upright stage runs at
  // each and ranks their candidates together (base_stage.cc). A laser
  // scan's bins all sit at k = 1: one level, as before.
  double noise_level_ratio = 1.5;

  bool IsValid(std::string* error) const;
  // These options for a scan whose local noise (scan_noise.h) is sigma [m]:
  // the four distances times k = clamp(sigma / noise_reference, 1,
  // max_noise_scale); unchanged at k = 1.
  BaseRoughOptions ScaledToNoise(double sigma) const;
  // That k for sigma [m]; 1 for NaN (no measurement).
  double NoiseScale(double sigma) const;
  // The sigmas [m] to scale to, the median's first, then by rising k.
  std::vector<double> NoiseLevels(const ScanNoise& noise) const;
};

struct BaseRoughResult {
  Pose T_world_base = Pose::Identity();  // the best hypothesis
  std::vector<Pose> candidates;          // distinct hypotheses, best first (incl. the best)
  double floor_z = 0.0;                  // [m]
  int scan_corners = 0;                  // over all heights
  int model_corners = 0;
  int hypotheses = 0;         // scored
  double inlier_share = 0.0;  // of the scored model section points, at the best pose
  double seconds = 0.0;
};

// base_mesh_link: the base link's mesh in its link frame (z up when the
// robot stands level); floor_z: the scan's floor height [m, world]
// (EstimateFloorHeight). Fails with a message when no corners or no
// hypothesis is found.
Status FitBaseRough(const ScanSet& scans, double floor_z, const TriangleMesh& base_mesh_link,
                    const BaseRoughOptions& options, BaseRoughResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_BASE_ROUGH_H_
