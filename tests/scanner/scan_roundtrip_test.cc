// A virtual scan written as PTX reads back as the same grid, and the lattice
// estimated from the points matches the generator's exact one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "edgefit/io/scan_io.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "scanner/scanner_test_util.h"

namespace edgefit {
namespace {

TEST(ScanRoundTripTest, PtxReadsBackWithTheGeneratorsLattice) {
  Scene scene;
  scene.meshes.push_back(testing_util::FloorMesh());
  SceneMesh box;
  Pose T_box = Pose::Identity();
  T_box.translation() = Eigen::Vector3d(3, 0.5, 0.6);
  box.mesh_world.Append(MakeBoxMesh({0.8, 1.0, 1.2}), T_box);
  box.label = LinkLabel(0);
  box.link = 0;
  scene.meshes.push_back(box);
  Pose T_world_scanner = Pose::Identity();
  T_world_scanner.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T_world_scanner.translation() = Eigen::Vector3d(0.2, -0.4, 1.5);
  VirtualScanOptions options;
  options.spacing = 0.01;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {T_world_scanner, Pose(Eigen::Translation3d(6, 3, 1.3))}, options,
                        &scan)
                  .ok());

  const std::string path = (std::filesystem::temp_directory_path() /
                            ("scanner_roundtrip_" + std::to_string(getpid()) + ".ptx"))
                               .string();
  ASSERT_TRUE(WriteScans(path, scan.scans, WriteOptions{}).ok());
  ScanSet read;
  const Status status = ReadScans(path, ReadOptions{}, &read);
  std::filesystem::remove(path);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(read.scans.size(), scan.scans.scans.size());
  for (size_t k = 0; k < read.scans.size(); ++k) {
    const OrganizedScan& a = scan.scans.scans[k];
    const OrganizedScan& b = read.scans[k];
    EXPECT_EQ(b.rows(), a.rows());
    EXPECT_EQ(b.cols(), a.cols());
    EXPECT_EQ(b.CountValid(), a.CountValid());
    const double el = std::abs(a.lattice().row_step());
    const double az = std::abs(a.lattice().col_step());
    EXPECT_NEAR(std::abs(b.lattice().row_step()), el, 0.01 * el);
    EXPECT_NEAR(std::abs(b.lattice().col_step()), az, 0.01 * az);
    EXPECT_TRUE(b.T_world_scanner().isApprox(a.T_world_scanner(), 1e-6));
  }
}

}  // namespace
}  // namespace edgefit
