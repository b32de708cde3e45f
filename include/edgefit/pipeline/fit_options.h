// Every setting of a fit, each in one place: FitOptions holds one struct
// per stage of the method (the folder that reads it in brackets) and the
// settings every stage shares. Commands read it from flags in one function
// (tools/fit_flags.h); FitOptionsFor (asset_kind.h) gives the defaults of
// a kind of equipment.
#ifndef EDGEFIT_PIPELINE_FIT_OPTIONS_H_
#define EDGEFIT_PIPELINE_FIT_OPTIONS_H_

#include <cstdint>
#include <string>

#include "edgefit/core/pose.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/model/frozen_joints.h"
#include "edgefit/pipeline/instance_crop.h"
#include "edgefit/scan/mixed_pixels.h"
#include "solvers/base/base_hypotheses.h"
#include "solvers/base/base_rough.h"
#include "solvers/base/conveyance_base_rough.h"
#include "solvers/base/floor_height.h"
#include "solvers/base/pose_voting.h"
#include "solvers/base/up_direction.h"
#include "solvers/joints/body.h"
#include "solvers/joints/chain_fitter.h"
#include "solvers/joints/observability.h"
#include "solvers/refinement/chain_refinement.h"
#include "solvers/refinement/coverings.h"
#include "solvers/registration/residual_options.h"
#include "solvers/registration/station_alignment.h"
#include "solvers/registration/weighted_icp.h"

namespace edgefit {

// Sec. 5.1 / 6.1: the base link (solvers/base/, solvers/registration/).
struct BaseOptions {
  // The rough stage: cross-section corners (Sec. 5.1.1, robots) or arm tips
  // and their symmetry axis (Sec. 6.1, conveyance systems). When the tips
  // find no placement, the cross sections are tried.
  enum class Method { kCrossSections, kArmTips };
  Method method = Method::kCrossSections;
  // How the base may be mounted. kUpright: standing on the floor, as the
  // rough stages of Sec. 5.1.1 / 6.1 assume; kAny: anywhere, in any
  // orientation (hanging, on a wall, on a wedge), found by pose voting
  // (solvers/base/pose_voting.h, mounting_stage.cc); kAuto: the upright
  // stage on laser scans, both on a depth camera's frames (a camera looks
  // at robots mounted any way, from any side). Voting on a laser scan of a
  // cell costs tens of seconds where the upright stage finds nothing (a
  // scan without the robot): ask for it there (kAny).
  enum class Mounting { kAuto, kUpright, kAny };
  Mounting mounting = Mounting::kAuto;
  PoseVotingOptions voting;
  // The bodies voted for: the base with its first two joints' bodies, the
  // first joint at zero, the second at this many values over its range
  // (mounting_stage.cc).
  int voting_joint_values = 9;
  // Each voted pose (a voxel and 12 degrees off) is registered (at most
  // voted_icp_samples, point to plane, the gate from two voxels down to
  // NoiseOptions::gate, at most voted_icp_iterations iterations), then
  // ranked by its body's samples' evidence (seen within the sweep's
  // tau_dist, less those seen in free space; mounting_stage.cc); the best
  // voted_roughs distinct ones are fitted through the whole chain.
  int voted_icp_iterations = 15;
  int voted_icp_samples = 3000;
  int voted_roughs = 4;
  // Up for the upright stage: the world z (a levelled laser scan, a frame's
  // pose) unless `up` is given (non-zero: the upright stage runs levelled
  // to it alone). On a depth camera's frame with kAuto, up is also
  // estimated from the dominant floor or table plane (up_estimation); when
  // it is more than min_up_tilt from z, the upright stage runs a second
  // time levelled to it and the chain tells the poses apart. Every pose
  // stays in the scan's frame.
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  UpOptions up_estimation;  // its seed is FitOptions::seed
  double min_up_tilt = 3.0 * M_PI / 180.0;  // [rad]
  // The floor both rough stages and the hint stand the base on.
  FloorOptions floor;
  BaseRoughOptions cross_sections;      // its seed is FitOptions::seed
  ConveyanceBaseRoughOptions arm_tips;  // its symmetry seed is FitOptions::seed
  BaseHypothesesOptions hypotheses;
  // Sec. 5.1.2: the base's precise ICP (6-DoF); its first gate covers the
  // rough error.
  WeightedIcpOptions icp = DefaultIcp();
  // Optional hint: skip the rough stage and start from this pose, its z
  // measured from the scan's floor (EstimateFloorHeight; 0 for equipment
  // standing on it: the hint need not know where the scan's origin is).
  bool has_initial = false;
  Pose T_world_base_initial = Pose::Identity();

  static WeightedIcpOptions DefaultIcp();
  bool IsValid(std::string* error) const;
};

// The refinement of the whole chain (solvers/refinement/).
struct RefinementOptions {
  // On by default: after the sequential fit, one Ceres problem over the
  // base pose and every joint together. It lowered the revolute errors of
  // every robot measured and the conveyor's prismatic errors, for about
  // 1 s on 6 M points (BENCHMARK.md, "Whole-chain refinement"). The
  // covariance of the joints is computed either way (chain.covariance).
  ChainRefinementOptions chain;
  // Jackets and covers found after the sequential fit and left out of the
  // refinement (solvers/refinement/coverings.h); rounds = 0 turns it off.
  CoveringOptions coverings;
};

// The verdict of each body alone at the final values (src/pipeline/quality).
struct QualityOptions {
  // A body fits when at least this share of its visible samples is within
  // the final gate of the joint ICP and their RMS is at most max_rms [m]
  // (on a noisy scan 0.6 of the grown gate, as 3 mm is of 5: noise_scale.h).
  double min_inlier_share = 0.8;
  double max_rms = 0.003;  // [m]
  // A joint is not seen when fewer of its body's CAD samples than this are
  // visible from the stations at the fitted pose (4 mm samples: 30 are
  // about 5 cm by 10 cm of surface).
  size_t min_visible_samples = 30;
  // Which revolute joints the geometry cannot pin (a bare round flange).
  ObservabilityOptions observability;
  // A joint whose joint_std (the covariance, with the CAD's and the
  // sensor's correlated deviation) is above this is not pinned: ambiguous.
  // Three std within the bars of a wrong answer said ok (4 deg, 3 mm). On
  // laser scans the stds are 0.01-0.1 deg and at most 0.5 mm; a depth
  // camera's centimetre of correlated error leaves some joints degrees.
  double max_joint_std_revolute = 4.0 / 3.0 * M_PI / 180.0;  // [rad]
  double max_joint_std_prismatic = 0.001;                    // [m]
  // The base is not seen (hidden) when its visible samples are less than
  // this share of those facing a station in its window (visible plus
  // occluded: behind the surface the station scanned there). A base fitted
  // onto clutter lies mostly inside or behind scanned surfaces and matches
  // with the few samples left in view: on virtual depth frames (3.5-4.3 m,
  // the bundled robot and a KUKA KR 150) three bases 0.6-3.9 m off were
  // said ok at 0.5-7 % in view, one with a joint 35 deg off said ok; right
  // ones had 27-37 % (their noise and their own arm in front hide the rest).
  double min_base_seen_share = 0.15;

  bool IsValid(std::string* error) const;
};

// The scans' noise, measured where the fit meets the model, and the fit's
// distance thresholds scaled to it (noise_scale.h).
struct NoiseOptions {
  bool scale = true;
  // At or below this sigma [m] every threshold stays as measured on laser
  // scans (their 1 mm noise, 0.5-2 mm as-built surfaces and up to 4 mm of
  // incidence noise measure 1-3 mm here); above it they grow in proportion.
  double reference_sigma = 0.003;
  double max_scale = 15.0;
  // The measuring registration's fixed gate [m]: wide enough for a
  // centimetre of noise on both sides, narrow enough to leave the floor.
  double gate = 0.04;
  // On a noisy scan each 0.2 m patch of the surface deviates as a whole by
  // this many times the noise measured where the base meets the scan (the
  // covariance's correlated part, noise_scale.cc): the joints' and the
  // base's standard deviations. At 1 sigma, the 32 joints said ok on 18
  // virtual depth frames of two robots and the 5 real ZED 2i frames were
  // off by a median 1.44 stds (0.67 for a right std), up to 6.9 (one 5.0
  // degrees off with a std of 1.08); the real frames' calibrations spread
  // 1.5 times their stated std, at 2 sigma 0.75 times
  // (benchmarks/results/2026-11-30-noise-levels.md).
  double patch_deviation = 2.0;  // [sigma]

  bool IsValid(std::string* error) const;
};

struct FitOptions {
  // Seed of the CAD sampling and of every RANSAC.
  uint64_t seed = 1;
  // Joints held at given values [rad] or [m] (frozen_joints.h): the fit
  // fits the others; with every joint given it fits the base alone
  // (camera-to-robot calibration). Their verdict is "given".
  KnownJoints known_joints;
  // Uniform weights (w_edge = 1) in every stage instead of Eq. (6)'s (the
  // paper's edge weights, w_high at the scan's edge points): the
  // correspondence search is then given no weights. On by default: measured
  // on the same scans, uniform weights had the lower revolute means on every
  // robot, ideal and realistic (bare KUKA, ABB, FANUC, 20 postures each:
  // 0.0065 / 0.0026 / 0.0037 deg against edge weights' 0.0094 / 0.0038 /
  // 0.0045; realistic with jackets and guns: 0.0171 / 0.0203 / 0.0179 /
  // 0.0155 deg against 0.0184 / 0.0201 / 0.0197 / 0.0170 for the bundled
  // robot, KUKA, ABB, FANUC), the same p95 and gun jaw, one larger maximum
  // (the bundled robot's weld_low, 0.178 against 0.104 deg). Edge weights
  // put two bare KUKA wrists 0.059 and 0.072 deg off, uniform ones 0.012
  // and 0.042 (BENCHMARK.md). With uniform weights Fit() runs no edge
  // stage (Sec. 4) at all: 2 s of a 10 s fit on 5.94 M points.
  bool uniform_weights = true;
  // Extension: mixed pixels (scan/mixed_pixels.h) removed from the scans
  // before Sec. 4, so that neither the edges nor any stage sees them. Off:
  // on realistic scans with jackets (20 postures each) it flipped one of
  // the KUKA's wrists (said not ok) and took its revolute mean on the other
  // 19 from 0.0199 to 0.0232 deg, the ABB's from 0.0192 to 0.0209 deg; the bundled robot's
  // stayed (0.0178 -> 0.0175 deg, 23 postures) and its gun's jaw came a
  // quarter closer (mean 0.45 -> 0.34 mm on 22 of them). Measured before
  // the jacketed links were left out of the stations' registration; with
  // that, the KUKA's flipped wrist is still wrong (96.7 deg, said not ok).
  bool remove_mixed_pixels = false;
  // Extension: the whole-chain refinement, which sets the final values, on
  // the scans without their mixed pixels; every stage before it keeps them
  // (ignored with remove_mixed_pixels). A CAD sample whose cell returned a
  // blend of two surfaces is not seen there, rather than matched to the
  // blend: at a small part's silhouette (the gun's electrode tip) those
  // matches pulled the part along its slide. On realistic scans with
  // jackets the bundled gun's jaw went from 0.48 to 0.36 mm mean (23
  // postures) and the revolute means moved by at most 0.0011 deg (the
  // KUKA's, 8 postures; BENCHMARK.md).
  bool refine_without_mixed_pixels = true;
  MixedPixelOptions mixed_pixels;
  // Extension: after the rough base poses, the scans cropped to the rays
  // that pass within the model's reach of them (instance_crop.h); on in a
  // cell, off for one asset.
  InstanceCropOptions crop;
  // Extension for cells: when the base, after its precise ICP from every
  // rough pose, has fewer than this share of its visible samples within the
  // quality's inlier distance, the fit stops there, not ok, without the
  // chain (no machine of this model there). 0 = off (edgefit fit: the whole
  // fit and every body's verdict); the cell fit sets the quality's
  // min_inlier_share (cell_fit.h).
  double min_base_inlier_share = 0.0;
  // Sec. 4: edges and their weights (w_high lives here).
  EdgeDetectionOptions edges;
  // Extension: the stations aligned to each other before the fit, against
  // their registration residuals (solvers/registration/station_alignment.h).
  StationAlignmentOptions stations;
  // The loss and joint constraint of every precise stage.
  ResidualOptions residuals;
  // The CAD samples of every stage.
  CadSampleOptions samples;
  BaseOptions base;
  // Sec. 5.2-5.3 / 6.2: every joint (solvers/joints/).
  ChainOptions chain;
  RefinementOptions refinement;
  QualityOptions quality;
  NoiseOptions noise;

  bool IsValid(std::string* error) const;
};

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_FIT_OPTIONS_H_
