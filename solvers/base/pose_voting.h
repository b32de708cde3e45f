// A rigid body found in the scans in any orientation by voting on oriented
// point pairs (Drost, Ulrich, Navab, Ilic, "Model globally, match locally",
// CVPR 2010): the rough stage of a base on any mounting (standing, hanging,
// on a wall or a wedge), where the cross sections of Sec. 5.1.1 assume it
// stands upright.
//
// For two points with normals (m1, n1), (m2, n2) and d = m2 - m1, the pair
// feature F = (|d|, angle(n1, d), angle(n2, d), angle(n1, n2)) does not
// change with the body's pose. The model's pairs are hashed by F, quantized
// (distance: sampling_share of the model's diameter D; angles: 2 pi /
// angle_bins); pairs of one plane (normals parallel, both across the pair)
// are left out: they tell no pose, and a floor is made of them. Each
// reference point s_r of the scene (every
// reference_stride-th of the oriented cloud) pairs with every scene point
// within D; each model pair with the same F votes for (m_r, alpha): the
// model point s_r is, and the turn alpha about s_r's normal that brings
// the pair onto the scene's. With T_s (T_m) moving s_r (m_r) to the origin
// and its normal onto +x, the vote's pose is
//   T_world_model = T_s^-1 Rx(alpha) T_m,   alpha = theta_s - theta_m,
// theta the angle of the pair's second point about +x. Each reference
// keeps its best-voted pose; poses within cluster_translation_share * D and
// cluster_rotation of each other are one cluster, its votes summed.
#ifndef EDGEFIT_SOLVERS_BASE_POSE_VOTING_H_
#define EDGEFIT_SOLVERS_BASE_POSE_VOTING_H_

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/base/oriented_cloud.h"

namespace edgefit {

struct PoseVotingOptions {
  // Sampling of model and scene, and the distance bin, as a share of the
  // model's diameter (Drost et al.'s tau_d).
  double sampling_share = 0.05;
  // The scene is never thinned coarser than this [m]. The work grows as
  // (diameter / voxel)^4: with a 4 cm cap the 2.7 m base and first links of
  // the bundled robot took 738 s on a virtual depth frame, 4 s at 5 %.
  double max_voxel = 0.2;
  int angle_bins = 30;        // angles quantized to 2 pi / angle_bins (12 deg)
  int reference_stride = 3;   // every n-th scene point is a reference
  // The normals' neighbourhood, in voxels.
  double normal_radius_voxels = 2.5;
  // Poses this close are one cluster: translation (share of the diameter)
  // and rotation [rad].
  double cluster_translation_share = 0.1;
  double cluster_rotation = 12.0 * M_PI / 180.0;
  int max_poses = 32;  // clusters returned, most votes first
  // Only scene points within this box [m, world]; empty: all.
  Eigen::AlignedBox3d roi_world;

  bool IsValid(std::string* error) const;
};

struct VotedPose {
  Pose T_world_model = Pose::Identity();
  double votes = 0.0;  // of the cluster
};

struct PoseVotingSummary {
  size_t model_points = 0, scene_points = 0, references = 0;
  double voxel = 0.0;     // [m]
  double diameter = 0.0;  // the model's [m]
  double seconds = 0.0;
};

// The voxel [m] the body of diameter `diameter` [m] is matched at, and the
// scene cloud for it (MakeOrientedCloud with the voting's normal radius and
// region): one scene serves every body of about that size.
double VotingVoxel(double diameter, const PoseVotingOptions& options);
OrientedCloud VotingScene(const ScanSet& scans, double voxel, const PoseVotingOptions& options);
// The diameter of the samples' bounding box [m].
double SamplesDiameter(const SurfaceSamples& samples);

// The poses of the body whose surface samples (with outward normals, body
// frame) are `model`, most votes first, in `scene` (VotingScene at `voxel`).
// Fails when the model or the scene has too few points with normals.
Status VoteModelPoses(const OrientedCloud& scene, double voxel, const SurfaceSamples& model,
                      const PoseVotingOptions& options, std::vector<VotedPose>* poses,
                      PoseVotingSummary* summary);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_POSE_VOTING_H_
