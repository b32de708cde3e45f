// The virtual depth camera (depth_camera.h): its pose, its pixel grid, depth
// noise that grows with depth^2 and is correlated over a matcher's window,
// flying pixels at silhouettes, and scans independent of the thread count.
#include "edgefit/scanner/depth_camera.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <vector>

#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scanner/virtual_scanner.h"

namespace edgefit {
namespace {

DepthCameraOptions Camera() {
  DepthCameraOptions camera;
  camera.width = 320;
  camera.height = 240;
  camera.camera.fx = camera.camera.fy = 300.0;
  camera.camera.cx = 159.5;
  camera.camera.cy = 119.5;
  return camera;
}

SceneMesh Box(const Eigen::Vector3d& size, const Eigen::Vector3d& centre, uint16_t label) {
  SceneMesh m;
  Pose T = Pose::Identity();
  T.translation() = centre;
  m.mesh_world.Append(MakeBoxMesh(size), T);
  m.label = label;
  m.kind = "box";
  return m;
}

// A wall facing the camera at x = 2 (its face at x = 1.9), a camera at the
// origin looking along +x.
Scene Wall() {
  Scene scene;
  scene.meshes.push_back(Box(Eigen::Vector3d(0.2, 8.0, 8.0), Eigen::Vector3d(2.0, 0, 0), kLabelBackground));
  return scene;
}

Pose CameraAlongX() {
  Pose T;
  EXPECT_TRUE(LookAt(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::UnitZ(), &T));
  return T;
}

TEST(DepthCameraTest, LookAtPointsTheOpticalAxisAtTheTargetWithUpUp) {
  Pose T;
  ASSERT_TRUE(LookAt(Eigen::Vector3d(3, 1, 1.5), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ(), &T));
  const Eigen::Vector3d target_camera = T.inverse() * Eigen::Vector3d(0, 0, 1);
  EXPECT_NEAR(target_camera.x(), 0.0, 1e-12);
  EXPECT_NEAR(target_camera.y(), 0.0, 1e-12);
  EXPECT_GT(target_camera.z(), 0.0);
  // A point above the target is up in the image: negative y (rows go down).
  EXPECT_LT((T.inverse() * Eigen::Vector3d(0, 0, 2)).y(), 0.0);
  EXPECT_NEAR(T.linear().determinant(), 1.0, 1e-12);
  EXPECT_FALSE(LookAt(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 2), Eigen::Vector3d::UnitZ(), &T));
  EXPECT_FALSE(LookAt(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), &T));
}

TEST(DepthCameraTest, ScansThePixelGridWithNoiseGrowingWithDepthSquared) {
  VirtualScanOptions options;
  options.camera = Camera();
  options.camera.footprint_px = 0.0;
  options.camera.sigma_at_1m = 0.0025;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(Wall(), {CameraAlongX()}, options, &scan).ok());
  const OrganizedScan& s = scan.scans.scans[0];
  ASSERT_EQ(s.rows(), 240);
  ASSERT_EQ(s.cols(), 320);
  EXPECT_EQ(s.lattice().model(), ScanLattice::Model::kProjective);
  EXPECT_DOUBLE_EQ(s.lattice().camera().fx, 300.0);
  // Every pixel sees the wall, at depth 1.9 m plus noise of 2.5 mm * 1.9^2.
  const double sigma = 0.0025 * 1.9 * 1.9;
  double sum = 0.0, sum_sq = 0.0, diff_sq = 0.0;
  size_t n = 0, diffs = 0;
  for (int r = 0; r < s.rows(); ++r) {
    for (int c = 0; c < s.cols(); ++c) {
      ASSERT_TRUE(s.IsValid(s.Index(r, c))) << r << " " << c;
      const Eigen::Vector3f p = s.point_scanner(s.Index(r, c));
      const double e = p.z() - 1.9;
      sum += e;
      sum_sq += e * e;
      ++n;
      // The pixel lies on its own ray: x / z and y / z are the pixel's.
      EXPECT_NEAR(300.0 * p.x() / p.z() + 159.5, c, 1e-3);
      EXPECT_NEAR(300.0 * p.y() / p.z() + 119.5, r, 1e-3);
      if (c > 0) {
        const double d = p.z() - s.point_scanner(s.Index(r, c - 1)).z();
        diff_sq += d * d;
        ++diffs;
      }
    }
  }
  const double mean = sum / n, std = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_NEAR(std, sigma, 0.25 * sigma);
  EXPECT_LT(std::abs(mean), 0.5 * sigma);
  // Correlated over the matcher's window: neighbours differ far less than
  // independent draws would (sqrt(2) sigma).
  EXPECT_LT(std::sqrt(diff_sq / diffs), 0.8 * sigma);

  // The same wall at twice the depth: four times the noise.
  Pose T_far = CameraAlongX();
  T_far.translation().x() = -1.9;
  ASSERT_TRUE(ScanScene(Wall(), {T_far}, options, &scan).ok());
  const OrganizedScan& far = scan.scans.scans[0];
  double far_sq = 0.0;
  for (size_t i = 0; i < far.size(); ++i) far_sq += std::pow(far.point_scanner(i).z() - 3.8, 2);
  EXPECT_NEAR(std::sqrt(far_sq / far.size()), 4.0 * sigma, 1.2 * sigma);
}

TEST(DepthCameraTest, FlyingPixelsFloatAtSilhouettesOnlyWithAFootprint) {
  Scene scene = Wall();
  scene.meshes.push_back(Box(Eigen::Vector3d(0.3, 0.3, 0.3), Eigen::Vector3d(1.0, 0, 0), kLabelAccessory));
  VirtualScanOptions options;
  options.camera = Camera();
  options.camera.sigma_at_1m = 0.0;
  auto floating = [&](double footprint_px) {
    options.camera.footprint_px = footprint_px;
    options.beam = options.camera.FlyingPixelBeam();
    VirtualScan scan;
    EXPECT_TRUE(ScanScene(scene, {CameraAlongX()}, options, &scan).ok());
    const OrganizedScan& s = scan.scans.scans[0];
    size_t between = 0, flagged = 0;
    for (size_t i = 0; i < s.size(); ++i) {
      if (!s.IsValid(i)) continue;
      const float z = s.point_scanner(i).z();
      between += z > 0.9f && z < 1.85f && std::abs(z - 0.85f) > 0.01f;
      flagged += (scan.labels[0][i] & kMixedPixelFlag) != 0;
    }
    return std::make_pair(between, flagged);
  };
  const auto [ideal_between, ideal_flagged] = floating(0.0);
  EXPECT_EQ(ideal_between, 0u);
  EXPECT_EQ(ideal_flagged, 0u);
  const auto [between, flagged] = floating(2.0);
  // The box's outline is about 4 x 106 pixels long at 0.85 m (300 px / m at 1 m).
  EXPECT_GT(between, 100u);
  EXPECT_GE(flagged, between / 2);
}

TEST(DepthCameraTest, AScanIsTheSameForAnyThreadCount) {
  Scene scene = Wall();
  scene.meshes.push_back(Box(Eigen::Vector3d(0.3, 0.3, 0.3), Eigen::Vector3d(1.0, 0, 0), kLabelAccessory));
  VirtualScanOptions options;
  options.camera = Camera();
  options.beam = options.camera.FlyingPixelBeam();
  const int saved = omp_get_max_threads();
  VirtualScan one, two;
  omp_set_num_threads(1);
  ASSERT_TRUE(ScanScene(scene, {CameraAlongX()}, options, &one).ok());
  omp_set_num_threads(2);
  ASSERT_TRUE(ScanScene(scene, {CameraAlongX()}, options, &two).ok());
  omp_set_num_threads(saved);
  const OrganizedScan &a = one.scans.scans[0], &b = two.scans.scans[0];
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.IsValid(i), b.IsValid(i)) << i;
    if (a.IsValid(i)) {
      ASSERT_EQ(a.point_scanner(i), b.point_scanner(i)) << i;
    }
  }
  EXPECT_EQ(one.labels, two.labels);
}

TEST(DepthCameraTest, RejectsAnInvalidCamera) {
  VirtualScanOptions options;
  options.camera = Camera();
  std::string error;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.camera.camera.fx = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  options.camera = Camera();
  options.camera.correlated_share = 1.5;
  EXPECT_FALSE(options.IsValid(&error));
  options.camera = Camera();
  options.camera.footprint_px = -1.0;
  EXPECT_FALSE(options.IsValid(&error));
}

}  // namespace
}  // namespace edgefit
