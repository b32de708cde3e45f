// The projective lattice of a depth camera (scan_lattice.h, pinhole_camera.h)
// and its estimation from the points (lattice_estimation.h): projection
// inverts the rays with and without distortion, points behind the camera
// or off the image fall outside, the model is told from an angular scan's,
// and fx, fy, cx, cy come back from a frame's points.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "edgefit/scan/lattice_estimation.h"
#include "edgefit/scan/scan_lattice.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

PinholeCamera Camera() {
  PinholeCamera c;
  c.fx = 534.6;
  c.fy = 530.2;
  c.cx = 478.1;
  c.cy = 261.0;
  return c;
}

TEST(ProjectiveLatticeTest, ProjectInvertsDirection) {
  for (const bool distorted : {false, true}) {
    PinholeCamera camera = Camera();
    if (distorted) camera.distortion = {0.08, -0.05, 0.001, -0.0005, 0.01, 0.0, 0.0, 0.0};
    const ScanLattice lattice(540, 960, camera);
    EXPECT_EQ(lattice.model(), ScanLattice::Model::kProjective);
    EXPECT_STREQ(lattice.ModelName(), "projective");
    EXPECT_NEAR(lattice.row_step(), -1.0 / camera.fy, 1e-15);  // rows go down
    EXPECT_NEAR(lattice.col_step(), -1.0 / camera.fx, 1e-15);
    EXPECT_FALSE(lattice.full_circle());
    for (int r = 0; r < 540; r += 37) {
      for (int c = 0; c < 960; c += 53) {
        const Eigen::Vector3d d = lattice.Direction(r, c);
        EXPECT_NEAR(d.norm(), 1.0, 1e-12);
        double fr, fc;
        ASSERT_TRUE(lattice.Project(2.5 * d, &fr, &fc)) << r << " " << c;
        EXPECT_NEAR(fr, r, 1e-6) << distorted;
        EXPECT_NEAR(fc, c, 1e-6) << distorted;
      }
    }
  }
}

TEST(ProjectiveLatticeTest, BehindTheCameraAndOffTheImageAreOutside) {
  const ScanLattice lattice(540, 960, Camera());
  double r, c;
  EXPECT_FALSE(lattice.Project(Eigen::Vector3d(0.0, 0.0, -1.0), &r, &c));  // behind
  EXPECT_FALSE(lattice.Project(Eigen::Vector3d(1.0, 0.0, 0.0), &r, &c));   // in its plane
  EXPECT_FALSE(lattice.Project(Eigen::Vector3d(2.0, 0.0, 1.0), &r, &c));   // u = 1547
  EXPECT_TRUE(lattice.Project(Eigen::Vector3d(0.0, 0.0, 3.0), &r, &c));
  EXPECT_NEAR(c, 478.1, 1e-9);
  EXPECT_NEAR(r, 261.0, 1e-9);
  // Half a pixel beyond the first column is still in; a pixel is not.
  const Eigen::Vector3d left = Camera().Ray(-0.49, 100.0);
  EXPECT_TRUE(lattice.Project(left, &r, &c));
  EXPECT_FALSE(lattice.Project(Camera().Ray(-0.51, 100.0), &r, &c));
}

// A frame of a camera: a wall with a box in front, rows x cols pixels.
OrganizedScan CameraFrame(const PinholeCamera& camera, int rows, int cols, double missing_share) {
  OrganizedScan scan(rows, cols);
  scan.set_file_order(OrganizedScan::FileOrder::kRowMajor);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int v = 0; v < rows; ++v) {
    for (int u = 0; u < cols; ++u) {
      if (uniform(rng) < missing_share) continue;
      const bool box = std::abs(u - cols / 2) < cols / 6 && std::abs(v - rows / 2) < rows / 5;
      const double z = (box ? 1.4 : 3.0) + noise(rng);  // depth noise leaves x/z exact
      const Eigen::Vector3d p = z * camera.Ray(u, v);
      scan.SetPoint(scan.Index(v, u), p.cast<float>(), 0.0f);
    }
  }
  return scan;
}

TEST(ProjectiveLatticeTest, EstimatedFromTheFramesPoints) {
  const PinholeCamera camera = Camera();
  const OrganizedScan frame = CameraFrame(camera, 270, 480, 0.3);
  ScanLattice lattice;
  ASSERT_TRUE(EstimateLattice(frame, LatticeOptions(), &lattice).ok());
  ASSERT_EQ(lattice.model(), ScanLattice::Model::kProjective);
  EXPECT_NEAR(lattice.camera().fx, camera.fx, 1e-3);
  EXPECT_NEAR(lattice.camera().fy, camera.fy, 1e-3);
  EXPECT_NEAR(lattice.camera().cx, camera.cx, 1e-3);
  EXPECT_NEAR(lattice.camera().cy, camera.cy, 1e-3);
  EXPECT_EQ(lattice.rows(), 270);
  EXPECT_EQ(lattice.cols(), 480);
}

TEST(ProjectiveLatticeTest, AnAngularScanKeepsItsAngularLattice) {
  // A terrestrial scanner's window, every ray returning.
  testing::SyntheticScanOptions o;
  o.rows = 60;
  o.cols = 200;
  o.elevation_first = 0.2;
  o.elevation_step = 0.01;
  o.azimuth_first = -1.0;
  o.azimuth_step = 0.01;
  const OrganizedScan scan = testing::MakeSyntheticScan(testing::RoomScene(), o);
  ScanLattice lattice;
  ASSERT_TRUE(EstimateLattice(scan, LatticeOptions(), &lattice).ok());
  EXPECT_EQ(lattice.model(), ScanLattice::Model::kAngular);
  double rms_px = 0.0;
  const Status projective = EstimateProjectiveLattice(scan, LatticeOptions(), &lattice, &rms_px);
  EXPECT_TRUE(!projective.ok() || rms_px > 1.0) << rms_px;
}

TEST(ProjectiveLatticeTest, AFrameMostlyBehindItsAxisIsNotACamera) {
  OrganizedScan frame = CameraFrame(Camera(), 60, 80, 0.0);
  for (size_t i = 0; i < frame.size(); i += 2) {
    frame.SetPoint(i, -frame.point_scanner(i), 0.0f);
  }
  LatticeOptions options;
  options.model = LatticeOptions::Model::kProjective;
  ScanLattice lattice;
  const Status status = EstimateLattice(frame, options, &lattice);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("behind"), std::string::npos) << status.message();
}

}  // namespace
}  // namespace edgefit
