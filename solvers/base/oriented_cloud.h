// A scan set thinned to one point per voxel, each with a normal: what the
// searches that need no lattice work on (the pose voting of any mounting,
// the dominant plane that gives up). The point of a voxel is the centroid
// of the scan points in it; its normal the smallest principal axis of the
// voxel points within normal_radius (a 3D neighbourhood: depth noise of a
// centimetre needs more than a pixel window), turned toward the scanner
// that saw the voxel first.
#ifndef EDGEFIT_SOLVERS_BASE_ORIENTED_CLOUD_H_
#define EDGEFIT_SOLVERS_BASE_ORIENTED_CLOUD_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct OrientedCloudOptions {
  double voxel = 0.02;          // voxel edge [m]
  double normal_radius = 0.05;  // [m]
  // A voxel with fewer neighbours within normal_radius (itself included)
  // or a flatness below min_planarity gets no normal and is dropped.
  int min_neighbours = 5;
  // 1 - lambda_min / lambda_mid of the neighbourhood's covariance: 1 for a
  // plane, 0 for an isotropic blob.
  double min_planarity = 0.3;
  // Only points within this box [m, world]; empty: all.
  Eigen::AlignedBox3d roi_world;

  bool IsValid(std::string* error) const;
};

struct OrientedCloud {
  std::vector<Eigen::Vector3f> points;   // world frame [m]
  std::vector<Eigen::Vector3f> normals;  // unit, toward the scanner
  size_t size() const { return points.size(); }
};

// The thinned, oriented cloud of every valid point of `scans`, in voxel
// order (deterministic, any thread count).
OrientedCloud MakeOrientedCloud(const ScanSet& scans, const OrientedCloudOptions& options);

// The key of the voxel of edge `voxel` [m] that holds p: 21 bits per axis,
// +-1 M voxels (+-20 km at 2 cm).
int64_t VoxelKey(const Eigen::Vector3d& p, double voxel);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_ORIENTED_CLOUD_H_
