// Whole-chain refinement (--refine_chain, an extension of paper Sec. 5):
// after the sequential fit (base, then each joint with the joints above it
// held), one Ceres problem over the base pose and every independent joint
// value together. Each ICP iteration poses every link's CAD samples by the
// forward kinematics, keeps those a scanner could see, finds their scan
// correspondences (gated, edge weights w_edge) and solves
//
//   min_x  1/2 sum_links sum_i rho(r_i(x)^2),   x = (base pose, q)
//
// with r_i the Eq. (8) residual of costs/chain_point_cost.h (point-to-plane
// on the CAD normal, point-to-point on prismatic bodies, as the sequential
// stages use). The kinematic constraints hold exactly: the links move only
// as the joints let them, mimic and loop-closure joints follow theirs, and
// every joint stays within its limits (Ceres bounds).
//
// The standard deviations of the joints and the base come from two parts:
// the residuals' spread, s^2 H^-1 with H = J^T J at the estimate and
// s^2 = 2 cost / (residuals - parameters) (ceres::Covariance, dense SVD),
// which takes the residuals as independent; and the CAD's own error, each
// patch of a link's surface displaced as a whole (surface_patches.h). No
// amount of scan points averages the second away: a part pinned by a few
// small faces keeps their error (a gun's electrode along its slide, pinned
// by its tip; seen from one side, the tip's cone turns a sideways
// displacement into one along the slide).
//
// The iterations stop when no sample moved more than the ICP's
// convergence_displacement, or when the estimate came back to within that
// of an earlier one at the final gate (a cycle of flipping correspondences);
// the stop reason is kConverged for both.
//
// Deterministic: the correspondence search is, Ceres runs single-threaded.
#ifndef EDGEFIT_SOLVERS_REFINEMENT_CHAIN_REFINEMENT_H_
#define EDGEFIT_SOLVERS_REFINEMENT_CHAIN_REFINEMENT_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/correspondence/correspondence_search.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/scan/organized_scan.h"
#include "solvers/registration/residual_options.h"
#include "solvers/registration/weighted_icp.h"

namespace edgefit {

struct ChainRefinementOptions {
  // false: no solve, only the covariance at the given estimate.
  bool refine = true;
  // Iterations, gates (first gate: correspondence.max_distance, halved down
  // to final_gate), visibility and point-to-plane as in the sequential
  // stages; the quality fields do not apply. The weights are the search's.
  WeightedIcpOptions icp = DefaultIcp();
  // A sample counts as seen when a scan's range at its cell is at most this
  // much nearer than the sample [m] (ScanVisibility's tolerance; the gate
  // when that is smaller). A wider tolerance lets in samples just behind a
  // nearer surface (a flange's chamfer behind its rim, a link's edge behind
  // its neighbour); they match that surface, in front of them, with residuals
  // of one sign. At the 5 mm gate a bare FANUC's joint_5 came out 0.041 deg
  // off on a noise-free scan, 0.017 deg at 2 mm; on the bench's bare robots
  // (1.7 mm, 1 mm noise) 2 mm took the largest error from 0.095 to 0.036
  // deg and the KUKA's mean from 0.0065 to 0.0044 deg (BENCHMARK.md). Much
  // below twice the range noise, the samples whose noise puts the scan in
  // front of them drop out: a bias of the other sign (a 4 mm scan in
  // chain_refinement_test: joint_5 0.03 deg off at 2 mm, 0.01 at 5 mm).
  double visibility_tolerance = 0.002;
  // Compute the standard deviations at the estimate returned (one more
  // correspondence search and a dense SVD of 6 + joints parameters).
  bool covariance = true;
  // The CAD surfaces' deviation from the real ones [m], a standard
  // deviation per axis and patch of cad_deviation_patch [m] (the
  // covariance's second part above); 0: the residuals alone (a lower bound,
  // right only for scans of the CAD itself). 0.5 mm: machined and
  // sheet-metal parts are made to a millimetre or better, castings to one
  // or two. The realistic sensor's as-built surfaces (0.5-2 mm largest
  // displacement per link, 0.2-0.8 m wavelength) are off by 0.27 mm RMS
  // along their normals (the bundled robot with its gun, 20 postures'
  // fields). The patch: the shortest wavelength of those surfaces.
  double cad_deviation = 0.0005;
  double cad_deviation_patch = 0.2;
  // Weight each point-to-plane residual by min(1, c / incidence_cosine),
  // c the cosine of the angle between the beam of its scan point and the
  // CAD normal at its sample (the weight at least 1/16); 0: no such
  // weights. A return at grazing incidence counts less: there the beam's
  // footprint spreads over 1/c of its width, and where it meets an edge its
  // range lies off the surface. (Range noise alone would not ask for this:
  // it lies along the beam, and reaches a point-to-plane residual times c.)
  double incidence_cosine = 0.0;

  static WeightedIcpOptions DefaultIcp();
  bool IsValid(std::string* error) const;
};

struct ChainRefinementSummary {
  int iterations = 0;  // Ceres solves done
  IcpStopReason stop_reason = IcpStopReason::kMaxIterations;
  size_t correspondences = 0;  // at the estimate returned, final gate
  double final_cost = 0.0;     // Ceres cost at the estimate returned
  // Largest distance any sample moved from the sequential fit's estimate [m].
  double max_displacement = 0.0;
  // Covariance: every parameter has a deviation (false when covariance is
  // off, or when some direction of the problem is pinned by no residual: a
  // joint the scan does not pin, a round base's yaw with its first joint;
  // the parameters outside such directions still have theirs).
  bool covariance_ok = false;
  double sigma = 0.0;             // residual standard deviation s [m]
  // Per joint, model order [rad] or [m]; NaN: not a parameter, or one the
  // residuals do not pin (surface_patches.h InverseNormalMatrix).
  std::vector<double> joint_std;
  // The part of joint_std the residuals alone give (s^2 H^-1): a lower bound.
  std::vector<double> joint_std_residuals;
  Eigen::Vector3d base_rotation_std = Eigen::Vector3d::Constant(NAN);     // world axes [rad]
  Eigen::Vector3d base_translation_std = Eigen::Vector3d::Constant(NAN);  // world axes [m]
  double seconds = 0.0;
};

// link_samples: CAD samples of each link (indexed like model.links(), in
// the link frame, with normals; empty links are left out). Every body,
// prismatic ones too, has point-to-plane residuals (options.icp): unlike
// the joint ICP of a prismatic body, which needs point-to-point residuals
// to converge from its sweep, the refinement starts near the minimum, and
// point-to-point residuals would hold a sliding part where the samples
// fall on the scan's lattice (the gun's jaw stayed 0.9-1.9 mm off on
// ideal 1.7 mm scans, 0.01-0.5 mm with point-to-plane). Refines
// *T_world_base and the independent joints of *q (every joint, model order;
// the dependent ones are resolved) in place, under the loss of `residuals`
// (its parameterization and lambda do not apply: the joints are the
// parameters). `missing` (nullptr: none): cells of `scans` taken as if
// their beam had returned nothing (mixed pixels), in the visibility test;
// `search` must leave them out as well (CorrespondenceSearch's `missing`).
// Errors (estimate unchanged): invalid options, sizes that do not match the
// model, no samples.
Status RefineChain(const KinematicModel& model, const ScanSet& scans, const CellMask* missing,
                   CorrespondenceSearch* search, const std::vector<SurfaceSamples>& link_samples,
                   const ChainRefinementOptions& options, const ResidualOptions& residuals,
                   Pose* T_world_base, std::vector<double>* q, ChainRefinementSummary* summary);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REFINEMENT_CHAIN_REFINEMENT_H_
