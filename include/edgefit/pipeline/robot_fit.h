// Fits an articulated robot (a KinematicModel, end effectors attached) or a
// conveyance system (Sec. 6: FitOptionsFor in asset_kind.h) to a scan,
// paper Sec. 5: edges (Sec. 4), the base link rough (5.1.1, cross-
// section corners + RANSAC) and precise (5.1.2, edge-weighted ICP), then
// every independent joint parents first: the rough Eq. (9) sweep over its
// range (5.2.1; a rotationally symmetric link adds its child's loss) and the
// precise joint-constrained weighted ICP (5.2.2); end-effector joints the
// same way (5.3), mimic and loop-closure joints from the fitted ones.
//
// A conveyance system differs only in the base's rough stage (Sec. 6.1:
// arm tips in a height map, their symmetry axis); its prismatic joints are
// swept and fitted like any joint (6.2.1-6.2.2), branched trees parents
// first.
//
// A "body" is the link moved by a joint together with every link fixed to
// it (fixed joints, attached end effectors): they move as one.
#ifndef EDGEFIT_PIPELINE_ROBOT_FIT_H_
#define EDGEFIT_PIPELINE_ROBOT_FIT_H_

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scan/organized_scan.h"
#include "solvers/base_rough.h"
#include "solvers/chain_refinement.h"
#include "solvers/conveyance_base_rough.h"
#include "solvers/joint_sweep.h"
#include "solvers/weighted_icp.h"

namespace edgefit {

struct RobotFitOptions {
  EdgeDetectionOptions edges;  // w_high lives here
  // CAD samples of the precise ICP stages and of the rough sweeps [m].
  double icp_spacing = 0.004;
  double sweep_spacing = 0.012;
  // At most this many samples per body (evenly thinned): a large base at
  // 4 mm has 250 k, more than the pose needs and slow in Ceres.
  int max_icp_samples = 30000;
  int max_sweep_samples = 3000;
  // The subtree pass (a whole arm at once, one joint free) needs fewer:
  // halving them kept every joint within 0.003 deg on the 5.9 M point
  // weld_low scene and took a second off the chain.
  int max_subtree_icp_samples = 15000;
  uint64_t seed = 1;  // sampling and RANSAC
  // The base's rough stage: cross-section corners (Sec. 5.1.1, robots) or
  // arm tips and their symmetry axis (Sec. 6.1, conveyance systems). When
  // the tips find no placement, the cross sections are tried.
  enum class BaseRoughMethod { kCrossSections, kArmTips };
  BaseRoughMethod base_rough_method = BaseRoughMethod::kCrossSections;
  BaseRoughOptions base_rough;
  // A base more than slide_elongation times longer than wide (a linear
  // track's rail, uniform along its length) fits its cross sections about
  // equally well anywhere along it: each cross-section candidate is moved
  // along its length, up to half that length either way, to the lowest
  // Eq. (9) loss of the base (coarse steps of slide_step [m], then a fifth
  // of it). The KUKA on its 8.2 m rail (3 mm scan, no accessories) had its
  // rail put 0.61 m off without it (benchmark random_1).
  double slide_elongation = 3.0;
  double slide_step = 0.05;
  ConveyanceBaseRoughOptions conveyance_base_rough;
  // A base nearly symmetric under a half turn (a conveyor frame whose only
  // tell is a drive unit at one end) scores its turned pose nearly as well
  // alone; its links tell the two apart. Up to base_alternatives further
  // rough poses (distinct by 5 degrees or 5 cm) whose base loss is within
  // base_alternative_loss per sample [m] of the best are fitted through
  // the whole chain too; the lowest Eq. (9) loss of the whole model wins.
  // 0 for robots (FitOptionsFor: 1 for conveyance systems). The bundled
  // conveyor turned half a turn scored 0.34 mm/sample worse alone (3 mm
  // spacing, accessories); its whole model 4 % worse.
  int base_alternatives = 0;
  double base_alternative_loss = 0.001;
  // Base precise ICP (6-DoF); its first gate covers the rough error.
  WeightedIcpOptions base_icp = DefaultBaseIcp();
  JointSweepOptions sweep;
  // Per-joint precise ICP.
  WeightedIcpOptions joint_icp = DefaultJointIcp();
  // Extension: after the chain, each joint is refined once more, parents
  // first, with its whole subtree (everything it carries) as the ICP source.
  bool refine_subtrees = true;
  WeightedIcpOptions subtree_icp = DefaultSubtreeIcp();
  // --refine_chain (extension, on by default): after the sequential fit,
  // one Ceres problem over the base pose and every joint together
  // (solvers/chain_refinement.h). BENCHMARK.md ("Whole-chain refinement"):
  // at 3 mm with accessories it lowered the revolute errors of every robot
  // measured (bundled 23 fits: mean 0.0081 -> 0.0035 deg; KUKA, ABB, FANUC
  // with the X16005 gun, 5 each: 0.0305 -> 0.0086, 0.0116 -> 0.0078,
  // 0.0128 -> 0.0080 deg) and the conveyor's (0.062 -> 0.049 mm), for about 1 s on 6 M points.
  // The covariance of the joints is computed either way (chain_refinement.
  // covariance) at the final estimate, with at most max_chain_samples per
  // body: on the bundled robot 30000 halved the revolute errors; 5000
  // gained nothing (0.0075 deg) and put the base farther off.
  bool refine_chain = true;
  ChainRefinementOptions chain_refinement;
  int max_chain_samples = 30000;
  // --weighting=uniform: w_edge = 1 in every stage.
  bool uniform_weights = false;
  // A revolute body is rotationally symmetric about its axis (Sec. 5.2.1)
  // when this share of its samples lies on rings that are at least 3/4
  // covered all around.
  double symmetric_share = 0.9;
  // A revolute body is treated as symmetric too when its own sweep finds a
  // runner-up (JointSweepOptions::distinct_revolute away) costing less than
  // this more per sample than the best [m]: the scan cannot tell them apart.
  double flat_sweep_loss = 0.0005;
  // The children a symmetric body carries: a revolute child adds only its
  // round part about its own axis (see robot_bodies.h) when that holds at
  // least this share of its samples, else all of it at its current value.
  double min_round_child_share = 0.1;
  // A symmetric body is swept with its children at values not fitted yet:
  // it and every joint after it are swept and fitted again, up to this many
  // times, until no joint moves by more than resweep_tolerance_rad
  // (revolute) or resweep_tolerance_m (prismatic). 0: no resweep.
  int max_resweeps = 3;
  double resweep_tolerance_rad = 0.2 * M_PI / 180.0;  // a basin change, not the ICP's jitter
  double resweep_tolerance_m = 0.002;
  // A revolute joint's resweeps cover this much either side of its value
  // [rad] (its first sweep covers its range; prismatic joints always do).
  double resweep_window_rad = 20.0 * M_PI / 180.0;
  // Optional base hint: skip the rough base stage and start from this pose,
  // its z measured from the scan's floor (EstimateFloorHeight; 0 for
  // equipment standing on it: the hint need not know where the scan's
  // origin is).
  bool has_initial_base = false;
  Pose T_world_base_initial = Pose::Identity();
  // Quality: a body fits when at least this share of its visible samples
  // is within the final gate and their RMS is at most max_rms [m].
  double min_inlier_share = 0.8;
  double max_rms = 0.003;
  // Ambiguity (a link that fits two joint values, like a bare flange half a
  // turn apart, or a wrist flipped with the joints below it): when the
  // sweep's runner-up costs less than ambiguity_check_loss more per sample
  // than the best, the joint is fitted again from there with every joint
  // below it; the lower Eq. (9) loss of the subtree wins, and the joint is
  // ambiguous (not ok) when the two differ by less than ambiguity_mean_loss
  // per sample [m]. Calibrated on the bundled robot's 46 edge-weighted fits
  // (23 postures, with and without accessories, at 7b1034c, before the
  // CAD normals of WeightedIcpOptions::plane_normals): 91 of 92 checks chose the
  // right value, the smallest margin 0.12 mm (a flipped wrist whose only
  // tell is a drive cover); the wrong one, a gun's jaw, won by 0.006 mm.
  // The bound is half the smallest right margin. Not recalibrated since:
  // at 846eda4 the 84 fits of BENCHMARK.md had none flagged, none failed.
  double ambiguity_check_loss = 0.002;
  double ambiguity_mean_loss = 0.00006;
  // A revolute joint moved by pinning_revolute (a failed fit's bound) either
  // way must cost on average at least pinning_mean_loss per sample more
  // [m], else it is ambiguous. In the 69 fits of the bundled table at 7b1034c the
  // lower of the two sides' rises was never below 0.096 mm/sample (so
  // neither is the mean). Prismatic joints are not tested: on the bundled
  // gun's jaw (a rod sliding along itself) the lower rise at 5 mm ran from
  // -0.125 to 0.2 mm/sample over 48 fits whose jaws were within 4 mm, and
  // was 0.015 and -0.001 for the two off by more: no bound separates them.
  double pinning_revolute = 0.5 * M_PI / 180.0;  // [rad]
  double pinning_mean_loss = 0.00003;
  // After a joint takes its alternative value, the subtree pass runs again
  // over every joint, up to this many times, until none moves by more than
  // settle_tolerance_rad (revolute) or settle_tolerance_m (prismatic).
  int max_passes_after_switch = 3;
  double settle_tolerance_rad = 0.01 * M_PI / 180.0;
  double settle_tolerance_m = 0.0002;

  static WeightedIcpOptions DefaultBaseIcp();
  static WeightedIcpOptions DefaultJointIcp();
  static WeightedIcpOptions DefaultSubtreeIcp();
  bool IsValid(std::string* error) const;
};

struct BodyQuality {
  std::string link;    // the moved link (the base: the root)
  std::string joint;   // the joint that moves it ("" for the base)
  size_t samples = 0;  // CAD samples
  size_t visible = 0;  // seen at the fitted pose
  double inlier_share = 0.0;
  double rms = 0.0;          // [m]
  bool symmetric = false;    // the sweep included the child's loss
  double sweep_value = 0.0;  // rough joint value [rad] or [m]
  int icp_iterations = 0;
  // The other joint value the check above fitted (ambiguity_margin: their
  // loss difference per sample [m]; infinity when not checked).
  bool ambiguous = false;
  double alternative_value = 0.0;
  double ambiguity_margin = std::numeric_limits<double>::infinity();
  bool ok = false;
};

struct RobotFitTimings {
  // refine: the whole-chain refinement (or the covariance alone) [s]
  double edges = 0.0, base_rough = 0.0, base_precise = 0.0, chain = 0.0, refine = 0.0,
         total = 0.0;  // [s]
};

struct RobotFitResult {
  Pose T_world_base = Pose::Identity();  // root link in the world frame
  std::vector<double> q;                 // every joint, KinematicModel order
  // The base's rough stage: which method gave the pose, its result (the
  // pose, candidates and floor are in base_rough for either method).
  RobotFitOptions::BaseRoughMethod base_rough_method =
      RobotFitOptions::BaseRoughMethod::kCrossSections;
  BaseRoughResult base_rough;
  ConveyanceBaseRoughResult arm_tips;  // kArmTips
  std::vector<BodyQuality> bodies;     // base first, then joints in fit order
  // The whole-chain refinement (refine_chain) and the covariance: joint_std
  // per joint [rad] or [m], NaN for dependent joints or when not computed.
  ChainRefinementSummary chain_refinement;
  RobotFitTimings timings;
  bool ok = false;
  std::string message;  // why not ok
};

// Progress lines ("base: rough ...") for long steps; may be empty.
using ProgressFn = std::function<void(const std::string&)>;

// Fails (Status) on invalid options, a model without a base mesh or a scan
// the stages cannot work on; a fit that runs but does not match the scan
// returns Ok with result->ok = false and a message.
Status FitRobot(const KinematicModel& model, const ScanSet& scans, const RobotFitOptions& options,
                const ProgressFn& progress, RobotFitResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_ROBOT_FIT_H_
