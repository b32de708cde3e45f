#include "edgefit/scanner/virtual_scanner.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>

#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scanner/edge_proximity.h"
#include "scanner/scanner_test_util.h"

namespace edgefit {
namespace {

using testing_util::FloorMesh;

SceneMesh Mesh(const TriangleMesh& mesh, const Eigen::Vector3d& centre, uint16_t label,
               int link = -1) {
  SceneMesh m;
  Pose T = Pose::Identity();
  T.translation() = centre;
  m.mesh_world.Append(mesh, T);
  m.label = label;
  m.link = link;
  m.kind = link >= 0 ? "link" : "box";
  return m;
}

// A scanner at (x, y, z) looking along +x.
Pose ScannerAt(double x, double y, double z) {
  Pose T = Pose::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

TEST(VirtualScannerTest, BoxOccludesSphereAndRaysNeverPassThrough) {
  Scene scene;
  scene.meshes.push_back(FloorMesh());
  // A 0.3 m box at x = 2 in front of a 0.4 m sphere at x = 3.5, both at scanner height.
  const Eigen::AlignedBox3d box(Eigen::Vector3d(1.85, -0.15, 1.35), Eigen::Vector3d(2.15, 0.15, 1.65));
  scene.meshes.push_back(Mesh(MakeBoxMesh(box.sizes()), box.center(), kLabelAccessory));
  scene.meshes.push_back(Mesh(MakeSphereMesh(0.4, 4), Eigen::Vector3d(3.5, 0, 1.5), LinkLabel(0), 0));
  VirtualScanOptions options;
  options.spacing = 0.004;
  options.noise_sigma = 0.0;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {ScannerAt(0, 0, 1.5)}, options, &scan).ok());
  ASSERT_EQ(scan.scans.scans.size(), 1u);
  const OrganizedScan& s = scan.scans.scans[0];
  const auto& labels = scan.labels[0];
  ASSERT_EQ(labels.size(), s.size());
  EXPECT_EQ(scan.rays, s.size());
  size_t sphere = 0, accessory = 0, hidden_by_box = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const uint16_t cls = labels[i] & kLabelMask;
    EXPECT_EQ(cls == kLabelMissing, !s.IsValid(i));
    if (cls == kLabelAccessory) ++accessory;
    if (cls != LinkLabel(0)) continue;
    ++sphere;
    // The segment scanner -> point must not cross the box (slab test).
    const Eigen::Vector3d p = s.PointWorld(i), o(0, 0, 1.5), d = p - o;
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 3; ++k) {
      double a = (box.min()[k] - o[k]) / d[k], b = (box.max()[k] - o[k]) / d[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    if (t0 <= t1) ++hidden_by_box;
  }
  EXPECT_GT(accessory, 1000u);
  EXPECT_GT(sphere, 1000u);
  EXPECT_EQ(hidden_by_box, 0u);
  // The centre column/row looks straight at the box: it must be the accessory.
  int row, col;
  ASSERT_TRUE(s.lattice().ProjectToCell(Eigen::Vector3d(1, 0, 0), &row, &col));
  EXPECT_EQ(labels[s.Index(row, col)], kLabelAccessory);
  EXPECT_NEAR(s.point_scanner(s.Index(row, col)).x(), 1.85, 1e-4);
}

TEST(VirtualScannerTest, LatticeReprojectsEveryPointToItsCell) {
  Scene scene;
  scene.meshes.push_back(FloorMesh());
  scene.meshes.push_back(Mesh(MakeBoxMesh({0.6, 0.8, 1.0}), {3, 1, 0.5}, LinkLabel(0), 0));
  VirtualScanOptions options;
  options.spacing = 0.003;
  Pose T = Pose::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(-0.5, -1.0, 1.4);
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {T, ScannerAt(6, 4, 1.6)}, options, &scan).ok());
  for (const OrganizedScan& s : scan.scans.scans) {
    ASSERT_TRUE(s.lattice().valid());
    EXPECT_EQ(s.lattice().rows(), s.rows());
    EXPECT_EQ(s.lattice().cols(), s.cols());
    EXPECT_NEAR(std::abs(s.lattice().col_step()), std::abs(s.lattice().row_step()), 1e-12);
    size_t valid = 0, wrong = 0;
    for (size_t i = 0; i < s.size(); ++i) {
      if (!s.IsValid(i)) continue;
      ++valid;
      int row, col;
      if (!s.lattice().ProjectToCell(s.point_scanner(i).cast<double>(), &row, &col) ||
          row != s.RowOf(i) || col != s.ColOf(i)) {
        ++wrong;
      }
    }
    EXPECT_GT(valid, 10000u);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(VirtualScannerTest, IdenticalForOneAndTwoThreads) {
  Scene scene;
  scene.meshes.push_back(FloorMesh());
  scene.meshes.push_back(Mesh(MakeSphereMesh(0.5, 3), {3, 0, 1}, LinkLabel(1), 1));
  scene.meshes.push_back(Mesh(MakeBoxMesh({0.5, 0.5, 0.5}), {2.5, 0.8, 0.25}, LinkLabel(0), 0));
  VirtualScanOptions options;
  options.spacing = 0.003;
  options.seed = 42;
  const std::vector<Pose> poses = {ScannerAt(0, 0, 1.5), ScannerAt(0, 2, 1.3)};
  VirtualScan a, b;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  ASSERT_TRUE(ScanScene(scene, poses, options, &a).ok());
  omp_set_num_threads(2);
  ASSERT_TRUE(ScanScene(scene, poses, options, &b).ok());
  omp_set_num_threads(saved);
  ASSERT_EQ(a.scans.scans.size(), b.scans.scans.size());
  for (size_t k = 0; k < a.scans.scans.size(); ++k) {
    const OrganizedScan& sa = a.scans.scans[k];
    const OrganizedScan& sb = b.scans.scans[k];
    ASSERT_EQ(sa.size(), sb.size());
    EXPECT_EQ(a.labels[k], b.labels[k]);
    for (size_t i = 0; i < sa.size(); ++i) {
      ASSERT_EQ(std::memcmp(sa.point_scanner(i).data(), sb.point_scanner(i).data(), 12), 0) << i;
      const float ia = sa.intensity(i), ib = sb.intensity(i);
      ASSERT_EQ(std::memcmp(&ia, &ib, 4), 0) << i;
    }
  }
  // A different seed changes the noise.
  options.seed = 43;
  VirtualScan c;
  ASSERT_TRUE(ScanScene(scene, poses, options, &c).ok());
  size_t differ = 0;
  for (size_t i = 0; i < a.scans.scans[0].size(); ++i) {
    if (a.scans.scans[0].IsValid(i) &&
        a.scans.scans[0].point_scanner(i) != c.scans.scans[0].point_scanner(i)) {
      ++differ;
    }
  }
  EXPECT_GT(differ, 1000u);
}

TEST(VirtualScannerTest, RangeNoiseSigmaMatchesOption) {
  // A wall x = 3 facing the scanner: the noise-free range of cell direction d
  // is 3 / d.x, so range - 3 / d.x is the noise.
  Scene scene;
  SceneMesh wall;
  wall.mesh_world.vertices = {{3, -5, -5}, {3, 5, -5}, {3, 5, 5}, {3, -5, 5}};
  wall.mesh_world.triangles = {{0, 1, 2}, {0, 2, 3}};
  wall.label = LinkLabel(0);
  wall.link = 0;
  scene.meshes.push_back(wall);
  VirtualScanOptions options;
  options.spacing = 0.005;
  options.asset_box_world = Eigen::AlignedBox3d(Eigen::Vector3d(3, -1, -1), Eigen::Vector3d(3, 1, 1));
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {Pose::Identity()}, options, &scan).ok());
  const OrganizedScan& s = scan.scans.scans[0];
  double sum = 0, sum2 = 0;
  size_t n = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!s.IsValid(i)) continue;
    const Eigen::Vector3d d = s.lattice().Direction(s.RowOf(i), s.ColOf(i));
    const double e = s.point_scanner(i).cast<double>().norm() - 3.0 / d.x();
    sum += e;
    sum2 += e * e;
    ++n;
  }
  ASSERT_GT(n, 100000u);
  const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 5e-5);
  EXPECT_NEAR(sigma, options.noise_sigma, 0.15 * options.noise_sigma);
}

TEST(VirtualScannerTest, TrueEdgeFlagsAreThePointsNearTheBoxEdges) {
  Scene scene;
  scene.meshes.push_back(FloorMesh());
  const Eigen::Vector3d size(0.4, 0.5, 0.6), centre(2.0, 0.3, 0.9);
  scene.meshes.push_back(Mesh(MakeBoxMesh(size), centre, LinkLabel(0), 0));
  VirtualScanOptions options;
  options.spacing = 0.0007;
  options.noise_sigma = 0.0;
  Pose T = ScannerAt(0.2, -0.9, 1.5);  // sees three faces, so edges between them
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {T}, options, &scan).ok());
  // The 12 edges of the box.
  std::vector<EdgeSegment> edges;
  const Eigen::Vector3d h = size / 2;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int su : {-1, 1}) {
      for (int sv : {-1, 1}) {
        Eigen::Vector3d a = centre, b = centre;
        a[axis] -= h[axis];
        b[axis] += h[axis];
        a[u] += su * h[u];
        b[u] += su * h[u];
        a[v] += sv * h[v];
        b[v] += sv * h[v];
        edges.push_back({a, b});
      }
    }
  }
  const OrganizedScan& s = scan.scans.scans[0];
  size_t flagged = 0, link = 0, mismatched = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    const uint16_t label = scan.labels[0][i];
    if (!IsLinkLabel(label)) {
      EXPECT_EQ(label & kTrueEdgeFlag, 0);
      continue;
    }
    ++link;
    const Eigen::Vector3d p = s.PointWorld(i);
    double d = 1e9;
    for (const EdgeSegment& e : edges) d = std::min(d, PointSegmentDistance(p, e.a, e.b));
    const bool is_flagged = (label & kTrueEdgeFlag) != 0;
    flagged += is_flagged;
    // Float points are ~0.5 um off the double hit the scanner tested.
    if (std::abs(d - options.true_edge_distance) < 5e-6) continue;
    if (is_flagged != (d <= options.true_edge_distance)) ++mismatched;
  }
  EXPECT_GT(link, 100000u);
  EXPECT_GT(flagged, 1000u);
  EXPECT_EQ(mismatched, 0u);
}

TEST(VirtualScannerTest, FullDomeClosesTheCircleAndMissesAreMissing) {
  Scene scene;
  scene.meshes.push_back(Mesh(MakeBoxMesh({1, 1, 1}), {3, 0, 0}, LinkLabel(0), 0));
  VirtualScanOptions options;
  options.spacing = 0.05;
  options.full_dome = true;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {Pose::Identity()}, options, &scan).ok());
  const OrganizedScan& s = scan.scans.scans[0];
  EXPECT_TRUE(s.lattice().full_circle());
  EXPECT_NEAR(s.lattice().elevation(0), -60.0 * M_PI / 180.0, 1e-12);
  EXPECT_LT(s.lattice().elevation(s.rows() - 1), M_PI / 2);
  size_t valid = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(s.IsValid(i), scan.labels[0][i] != kLabelMissing);
    valid += s.IsValid(i);
  }
  EXPECT_GT(valid, 100u);
  EXPECT_LT(valid, s.size() / 4);
}

TEST(VirtualScannerTest, BadInputIsAStatus) {
  VirtualScan scan;
  VirtualScanOptions options;
  EXPECT_FALSE(ScanScene(Scene{}, {Pose::Identity()}, options, &scan).ok());
  Scene scene;
  scene.meshes.push_back(FloorMesh());
  options.spacing = -1;
  EXPECT_FALSE(ScanScene(scene, {ScannerAt(0, 0, 1)}, options, &scan).ok());
  options.spacing = 1e-7;  // far too many cells
  options.asset_box_world = Eigen::AlignedBox3d(Eigen::Vector3d(2, -1, 0), Eigen::Vector3d(3, 1, 1));
  const Status status = ScanScene(scene, {ScannerAt(0, 0, 1)}, options, &scan);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("max_cells_per_scan"), std::string::npos) << status.message();
  SceneMesh broken = FloorMesh();
  broken.mesh_world.vertices[0].x() = std::nan("");
  scene.meshes.push_back(broken);
  options.spacing = 0.01;
  EXPECT_FALSE(ScanScene(scene, {ScannerAt(0, 0, 1)}, options, &scan).ok());
}

}  // namespace
}  // namespace edgefit
