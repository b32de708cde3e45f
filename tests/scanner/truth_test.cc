#include "edgefit/scanner/truth.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "edgefit/core/atomic_file.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scanner/label_file.h"
#include "scanner/scanner_test_util.h"

namespace edgefit {
namespace {

std::string TempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("scanner_" + std::to_string(getpid()) + "_" + name))
      .string();
}

TEST(TruthTest, JsonRoundTripsWithAllMovingJoints) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(EDGEFIT_SOURCE_DIR "/assets/models/fk_arm.urdf", {}, &model).ok());
  std::vector<double> q = model.ZeroJoints();
  for (size_t j = 0; j < q.size(); ++j) q[j] = model.joints()[j].IsMoving() ? 0.1 * (j + 1) : 0.0;
  Truth truth;
  truth.urdf = "fk_arm.urdf";
  truth.attachments = {"tool.urdf@tool0"};
  truth.joints = NamedJointValues(model, q);
  truth.T_world_base = PoseFromXyYaw(1.5, -2.0, 0.25);
  truth.base_x = 1.5;
  truth.base_y = -2.0;
  truth.base_yaw = 0.25;
  truth.T_world_scanners = {PoseFromXyYaw(4, 0, 3.1), PoseFromXyYaw(0, 4, -1.5)};
  truth.seed = 12345678901234ULL;
  truth.settings = MakeTruthSettings(VirtualScanOptions{}, 2, true, true);
  truth.counts.cells = 10;
  truth.counts.valid = 7;
  truth.counts.per_link = {{"base_link", 3}};
  const std::string path = TempPath("truth.json");
  ASSERT_TRUE(WriteTruthJson(path, truth).ok());
  Truth read;
  ASSERT_TRUE(ReadTruthJson(path, &read).ok());
  std::filesystem::remove(path);

  size_t moving = 0;
  for (const Joint& j : model.joints()) moving += j.IsMoving();
  EXPECT_EQ(read.joints.size(), moving);
  EXPECT_EQ(read.joints, truth.joints);
  EXPECT_EQ(read.urdf, truth.urdf);
  EXPECT_EQ(read.attachments, truth.attachments);
  EXPECT_TRUE(read.T_world_base.isApprox(truth.T_world_base, 1e-15));
  EXPECT_EQ(read.base_yaw, 0.25);
  ASSERT_EQ(read.T_world_scanners.size(), 2u);
  EXPECT_TRUE(read.T_world_scanners[1].isApprox(truth.T_world_scanners[1], 1e-15));
  EXPECT_EQ(read.seed, truth.seed);
  EXPECT_EQ(read.settings.spacing, 0.0017);
  EXPECT_EQ(read.settings.noise_sigma, 0.001);
  EXPECT_TRUE(read.settings.accessories);
  EXPECT_EQ(read.counts.valid, 7u);
  EXPECT_EQ(read.counts.per_link, truth.counts.per_link);
}

TEST(TruthTest, BadJsonIsAStatus) {
  const std::string path = TempPath("bad.json");
  ASSERT_TRUE(WriteStringAtomically(path, "{\"joints\": {\"a\": \"x\"}}").ok());
  Truth truth;
  EXPECT_FALSE(ReadTruthJson(path, &truth).ok());
  ASSERT_TRUE(WriteStringAtomically(path, "not json").ok());
  EXPECT_FALSE(ReadTruthJson(path, &truth).ok());
  std::filesystem::remove(path);
  EXPECT_FALSE(ReadTruthJson(path, &truth).ok());
}

TEST(LabelFileTest, WritesLabelsInTheScanFilesPointOrder) {
  Scene scene;
  scene.meshes.push_back(testing_util::FloorMesh());
  SceneMesh box;
  box.mesh_world.Append(MakeBoxMesh({0.5, 0.5, 0.5}), Pose(Eigen::Translation3d(2, 0, 0.25)));
  box.label = LinkLabel(2);
  box.link = 2;
  scene.meshes.push_back(box);
  VirtualScanOptions options;
  options.spacing = 0.01;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, {Pose(Eigen::Translation3d(0, 0, 1.5)),
                                Pose(Eigen::Translation3d(0, 1, 1.2))},
                        options, &scan)
                  .ok());
  for (const std::string& scan_path : {std::string("a.ptx"), std::string("a.pcd")}) {
    const std::string path = TempPath("labels.bin");
    ASSERT_TRUE(WriteLabels(path, scan, scan_path).ok());
    LabelFile file;
    ASSERT_TRUE(ReadLabels(path, &file).ok());
    EXPECT_EQ(std::filesystem::file_size(path),
              12 + 8 * 2 + 2 * (scan.scans.scans[0].size() + scan.scans.scans[1].size()));
    std::filesystem::remove(path);
    ASSERT_EQ(file.labels.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
      const OrganizedScan& s = scan.scans.scans[k];
      EXPECT_EQ(file.rows[k], s.rows());
      EXPECT_EQ(file.cols[k], s.cols());
      const bool row_major = scan_path == "a.pcd";
      for (size_t i = 0; i < s.size(); ++i) {
        const size_t f = row_major ? static_cast<size_t>(s.RowOf(i)) * s.cols() + s.ColOf(i) : i;
        ASSERT_EQ(file.labels[k][f], scan.labels[k][i]);
      }
    }
  }
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(EDGEFIT_SOURCE_DIR "/assets/models/fk_arm.urdf", {}, &model).ok());
  const LabelCounts counts = CountLabels(scan, model);
  EXPECT_EQ(counts.cells, scan.scans.TotalCells());
  EXPECT_EQ(counts.valid, scan.scans.TotalValid());
  EXPECT_EQ(counts.valid, counts.background + counts.accessory + counts.link);
  EXPECT_EQ(counts.per_link[2].second, counts.link);
  EXPECT_GT(counts.link, 100u);
}

}  // namespace
}  // namespace edgefit
