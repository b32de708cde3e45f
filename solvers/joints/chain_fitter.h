// Sec. 5.2-5.3 and 6.2: every independent joint of a kinematic tree,
// parents first, on a fitted base. Per joint: the rough Eq. (9) sweep over
// its range (5.2.1; a rotationally symmetric body carries its children) and
// the precise joint-constrained weighted ICP (5.2.2). Extensions: bodies
// swept with children not yet fitted are swept again after them; each joint
// is refined once more with its whole subtree; a joint whose sweep found a
// near-equal runner-up is fitted from there too and the lower subtree loss
// wins (ambiguity.cc); a revolute joint the scan does not pin is flagged.
// End effectors (5.3) are bodies like any other; mimic and loop-closure
// joints follow the fitted ones.
#ifndef EDGEFIT_SOLVERS_JOINTS_CHAIN_FITTER_H_
#define EDGEFIT_SOLVERS_JOINTS_CHAIN_FITTER_H_

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/joints/body.h"
#include "solvers/joints/joint_sweep.h"
#include "solvers/registration/weighted_icp.h"

namespace edgefit {

struct ChainOptions {
  // The rough Eq. (9) sweep of each joint (Sec. 5.2.1, 6.2.1).
  JointSweepOptions sweep;
  // The precise joint-constrained ICP of each joint (Sec. 5.2.2, 6.2.2).
  WeightedIcpOptions joint_icp = DefaultJointIcp();
  // Extension: after the chain, each joint is refined once more, parents
  // first, with its whole subtree (everything it carries) as the ICP source.
  bool refine_subtrees = true;
  WeightedIcpOptions subtree_icp = DefaultSubtreeIcp();
  // A revolute body is rotationally symmetric about its axis (Sec. 5.2.1)
  // when this share of its samples lies on rings that are at least 3/4
  // covered all around.
  double symmetric_share = 0.9;
  // A revolute body is treated as symmetric too when its own sweep finds a
  // runner-up (JointSweepOptions::distinct_revolute away) costing less than
  // this more per sample than the best [m]: the scan cannot tell them apart.
  double flat_sweep_loss = 0.0005;
  // A symmetric body whose sweep with its children is still flat (below
  // flat_sweep_loss) is swept again together with the bend below it
  // (pair_sweep.h), on a grid of this step over both ranges [rad]; 0: off.
  // The fit keeps it on noisy scans only (ScaledToNoise, noise_scale.h).
  double pair_sweep_step = 5.0 * M_PI / 180.0;
  // The children a symmetric body carries: a revolute child adds only its
  // round part about its own axis (see body.h) when that holds at least
  // this share of its samples, else all of it at its current value.
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
  // Ambiguity (a link that fits two joint values, like a bare flange half a
  // turn apart, or a wrist flipped with the joints below it): when the
  // sweep's runner-up costs less than ambiguity_check_loss more per sample
  // than the best, the joint is fitted again from there with every joint
  // below it; the lower Eq. (9) loss of the subtree wins (of its bodies the
  // two place apart, see alike_share), and the joint is ambiguous (not ok)
  // when the two differ by less than ambiguity_mean_loss per sample of the
  // whole subtree [m]. Calibrated, on the whole subtree's loss, on the
  // bundled robot's 46 edge-weighted fits
  // (23 postures, with and without accessories): 91 of 92 checks chose the
  // right value, the smallest margin 0.12 mm (a flipped wrist whose only
  // tell is a drive cover); the wrong one, a gun's jaw, won by 0.006 mm.
  // The bound is half the smallest right margin.
  double ambiguity_check_loss = 0.002;
  double ambiguity_mean_loss = 0.00006;
  // The two values are compared on the bodies they place differently: a
  // body of the subtree whose samples move by less than alike_share of the
  // most any body's samples move between the two (a wrist flip's flange
  // and gun: the flip turns the forearm half a turn, the flange only by
  // the two branches' fitting differences) says only how well each
  // branch's later fits went, not which value is right, and is left out of
  // the loss difference. The per-sample margin still divides by the whole
  // subtree's samples, so the bounds above keep their scale.
  double alike_share = 0.25;
  // A branch's subtree pass is run up to branch_passes times, again while
  // it moved the branch's joint by more than branch_settled of the sweep's
  // distinct-basin distance (5 deg, 20 mm): the value a branch is compared
  // at is where its ICP settled.
  int branch_passes = 4;
  double branch_settled = 0.2;
  // CheckFinalBasins: a sweep's best at least this far from the final value
  // (and better by ambiguity_mean_loss per sample) is another basin, and
  // followed as a branch. The jaw's is below the sweep's distinct_prismatic
  // (20 mm): jaws 8-9 mm off, in the bench's realistic scenes, were
  // reported ok; not below 5 mm: at 2 mm, tried while the jaw's ICP and
  // refinement still ended with point-to-point residuals, the branches
  // moved the jaw of a realistic 1.7 mm scene from 3.8 to 1.2 mm off but on
  // an ideal 4 mm scan from 6.0 to 9.9 mm off (not tried since). Revolute
  // joints keep the sweep's 5 deg: at 1 deg a jacketed forearm's sweep
  // preferred 1.7 deg off the right value by 0.09 mm/sample. [rad], [m]
  double final_basin_revolute = 5.0 * M_PI / 180.0;
  double final_basin_prismatic = 0.005;
  // Rounds in which a better basin found by CheckFinalBasins is taken (and
  // the chain refined again); a better basin found after the last is
  // reported. One branch can uncover another: on a realistic scene a
  // flipped wrist taken in the first round left the gun's jaw 42 mm off,
  // which only the second round's sweep saw. 0: only report.
  int final_basin_rounds = 2;
  // CheckFinalBasins: a branch better by more than ambiguity_mean_loss per
  // sample, but not on the evidence (CompareViews: the samples seen at
  // both values and those matched within explained_distance [m] on surface
  // the other value leaves unmatched), only shows more of surface both
  // explain: the joint is not pinned between the two (ambiguous), not in a
  // wrong basin.
  double explained_distance = 0.003;
  // A revolute joint moved by pinning_revolute either way (the sweep's
  // distinct basins, JointSweepOptions::distinct_revolute) must cost on
  // average at least pinning_mean_loss per sample more [m], the bound of
  // two distinct values (ambiguity_mean_loss), else it is ambiguous: a
  // value that far fits about as well. Not at the failure bound (0.5 deg),
  // which asked how sharp one minimum is, not whether another value fits:
  // a bare wrist's right value rose 0.027 mm/sample there (the bundled
  // robot's joint 4, 4 mm scan), 0.017 and 0.029 (a KUKA KR 150's axes 5
  // and 4, 0.06 and 0.03 deg off), and a KUKA axis 5 0.0002 deg off fell
  // (its Eq. 9 minimum at 12 mm samples lies a little off the ICP's), while
  // a round flange 31 deg off rose 0.042 (its bolt holes): no bound there
  // tells right from wrong. A flange no scan can pin is found by its
  // geometry (observability.h). Prismatic joints are not tested: on the
  // bundled gun's jaw (a rod sliding along itself) the lower rise at 5 mm
  // ran from -0.125 to 0.2 mm/sample over 48 fits whose jaws were within
  // 4 mm, and was 0.015 and -0.001 for the two off by more: no bound
  // separates them.
  double pinning_revolute = 5.0 * M_PI / 180.0;  // [rad]
  double pinning_mean_loss = 0.00006;
  // After a joint takes its alternative value, the subtree pass runs again
  // over every joint, up to this many times, until none moves by more than
  // settle_tolerance_rad (revolute) or settle_tolerance_m (prismatic).
  int max_passes_after_switch = 3;
  double settle_tolerance_rad = 0.01 * M_PI / 180.0;
  double settle_tolerance_m = 0.0002;

  static WeightedIcpOptions DefaultJointIcp();
  static WeightedIcpOptions DefaultSubtreeIcp();
  bool IsValid(std::string* error) const;
};

// What the chain pass found for one independent joint.
struct JointRecord {
  int joint = -1;
  bool symmetric = false;  // the sweep and ICP carried the children
  JointSweepSummary sweep;
  double sweep_margin = std::numeric_limits<double>::infinity();  // runner-up, per sample [m]
  int icp_iterations = 0;
  // full_sweep: FitJoint's last sweep over the joint's whole range was of
  // a revolute body alone (not symmetric); full_sweep_q its best value, and
  // the pose of the link the joint hangs from then (CheckFinalBasins does
  // not sweep it again there).
  bool full_sweep = false;
  double full_sweep_q = 0.0;
  Pose T_world_parent_swept = Pose::Identity();
  // ChainFitter::CheckAlternatives and CheckPinning (ChainOptions::ambiguity_*).
  bool ambiguous = false;
  // CheckFinalBasins: another value fits better than the final one.
  bool better_elsewhere = false;
  double alternative = 0.0;
  double margin = std::numeric_limits<double>::infinity();
  // CheckAlternatives: how much better the value taken fits the scan with
  // the coverings, per sample [m] (negative: the alternative does); NaN
  // when no pair was compared.
  double covered_margin = std::numeric_limits<double>::quiet_NaN();
};

// The scan with the coverings prefers the alternative by more than
// ambiguity_mean_loss per sample: the pair is decided by where the
// coverings were found (CheckAlternatives calls it ambiguous).
inline bool DecidedByCoverings(double covered_margin, const ChainOptions& options) {
  return covered_margin < -options.ambiguity_mean_loss;
}

class ChainFitter {
 public:
  // All borrowed and must outlive the fitter: icp_samples and sweep_samples
  // are the CAD samples of every link (model.links() order, link frame), at
  // the ICP's and the sweep's spacing; say gets a line per step (may be empty).
  ChainFitter(const KinematicModel& model, const ChainOptions& options,
              const CadSampleOptions& samples, const std::vector<SurfaceSamples>& icp_samples,
              const std::vector<SurfaceSamples>& sweep_samples, WeightedIcp* icp,
              const JointSweep* sweep, std::function<void(const std::string&)> say);

  // Every joint on the base at T_world_base: the chain pass with its
  // resweeps, then (refine_subtrees) the subtree pass, the alternatives and
  // the passes after a switch. *q: every joint
  // (model order, dependent ones resolved as far as possible); *records:
  // one per independent joint in fit order; *loss: the Eq. (9) loss of the
  // whole model.
  Status Fit(const Pose& T_world_base, std::vector<double>* q, std::vector<JointRecord>* records,
             double* loss);

  // Extension, after the whole-chain refinement: each joint's body (with
  // its children when symmetric) is swept over the joint's range at the
  // final values of every other joint. The sequential fit chose each basin
  // with the joints above it not yet final (a gun's jaw swept under a wrist
  // a degree off); the final values are the best context there is. When
  // the sweep's best lies in another basin (ChainOptions::final_basin_*)
  // and beats the final value by more than ambiguity_mean_loss per sample,
  // the joint is fitted from there as a branch (FitBranch: the joints below
  // it fitted anew, since a wrist flip moves three joints at once) and the
  // two are compared as CheckAlternatives does. A revolute body alone
  // whose sweep over the whole range (JointRecord::full_sweep) found this
  // basin with the link it hangs from within resweep_tolerance_* of where
  // it is now is not swept again: the same sweep would find the same (the
  // demo's realistic fit: these sweeps 1.35 -> 0.68 s). A prismatic one
  // always is (its sweep costs little): a jaw sliding along itself has a
  // flat profile, which a wrist moved by less than that can tip. A branch
  // better by more
  // than ambiguity_mean_loss per sample of the subtree is another basin:
  // take = true moves *q there (*moved; refine the chain again), take =
  // false marks the record ambiguous and better_elsewhere with the
  // branch's value as its alternative (the fit is not ok). A branch better
  // on the whole subtree but not on the evidence (CompareViews'
  // evidence_gain) only shows more of surface both values explain: the scan
  // does not pin the joint, which keeps its value and is ambiguous with the
  // branch's value as its alternative. A branch that is not better leaves
  // the joint as it is. A taken branch clears what
  // the earlier checks said of the joints below, except this joint's own
  // ambiguity when its alternative is another basin from the new value too.
  Status CheckFinalBasins(const Pose& T_world_base, bool take, std::vector<double>* q,
                          std::vector<JointRecord>* records, bool* moved);

  // Whether the scan pins each revolute joint down at the final values q:
  // its subtree's Eq. (9) loss at the joint's value moved by
  // ChainOptions::pinning_revolute must rise by at least pinning_mean_loss
  // per sample, on average over the two sides within the limits; else the
  // joint is ambiguous with the moved value as its alternative (a link that
  // nothing below it tells). Checked at the sequential fit's values instead
  // (with the 0.5 deg move of then), jacketed wrists pulled off their
  // minimum rose by -0.043 to 0.020 mm/sample, and 4 of 12 right fits of
  // big robots with a gun were called ambiguous.
  void CheckPinning(const Pose& T_world_base, std::vector<JointRecord>* records,
                    const std::vector<double>& q) const;
  // The scan with its coverings (jackets, covers; borrowed, may be null),
  // for a fitter whose own scan has them removed: a covering hides its
  // link's surface but keeps the link's shape a few millimetres out, which
  // the Eq. (9) loss (tau_dist 1 cm) still reads (a jacketed forearm: its
  // drive cover under the jacket tells a flipped wrist).
  void set_covered_scan(const JointSweep* sweep) { covered_scan_ = sweep; }
  // How much better q fits than q_other on the scan with the coverings
  // (BranchGain's scoring; 0 without that scan) [m per sample]: a pair the
  // fitter's own scan cannot tell apart is told when this exceeds
  // ambiguity_mean_loss, and a pair this scores the other way by more than
  // that is ambiguous, decided by where the coverings were found
  // (CheckAlternatives, and the pipeline's comparison of its passes with
  // and without the coverings).
  double CoveredMargin(const Pose& T_world_base, const std::vector<double>& q,
                       const std::vector<double>& q_other, int link) const;

  // How much better q_other fits than q the bodies below `link` that the
  // two place apart (PlacedApart): their Eq. (9) loss difference per
  // sample of the whole subtree [m]; negative when q fits better. Scored
  // on `sweep`'s scan (nullptr: the fitter's).
  double BranchGain(const Pose& T_world_base, const std::vector<double>& q,
                    const std::vector<double>& q_other, int link,
                    const JointSweep* sweep = nullptr) const;
  // What the bodies below `link` that q and q_other place apart show at
  // each. evidence_gain, per sample of the whole subtree (BranchGain's
  // scale) [m]: BranchGain on their samples a scanner sees at both values,
  // plus each sample matched within ChainOptions::explained_distance at one
  // value and hidden at the other when no matched sample of the model at
  // the other lies near it (surface only that value explains; for q_other,
  // against q); samples that only show more of surface both explain are
  // left out. shown counts the samples matched at q_other and hidden at q,
  // new_surface those of them on surface q leaves unmatched.
  struct ViewComparison {
    double evidence_gain = 0.0;
    size_t shown = 0;
    size_t new_surface = 0;
  };
  ViewComparison CompareViews(const Pose& T_world_base, const std::vector<double>& q,
                              const std::vector<double>& q_other, int link) const;
  // The Eq. (9) loss of every link at or below `link` at joint values q;
  // *samples counts the sweep samples scored.
  double SubtreeLoss(const Pose& T_world_base, const std::vector<double>& q, int link,
                     size_t* samples) const;
  // The same over the links with in[l] set only, on `sweep`'s scan
  // (nullptr: the fitter's).
  double LinksLoss(const Pose& T_world_base, const std::vector<double>& q,
                   const std::vector<bool>& in, size_t* samples,
                   const JointSweep* sweep = nullptr) const;

 private:
  // ChainOptions::pair_sweep_step: `record`'s joint and `bend` swept
  // together (pair_sweep.h); the bend takes its swept value in *q and the
  // joint's ICP samples (*body_icp) carry the bend's body at it.
  Status SweepWithTheBend(const Pose& T_world_base, const Body& body, int bend,
                          std::vector<double>* q, JointRecord* record,
                          SurfaceSamples* body_icp) const;
  // The chain pass: per joint the Eq. (9) sweep and the joint ICP; a
  // symmetric body and every joint after it are swept again near their
  // values until none moves (a round wrist, then the flange and the gun).
  Status FitJoints(const Pose& T_world_base, std::vector<double>* q,
                   std::vector<JointRecord>* records);
  // One joint. resweep: it was fitted before; a revolute joint is swept
  // only within ChainOptions::resweep_window_rad of its value and keeps its
  // symmetry decision and runner-up.
  Status FitJoint(const Pose& T_world_base, std::vector<double>* q, JointRecord* record,
                  bool resweep = false);
  // Extension of Sec. 5.2.2: each joint once more, parents first, with all
  // it carries (its subtree at the fitted values): a nearly round link (a
  // wrist) fits its angle poorly alone; its children's lever fixes it.
  // Only the joints of records from `first` on that lie in `only_below`'s
  // subtree (a link; -1: all).
  Status RefineSubtrees(const Pose& T_world_base, size_t first, int only_below,
                        std::vector<JointRecord>* records, std::vector<double>* q);
  // Extension: a joint swept while the link it hangs from was elsewhere (the
  // subtree pass turned that link by more than resweep_tolerance_rad or
  // moved it by more than resweep_tolerance_m since `swept`, the values
  // after the chain pass) is fitted again, as in a resweep: a revolute one
  // near its value, a prismatic one over its range. A gun's jaw swept under
  // a wrist a degree off (a jacketed forearm pulls the joint ICP) lands in
  // a wrong basin that its ICP does not leave. *reswept: some joint was.
  Status ResweepMoved(const Pose& T_world_base, const std::vector<double>& swept,
                      std::vector<JointRecord>* records, std::vector<double>* q, bool* reswept);
  // A joint whose sweep found a runner-up nearly as good (a wrist turned
  // half a turn, a bare flange) is fitted again from the runner-up, with
  // every joint below it fitted anew (a wrist flip changes them too), and
  // the Eq. (9) losses of the subtree's bodies the two place apart
  // (PlacedApart) are compared: the lower wins; a margin
  // below ChainOptions::ambiguity_mean_loss per sample makes the joint
  // ambiguous. *switched: some joint took its other value (the joints
  // above it were refined with the old subtree: refine them again).
  Status CheckAlternatives(const Pose& T_world_base, std::vector<JointRecord>* records,
                           std::vector<double>* q, bool* switched);
  // The branch of records[i]'s joint at `value`: *q_other is q with the
  // joint there, every later joint below it fitted anew (FitJoint over its
  // range) and the subtree pass run below it; *other_records likewise.
  Status FitBranch(const Pose& T_world_base, size_t i, double value, const std::vector<double>& q,
                   const std::vector<JointRecord>& records, std::vector<double>* q_other,
                   std::vector<JointRecord>* other_records);
  // Adds the children of `joint`'s body at their values in T_world_link,
  // in the body's frame: a revolute child only its round part about its
  // own axis when it has one (a flange: it is where it is whatever the
  // child's value, while the rest, at a value not fitted yet, could pull
  // the joint into a wrong basin it would not leave; a wrist under a gun).
  // icp may be null (a sweep alone).
  void AddChildren(int joint, const std::vector<Pose>& T_world_link, SurfaceSamples* icp,
                   SurfaceSamples* sweep) const;
  // The links with in[l] that q and q_other place apart (see
  // ChainOptions::alike_share): the ones a comparison of the two should
  // score.
  std::vector<bool> PlacedApart(const Pose& T_world_base, const std::vector<double>& q,
                                const std::vector<double>& q_other,
                                const std::vector<bool>& in) const;
  // in[l]: link l is `link` or below it (link -1: every link).
  std::vector<bool> SubtreeMask(int link) const;
  // Whether a link at `now` turned by more than resweep_tolerance_rad or
  // moved by more than resweep_tolerance_m from `then`.
  bool LinkMoved(const Pose& then, const Pose& now) const;

  const KinematicModel& model_;
  const ChainOptions& options_;
  const CadSampleOptions& samples_;
  const std::vector<SurfaceSamples>& icp_samples_;
  const std::vector<SurfaceSamples>& sweep_samples_;
  WeightedIcp* icp_;
  const JointSweep* sweep_;
  const JointSweep* covered_scan_ = nullptr;
  std::function<void(const std::string&)> say_;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_JOINTS_CHAIN_FITTER_H_
