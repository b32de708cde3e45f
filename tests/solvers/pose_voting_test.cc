// Pose voting on oriented point pairs (solvers/base/pose_voting.h): a base
// mounted any way (tilted on a wedge, hanging from a ceiling) on a virtual
// scan with a floor and a decoy box is found without hints, its best
// cluster within two voxels and 12 degrees of the truth; the oriented
// cloud's normals face the scanner. A cube is voted at about Drost's 5 % of
// its diameter, a slim body at the finer voxel that gives it as many samples.
#include "solvers/base/pose_voting.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/core/angles.h"
#include "edgefit/model/primitive_meshes.h"
#include "solvers/icp_test_util.h"
#include "solvers/link_scan_test_util.h"

namespace edgefit {
namespace {

using testing_util::RotationErrorRad;
using testing_util::TranslationError;

// An L-shaped body (a base with a shoulder on one side), frame at its foot.
TriangleMesh LShapedBody() {
  TriangleMesh mesh;
  mesh.Append(MakeCylinderMesh(0.12, 0.2, 64), PoseFromXyzRpy({0, 0, 0.1}, {0, 0, 0}));
  mesh.Append(MakeBoxMesh({0.12, 0.1, 0.35}), PoseFromXyzRpy({0.1, 0, 0.3}, {0, 0, 0}));
  return mesh;
}

TEST(PoseVotingTest, FindsABodyMountedAnyWay) {
  const SurfaceSamples model = SampleMeshSurface(LShapedBody(), 0.004, 3);
  SceneMesh decoy;
  decoy.mesh_world.Append(MakeBoxMesh({0.3, 0.3, 0.3}), PoseFromXyzRpy({-0.6, 0.5, 0.15}, {0, 0, 0.3}));
  decoy.kind = "clutter";
  for (const Pose& T_world_body :
       {PoseFromXyzRpy({0.2, 0.1, 0.3}, {0.0, 35.0 * kDeg, 20.0 * kDeg}),    // on a wedge
        PoseFromXyzRpy({0.0, -0.2, 1.4}, {M_PI, 0.0, -40.0 * kDeg})}) {      // hanging
    VirtualScanOptions options;
    options.spacing = 0.005;
    const VirtualScan scan = testing_util::ScanLinkOnFloor(LShapedBody(), T_world_body, {decoy}, 7, options);
    PoseVotingOptions voting;
    voting.reference_stride = 10;  // a small scene: enough references at a tenth
    const double voxel = VotingVoxel({model}, voting);
    const OrientedCloud scene = VotingScene(scan.scans, voxel, voting);
    ASSERT_GT(scene.size(), 100u);
    for (size_t i = 0; i < scene.size(); i += 97) {  // unit, toward the scanners
      EXPECT_NEAR(scene.normals[i].norm(), 1.0f, 1e-4f);
    }
    std::vector<VotedPose> poses;
    PoseVotingSummary summary;
    ASSERT_TRUE(VoteModelPoses(scene, voxel, model, voting, &poses, &summary).ok());
    ASSERT_FALSE(poses.empty());
    EXPECT_LE(static_cast<int>(poses.size()), voting.max_poses);
    for (size_t k = 1; k < poses.size(); ++k) EXPECT_GE(poses[k - 1].votes, poses[k].votes);
    const double t = TranslationError(poses.front().T_world_model, T_world_body);
    const double r = RotationErrorRad(poses.front().T_world_model, T_world_body);
    std::printf("  best of %zu clusters: %.1f mm, %.1f deg (voxel %.1f mm); %.2f s\n", poses.size(),
                1e3 * t, r / kDeg, 1e3 * voxel, summary.seconds);
    EXPECT_LT(t, 2.0 * voxel);
    EXPECT_LT(r, 12.0 * kDeg);
  }
}

TEST(PoseVotingTest, ASlimBodyIsVotedAtAFinerVoxel) {
  PoseVotingOptions voting;
  // A cube has about 730 samples at 5 % of its diameter (its box's
  // diagonal): it stays near 5 %.
  const SurfaceSamples cube = SampleMeshSurface(MakeBoxMesh({0.6, 0.6, 0.6}), 0.004, 3);
  EXPECT_GT(VotingVoxel({cube}, voting), 0.9 * voting.sampling_share * SamplesDiameter(cube));
  // A rod 1.2 m long, 12 cm thick (an arm's link) is two voxels across
  // at 6 cm: its voxel is about 2 cm (1.9 cm measured).
  const SurfaceSamples rod = SampleMeshSurface(MakeCylinderMesh(0.06, 1.2, 64), 0.004, 3);
  const double rod_share = voting.sampling_share * SamplesDiameter(rod);
  const double rod_voxel = VotingVoxel({rod}, voting);
  EXPECT_LT(rod_voxel, 0.5 * rod_share);
  EXPECT_GT(rod_voxel, 0.2 * rod_share);
  // The slimmest of several bodies decides, down to min_voxel.
  EXPECT_LT(VotingVoxel({cube, rod}, voting), 0.5 * rod_share);
  voting.min_voxel = 0.04;
  EXPECT_DOUBLE_EQ(VotingVoxel({rod}, voting), 0.04);
}

}  // namespace
}  // namespace edgefit
