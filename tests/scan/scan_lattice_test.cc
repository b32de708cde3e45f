#include "edgefit/scan/scan_lattice.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <vector>

namespace edgefit {
namespace {

ScanLattice MakeLattice(int rows, int cols, double e0, double de, double a0, double da,
                           const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  std::vector<double> e(static_cast<size_t>(rows)), a(static_cast<size_t>(cols));
  for (int r = 0; r < rows; ++r) e[r] = e0 + r * de;
  for (int c = 0; c < cols; ++c) a[c] = a0 + c * da;
  return ScanLattice(e, a, R);
}

TEST(ScanLatticeTest, ProjectInvertsDirection) {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.03, Eigen::Vector3d(1, 2, 0).normalized()).toRotationMatrix();
  const ScanLattice lattice = MakeLattice(40, 70, -0.6, 0.025, 2.5, 0.02, R);
  EXPECT_NEAR(lattice.row_step(), 0.025, 1e-12);
  EXPECT_NEAR(lattice.col_step(), 0.02, 1e-12);
  EXPECT_FALSE(lattice.full_circle());
  for (int r = 0; r < lattice.rows(); r += 3) {
    for (int c = 0; c < lattice.cols(); c += 5) {
      const Eigen::Vector3d p = 7.5 * lattice.Direction(r, c);
      double fr, fc;
      ASSERT_TRUE(lattice.Project(p, &fr, &fc));
      EXPECT_NEAR(fr, r, 1e-9);
      EXPECT_NEAR(fc, c, 1e-9);
      int ir, ic;
      ASSERT_TRUE(lattice.ProjectToCell(p, &ir, &ic));
      EXPECT_EQ(ir, r);
      EXPECT_EQ(ic, c);
      EXPECT_NEAR(lattice.Direction(r, c).norm(), 1.0, 1e-12);
    }
  }
}

TEST(ScanLatticeTest, FractionalPositionBetweenCells) {
  const ScanLattice lattice = MakeLattice(10, 10, 0.0, 0.1, 0.0, 0.1);
  const double e = 0.325, a = 0.41;
  const Eigen::Vector3d p(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  double r, c;
  ASSERT_TRUE(lattice.Project(3.0 * p, &r, &c));
  EXPECT_NEAR(r, 3.25, 1e-9);
  EXPECT_NEAR(c, 4.1, 1e-9);
}

TEST(ScanLatticeTest, RejectsOutsideAndOrigin) {
  const ScanLattice lattice = MakeLattice(10, 10, 0.0, 0.1, 0.0, 0.1);
  double r, c;
  EXPECT_FALSE(lattice.Project(Eigen::Vector3d::Zero(), &r, &c));
  EXPECT_FALSE(lattice.Project(Eigen::Vector3d(-1, 0, 0.1), &r, &c));    // behind
  EXPECT_FALSE(lattice.Project(Eigen::Vector3d(1, 0.1, -0.5), &r, &c));  // below row 0
  EXPECT_TRUE(lattice.Project(Eigen::Vector3d(1, -0.04, 0.0), &r, &c));  // half a step out
  EXPECT_NEAR(c, -0.4, 1e-2);
}

TEST(ScanLatticeTest, AnglesAgreeWithLibm) {
  // Directions in every octant, on the octants' borders and on the axes.
  const ScanLattice lattice = MakeLattice(3, 3, -0.1, 0.1, -0.1, 0.1);
  uint64_t state = 12345;
  auto uniform = [&state] {  // [-1, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-52 - 1.0;
  };
  std::vector<Eigen::Vector3d> directions = {{1, 0, 0},  {0, 1, 0},  {-1, 0, 0}, {0, -1, 0},
                                             {0, 0, 1},  {0, 0, -1}, {1, 1, 1},  {-1, -1, -1},
                                             {1, -1, 0}, {-1, 1, 0}, {2, 1, 0.5}};
  for (int i = 0; i < 100000; ++i) directions.emplace_back(uniform(), uniform(), uniform());
  for (const Eigen::Vector3d& d : directions) {
    double elevation, azimuth;
    lattice.Angles(d, &elevation, &azimuth);
    EXPECT_NEAR(elevation, std::atan2(d.z(), std::hypot(d.x(), d.y())), 2e-13) << d.transpose();
    EXPECT_NEAR(azimuth, std::atan2(d.y(), d.x()), 2e-13) << d.transpose();
  }
}

TEST(ScanLatticeTest, FullCircleHasNoSeam) {
  // Decreasing azimuths that cross +-pi, as a scanner turning clockwise.
  const int cols = 360;
  const ScanLattice lattice = MakeLattice(5, cols, -0.1, 0.05, 3.0, -2.0 * M_PI / cols);
  EXPECT_TRUE(lattice.full_circle());
  for (int c = 0; c < cols; ++c) {
    int ir, ic;
    ASSERT_TRUE(lattice.ProjectToCell(lattice.Direction(2, c), &ir, &ic));
    EXPECT_EQ(ic, c);
  }
  // Between the last column and the first one (one turn later): the seam.
  const double a = 3.0 + 0.4 * 2.0 * M_PI / cols;
  double r, c;
  ASSERT_TRUE(lattice.Project(Eigen::Vector3d(std::cos(a), std::sin(a), 0.0), &r, &c));
  EXPECT_NEAR(c, -0.4, 1e-6);
  int ir, ic;
  const double a2 = 3.0 + 0.6 * 2.0 * M_PI / cols;
  ASSERT_TRUE(lattice.ProjectToCell(Eigen::Vector3d(std::cos(a2), std::sin(a2), 0.0), &ir, &ic));
  EXPECT_EQ(ic, cols - 1);
}

}  // namespace
}  // namespace edgefit
