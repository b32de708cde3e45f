#include "edgefit/scan/lattice_estimation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "edgefit/core/angles.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

using testing::MakeSyntheticScan;
using testing::RoomScene;
using testing::SyntheticScanOptions;

struct LatticeCase {
  std::string name;
  SyntheticScanOptions options;
};

SyntheticScanOptions Base() {
  SyntheticScanOptions o;
  o.rows = 90;
  o.cols = 180;
  o.elevation_first = -50 * kDeg;
  o.elevation_step = 0.9 * kDeg;
  o.azimuth_first = -40 * kDeg;
  o.azimuth_step = 0.7 * kDeg;
  o.T_world_scanner = PoseFromXyzRpy(Eigen::Vector3d(0.3, -2.5, 1.4), Eigen::Vector3d(0, 0, 0.4));
  o.seed = 11;
  return o;
}

std::vector<LatticeCase> Cases() {
  std::vector<LatticeCase> cases;
  cases.push_back({"Clean", Base()});
  {
    auto o = Base();
    o.missing_fraction = 0.3;
    cases.push_back({"ThirtyPercentMissing", o});
  }
  {
    auto o = Base();
    o.missing_rows = {0, 1, 2, 45, 46, 89};
    o.missing_cols = {0, 17, 18, 19, 20, 100, 178, 179};
    cases.push_back({"MissingRowsAndColumns", o});
  }
  {
    auto o = Base();
    o.range_noise_m = 0.001;
    cases.push_back({"RangeNoise1mm", o});
  }
  {
    auto o = Base();
    o.R_scanner_lattice =
        Eigen::AngleAxisd(2 * kDeg, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
    cases.push_back({"Tilt2Degrees", o});
  }
  {
    auto o = Base();
    o.cols = 400;
    o.azimuth_first = 2.0;  // crosses +-pi
    o.azimuth_step = -2 * M_PI / o.cols;
    o.elevation_first = 40 * kDeg;
    o.elevation_step = -0.9 * kDeg;  // top to bottom
    cases.push_back({"Full360Decreasing", o});
  }
  {
    auto o = Base();
    o.cols = 241;
    o.azimuth_first = -60 * kDeg;
    o.azimuth_step = 0.5 * kDeg;
    cases.push_back({"Window120Degrees", o});
  }
  {
    auto o = Base();  // too narrow to observe the axis: no tilt estimate
    o.cols = 20;
    o.azimuth_step = 0.5 * kDeg;
    cases.push_back({"Window10Degrees", o});
  }
  {
    auto o = Base();
    o.cols = 360;
    o.azimuth_first = 0.0;
    o.azimuth_step = 2 * M_PI / o.cols;
    o.missing_fraction = 0.3;
    o.missing_rows = {10, 11};
    o.missing_cols = {0, 359, 100};
    o.range_noise_m = 0.001;
    o.R_scanner_lattice =
        Eigen::AngleAxisd(2 * kDeg, Eigen::Vector3d(0.3, -1, 0).normalized()).toRotationMatrix();
    cases.push_back({"Everything", o});
  }
  return cases;
}

class LatticeEstimationTest : public ::testing::TestWithParam<LatticeCase> {};

TEST_P(LatticeEstimationTest, RecoversKnownLattice) {
  const SyntheticScanOptions& options = GetParam().options;
  ScanLattice truth;
  const OrganizedScan scan = MakeSyntheticScan(RoomScene(), options, &truth);
  ScanLattice lattice;
  const Status status = EstimateLattice(scan, LatticeOptions(), &lattice);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(lattice.rows(), options.rows);
  ASSERT_EQ(lattice.cols(), options.cols);
  const double de = std::abs(options.elevation_step), da = std::abs(options.azimuth_step);
  EXPECT_NEAR(lattice.row_step(), options.elevation_step, 0.01 * de);
  EXPECT_NEAR(lattice.col_step(), options.azimuth_step, 0.01 * da);
  // Every ray direction within 1% of a step (angles are frame-free this way:
  // the lattice frame may turn about the axis relative to the truth).
  double worst = 0.0;
  for (int r = 0; r < options.rows; ++r) {
    for (int c = 0; c < options.cols; ++c) {
      const double angle = std::acos(std::min(1.0, lattice.Direction(r, c).dot(truth.Direction(r, c))));
      worst = std::max(worst, angle);
    }
  }
  EXPECT_LT(worst, 0.01 * std::min(de, da)) << "worst direction error [rad]";
  // Elevation per row in the tilt-corrected frame.
  const Eigen::Vector3d axis = lattice.R_scanner_lattice().col(2);
  const Eigen::Vector3d true_axis = options.R_scanner_lattice.col(2);
  EXPECT_LT(std::acos(std::min(1.0, axis.dot(true_axis))), 0.01 * de);
  for (int r = 0; r < options.rows; ++r) {
    EXPECT_NEAR(lattice.elevation(r), options.elevation_first + r * options.elevation_step, 0.01 * de);
  }
  // Every valid point projects to its own cell.
  size_t valid = 0, own = 0;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (!scan.IsValid(i)) continue;
    ++valid;
    int r, c;
    if (lattice.ProjectToCell(scan.point_scanner(i).cast<double>(), &r, &c) &&
        r == scan.RowOf(i) && c == scan.ColOf(i)) {
      ++own;
    }
  }
  ASSERT_GT(valid, scan.size() / 2);
  EXPECT_GE(static_cast<double>(own), 0.999 * static_cast<double>(valid));
}

INSTANTIATE_TEST_SUITE_P(Synthetic, LatticeEstimationTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<LatticeCase>& info) {
                           return info.param.name;
                         });

TEST(LatticeEstimationErrorTest, TooSparseScanFails) {
  SyntheticScanOptions o = Base();
  o.missing_fraction = 0.998;
  const OrganizedScan scan = MakeSyntheticScan(RoomScene(), o);
  ASSERT_LT(scan.CountValid(), 50u);
  ScanLattice lattice;
  const Status status = EstimateLattice(scan, LatticeOptions(), &lattice);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("too few valid points"), std::string::npos) << status.message();
}

TEST(LatticeEstimationErrorTest, EmptyScanFails) {
  const OrganizedScan scan(20, 30);
  ScanLattice lattice;
  EXPECT_FALSE(EstimateLattice(scan, LatticeOptions(), &lattice).ok());
}

TEST(LatticeEstimationErrorTest, SingleColumnOfPointsFails) {
  SyntheticScanOptions o = Base();
  for (int c = 1; c < o.cols; ++c) o.missing_cols.push_back(c);
  const OrganizedScan scan = MakeSyntheticScan(RoomScene(), o);
  ScanLattice lattice;
  const Status status = EstimateLattice(scan, LatticeOptions(), &lattice);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("columns"), std::string::npos) << status.message();
}

TEST(LatticeEstimationErrorTest, UnorganizedCloudFails) {
  OrganizedScan scan(1, 100);
  scan.set_organized(false);
  ScanLattice lattice;
  EXPECT_FALSE(EstimateLattice(scan, LatticeOptions(), &lattice).ok());
}

}  // namespace
}  // namespace edgefit
