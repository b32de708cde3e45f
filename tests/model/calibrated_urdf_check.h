// Shared by the calibrated-URDF tests (bundled and ../shared robots): write
// the calibrated URDF to a directory of its own, load it back and compare.
#ifndef EDGEFIT_TESTS_MODEL_CALIBRATED_URDF_CHECK_H_
#define EDGEFIT_TESTS_MODEL_CALIBRATED_URDF_CHECK_H_

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "edgefit/core/atomic_file.h"
#include "edgefit/model/calibrated_urdf.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace testing_util {

// Loaded back, the file has a "world" root and every link of `model`, with
// its mesh, where ForwardKinematics(q, T_world_base) puts it. Returns the
// text.
inline std::string ExpectCalibratedUrdfLoadsBack(
    const std::string& urdf_path, const std::vector<AttachSpec>& specs, const KinematicModel& model,
    const std::vector<double>& q, const Pose& T_world_base, const std::string& directory) {
  std::string text;
  Status status =
      CalibratedUrdf(urdf_path, specs, model, T_world_base, q, ModelLoadOptions(), &text);
  EXPECT_TRUE(status.ok()) << status.message();
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / directory;
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "fitted.urdf").string();
  EXPECT_TRUE(WriteStringAtomically(path, text).ok());
  KinematicModel loaded;
  status = LoadKinematicModel(path, ModelLoadOptions(), &loaded);
  EXPECT_TRUE(status.ok()) << status.message();
  if (!status.ok()) return text;
  EXPECT_EQ(loaded.links()[static_cast<size_t>(loaded.root_link())].name, "world");
  EXPECT_EQ(loaded.links().size(), model.links().size() + 1);
  std::vector<double> q_loaded = loaded.ZeroJoints();
  for (size_t j = 0; j < model.joints().size(); ++j) {
    const int index = loaded.JointIndex(model.joints()[j].name);
    EXPECT_GE(index, 0) << model.joints()[j].name;
    if (index >= 0) q_loaded[static_cast<size_t>(index)] = q[j];
  }
  const std::vector<Pose> T_fit = model.ForwardKinematics(q, T_world_base);
  const std::vector<Pose> T_loaded = loaded.ForwardKinematics(q_loaded, Pose::Identity());
  for (size_t l = 0; l < model.links().size(); ++l) {
    const Link& link = model.links()[l];
    const int index = loaded.LinkIndex(link.name);
    EXPECT_GE(index, 0) << link.name;
    if (index < 0) continue;
    EXPECT_TRUE(T_loaded[static_cast<size_t>(index)].isApprox(T_fit[l], 1e-7)) << link.name;
    EXPECT_EQ(loaded.links()[static_cast<size_t>(index)].mesh.triangles.size(),
              link.mesh.triangles.size())
        << link.name;
  }
  return text;
}

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_MODEL_CALIBRATED_URDF_CHECK_H_
