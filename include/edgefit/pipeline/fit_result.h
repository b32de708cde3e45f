// What a fit returns: the base pose, every joint, and how well each body
// matches the scan (the quality verdict), per stage.
#ifndef EDGEFIT_PIPELINE_FIT_RESULT_H_
#define EDGEFIT_PIPELINE_FIT_RESULT_H_

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/pipeline/fit_options.h"
#include "solvers/base/base_rough.h"
#include "solvers/base/conveyance_base_rough.h"
#include "solvers/joints/observability.h"
#include "solvers/refinement/chain_refinement.h"

namespace edgefit {

// Extension: what the scan says of one joint (result.json joint_status).
//  kOk            the scan pins it
//  kAmbiguous     another value fits about as well, or better (a wrong basin)
//  kUnobservable  no scan could pin it: the geometry it moves looks the same
//                 at every value (a bare round flange); reported by a
//                 convention, joint_std null; does not make the fit not ok
//  kNotSeen       too few of its samples are visible at the fitted pose
//  kMismatch      its body does not match the scan
// kGiven: held at a value the user gave (FitOptions::known_joints).
enum class JointVerdict { kOk, kAmbiguous, kUnobservable, kNotSeen, kMismatch, kGiven };
const char* JointVerdictName(JointVerdict verdict);

struct BodyQuality {
  std::string link;    // the moved link (the base: the root)
  std::string joint;   // the joint that moves it ("" for the base)
  size_t samples = 0;  // CAD samples
  size_t visible = 0;  // seen at the fitted pose
  size_t occluded = 0;  // facing a station, behind what it scanned there
  // visible / (visible + occluded); 1 when none faces a station in its window.
  double SeenShare() const {
    return visible + occluded == 0
               ? 1.0
               : static_cast<double>(visible) / static_cast<double>(visible + occluded);
  }
  double inlier_share = 0.0;
  double rms = 0.0;          // [m]
  bool symmetric = false;    // the sweep included the child's loss
  double sweep_value = 0.0;  // rough joint value [rad] or [m]
  int icp_iterations = 0;
  // The other joint value the ambiguity checks fitted (ambiguity_margin:
  // their loss difference per sample [m]; infinity when not checked).
  bool ambiguous = false;
  // ChainFitter::CheckFinalBasins: the alternative fits better than the
  // reported value (a wrong basin), not about as well.
  bool better_elsewhere = false;
  double alternative_value = 0.0;
  double ambiguity_margin = std::numeric_limits<double>::infinity();
  // The same pair on the scan with the parts found covered: how much better
  // the reported value fits there per sample [m] (negative: the
  // alternative; NaN when not compared).
  double covered_margin = std::numeric_limits<double>::quiet_NaN();
  // The joint's verdict (kOk for the base when ok) and, for a revolute
  // joint, TurnIsUnobservable's largest share of its subtree's samples a
  // turn moved off their own surface (NaN for the others).
  JointVerdict verdict = JointVerdict::kMismatch;
  double turned_off_share = std::numeric_limits<double>::quiet_NaN();
  // The other values 2 pi apart within the limits that place every link
  // the same (a revolute joint with a range beyond a full turn): the
  // reported value is the one nearest the joint's zero.
  std::vector<double> whole_turns;
  // Not pinned: joint_std above QualityOptions::max_joint_std_* (then
  // ambiguous).
  bool unpinned = false;
  // A body between the base and this joint (the base's included) does not
  // match the scan or is not seen: the joint's value is relative to links
  // the scan does not confirm, so it is not trusted (then ambiguous).
  bool chain_unmatched = false;
  // On a noisy scan (noise_scale > 1): a round joint (its sweep and ICP
  // carried its children) and its partner, the joint just below it, were
  // fitted together, and the other one (torn_partner) has two values that
  // fit about equally: this joint's value holds for one of them (then
  // ambiguous).
  bool partner_torn = false;
  std::string torn_partner;
  double joint_std = std::numeric_limits<double>::quiet_NaN();  // [rad] or [m]
  bool ok = false;  // the body matches and the verdict is ok or unobservable
};

struct FitTimings {
  // refine: the whole-chain refinement (or the covariance alone) [s]
  double edges = 0.0, stations = 0.0, base_rough = 0.0, base_precise = 0.0, chain = 0.0,
         refine = 0.0,
         total = 0.0;  // [s]
  // Of base_precise, chain and refine: the whole-model alternatives (the
  // base and chain fitted from each alternative rough pose, every joint
  // swept again at the final values, the pinning test) [s].
  double alternatives = 0.0;
  // The mixed-pixel detector, each time it runs: their removal
  // (remove_mixed_pixels) or the whole-chain refinement's mask of them
  // (refine_without_mixed_pixels) [s].
  double mixed_pixels = 0.0;
};

struct FitResult {
  Pose T_world_base = Pose::Identity();  // root link in the world frame
  std::vector<double> q;                 // every joint, KinematicModel order
  // The base's rough stage: which method gave the pose, its result (the
  // pose, candidates and floor are in base_rough for either method).
  BaseOptions::Method base_rough_method = BaseOptions::Method::kCrossSections;
  BaseRoughResult base_rough;
  ConveyanceBaseRoughResult arm_tips;  // kArmTips
  std::vector<BodyQuality> bodies;     // base first, then joints in fit order
  // The stations' alignment: each station's correction of its written pose.
  StationAlignmentSummary stations;
  // The whole-chain refinement and the covariance: joint_std per joint
  // [rad] or [m], NaN for dependent joints or when not computed.
  ChainRefinementSummary chain_refinement;
  // The coverings left out of the refinement's last round.
  CoveringSummary coverings;
  // Cells removed as mixed pixels before Sec. 4 (FitOptions::remove_mixed_pixels).
  size_t mixed_pixels = 0;
  // The scans' noise where the fit met the model (noise_scale.h): sigma
  // [m] (0: not measured) and the scale of the distance thresholds.
  double noise_sigma = 0.0;
  double noise_scale = 1.0;
  // Up of the upright stage (BaseOptions::up): "frame" (the world z),
  // "given", or "plane" (estimated from the dominant floor or table plane
  // of a depth camera's frame, more than min_up_tilt from z: the upright
  // stage ran levelled to it too); up_plane_share: the share of the sampled
  // points on that plane.
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  std::string up_from = "frame";
  double up_plane_share = 0.0;
  // The base's symmetry (observability.h): its joint is reported at the
  // placement nearest zero; the others are the same geometry.
  BaseSymmetry base_symmetry;
  FitTimings timings;
  bool ok = false;
  std::string message;  // why not ok
};

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_FIT_RESULT_H_
