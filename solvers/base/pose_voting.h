// A rigid body found in the scans in any orientation by voting on oriented
// point pairs (Drost, Ulrich, Navab, Ilic, "Model globally, match locally",
// CVPR 2010): the rough stage of a base on any mounting (standing, hanging,
// on a wall or a wedge), where the cross sections of Sec. 5.1.1 assume it
// stands upright.
//
// For two points with normals (m1, n1), (m2, n2) and d = m2 - m1, the pair
// feature F = (|d|, angle(n1, d), angle(n2, d), angle(n1, n2)) does not
// change with the body's pose. The model's pairs are hashed by F, quantized
// (distance: the voxel, VotingVoxel; angles: 2 pi / angle_bins); pairs of
// one plane (normals parallel, both across the pair) are left out: they
// tell no pose, and a floor is made of them. Each reference point s_r of
// the scene (every reference_stride-th of the oriented cloud, or sparser
// to keep at most max_references) pairs with every scene point
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
  // model's diameter (Drost et al.'s tau_d) ...
  double sampling_share = 0.05;
  // ... made finer, down to min_voxel [m], until every body voted for has
  // at least min_model_points samples (one per voxel): a compact body has
  // them at about 5 % (a cube 730), a slim arm does not. The whole LBR Med7
  // (1.17 m) at 5 % had 271, two voxels across its links, and normals over
  // normal_radius_voxels that were its links' axes: its calibration on a
  // real frame was voted onto clutter 1.7 m away; at 3.4 cm (885) it is
  // found. The work grows with the samples (the model's pairs and the
  // scene's points at that voxel), not with the diameter.
  int min_model_points = 800;
  double min_voxel = 0.01;
  int angle_bins = 30;        // angles quantized to 2 pi / angle_bins (12 deg)
  int reference_stride = 3;   // every n-th scene point is a reference ...
  // ... and at most this many: the work is the references times the scene
  // points within the diameter of each.
  int max_references = 4000;
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

// The voxel [m] the bodies (surface samples, body frame) are matched at,
// and the scene cloud for it (MakeOrientedCloud with the voting's normal
// radius and region): one scene serves them all.
double VotingVoxel(const std::vector<SurfaceSamples>& bodies, const PoseVotingOptions& options);
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
