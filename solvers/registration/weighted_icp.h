// The weighted, constrained ICP engine every precise registration stage
// calls (paper Sec. 5.1.2, 5.2.2, 6.1, 6.2.2). Each iteration:
//   1. pose the link's CAD samples p_link with the current estimate, leaving
//      out those no scanner could see (options.visibility);
//   2. correspondences: nearest scan point of each sample through the scan
//      lattice or a cropped kd-tree, gated by distance, each carrying the
//      target cell's edge weight w_edge (correspondence_search.h);
//   3. one Ceres problem: a data residual per correspondence, Eq. (8)
//      sqrt(w_edge) (R p + t - q) or its point-to-plane variant, under the
//      chosen loss (in joint space under the trivial loss all of them in
//      one block, costs/joint_batch_cost.h), plus, for a link on a joint,
//      the kinematic constraint;
//   4. stop when no sample moved more than convergence_displacement.
//
// How the residuals are formed (loss, the constraint of a link on its
// joint) is the engine's, given once when it is made (residual_options.h);
// what varies per stage (gates, iterations, point-to-plane, visibility) is
// in WeightedIcpOptions.
//
// Deterministic for any thread count: the correspondence search is, and
// Ceres runs single-threaded (its multi-threaded cost and gradient sums
// depend on the schedule); the problems are small (6 or 1 parameters).
#ifndef EDGEFIT_SOLVERS_REGISTRATION_WEIGHTED_ICP_H_
#define EDGEFIT_SOLVERS_REGISTRATION_WEIGHTED_ICP_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/correspondence/correspondence_search.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/scan/organized_scan.h"
#include "solvers/registration/link_motion.h"
#include "solvers/registration/residual_options.h"
#include "solvers/registration/scan_visibility.h"

namespace edgefit {

struct WeightedIcpOptions {
  // ICP iterations (correspondence search + Ceres solve) at most.
  int max_iterations = 30;
  // Converged when no CAD sample moved more than this in an iteration [m]
  // (measured exactly: a rigid motion moves a box's points most at a corner,
  // so the corners of the samples' box are checked). 10 um is 1 % of the
  // paper's scanner noise and 0.0006 degrees at 1 m.
  double convergence_displacement = 1e-5;
  // Fewer gated correspondences than this stops the fit (kTooFewCorrespondences).
  int min_correspondences = 12;
  // Search: lattice or kd-tree, lattice window, and the gate of the first
  // iteration (max_distance [m]: about the error of the initial estimate).
  CorrespondenceOptions correspondence;
  // The gate halves after every iteration down to final_gate [m], so that
  // matches on unmodelled surfaces near the link (cables, covers, parts the
  // CAD lacks) drop out once the estimate is close; convergence counts only
  // at the final gate. 5 mm is 5 sigma of the paper's 1 mm scanner noise.
  // A final_gate >= correspondence.max_distance keeps the gate fixed.
  double final_gate = 0.005;
  // Point-to-plane data residuals n^T (R p + t - q) instead of Eq. (8)'s
  // point-to-point ones. Both parameterisations (joint_point_to_plane_cost.h
  // in joint space).
  bool point_to_plane = false;
  // Where the point-to-plane normal n comes from:
  //   kModel  the CAD sample's own normal (SurfaceSamples::normals, needed),
  //           posed with the estimate at the start of each ICP iteration
  //           and held fixed within its solve: exact up to the mesh;
  //   kScan   the target normal the engine was given (the edge stage's PCA
  //           normals; cells without one fall back to point-to-point).
  //           Within a few mm of an edge these are tilted towards the other
  //           face, and those are the cells where Eq. (6) puts w_high: on 8
  //           bundled-robot fits with accessories, edge weights, the joints'
  //           mean error was 0.0214 deg with them, 0.0134 deg with kModel
  //           (BENCHMARK.md, "Robot fit").
  enum class PlaneNormals { kModel, kScan };
  PlaneNormals plane_normals = PlaneNormals::kModel;
  // Levenberg-Marquardt iterations per Ceres solve. The correspondences
  // change after each solve, so exact inner convergence is wasted; the
  // problem is nearly linear for fixed matches, so 3 are close to exact.
  int solver_iterations = 3;
  // Which samples take part in an iteration: only those some scanner could
  // see at the current pose. CAD samples on faces no scanner saw (back
  // faces, faces hidden by other parts of the link, by other links or by
  // cables) have their nearest scan points on the visible faces next to
  // them, a bias toward the scanners. A sample counts as seen by scan s when
  //   its outward normal faces the scanner: n . (o_s - p) > 0, and
  //   (organized scans) the scan's range at p's lattice cell is not shorter
  //   than p's range by more than the gate: the scan's range image is the
  //   z-buffer of the real scene, so whatever hid the sample, it is in it.
  // kAll uses every sample; kFacing the normal test alone; kSeen both.
  // Needs sample normals (SurfaceSamples::normals); without them every
  // sample is used.
  enum class Visibility { kAll, kFacing, kSeen };
  Visibility visibility = Visibility::kSeen;
  // Quality only (not the fit): a sample on a face seen so obliquely that
  // the scan's points on it lie farther apart than this [m] is left out of
  // the visible samples (ScanView::kGrazing, JointSweepOptions::
  // max_view_gap; 0: off). In the fit such faces help: leaving them out of
  // a conveyor's ICPs (5 mm spacing) took lifter_1 from 0.03 to 0.41 mm off.
  double quality_max_view_gap = 0.0;
  // Quality (WeightedIcpSummary inliers, rms) under point_to_plane with
  // kModel normals: a visible sample is an inlier when its nearest scan
  // point within quality_reach [m] lies within the final gate of the
  // sample's CAD tangent plane; rms is over those plane distances. A face
  // seen at a grazing angle (a conveyor's deck top at 85 degrees) has its
  // scan points 3 mm / cos(85 deg) = 3.4 cm apart along it: most of its
  // samples have no scan point within a 5 mm sphere, yet lie on the scanned
  // plane. Otherwise (and with quality_reach <= the gate) the Euclidean
  // distance within the final gate counts.
  double quality_reach = 0.02;
  // kd-tree crop: the box of the samples at the initial pose grown by
  // correspondence.max_distance + crop_margin [m], fixed for the whole fit
  // so the tree is built once.
  double crop_margin = 0.1;

  bool IsValid(std::string* error) const;
};

enum class IcpStopReason {
  kConverged,              // displacement below convergence_displacement
  kMaxIterations,          // max_iterations reached
  kTooFewCorrespondences,  // fewer than min_correspondences matches
  kSolverFailed,           // Ceres returned no usable solution
};
const char* IcpStopReasonName(IcpStopReason reason);  // "converged", ...

struct WeightedIcpSummary {
  int iterations = 0;  // Ceres solves done
  IcpStopReason stop_reason = IcpStopReason::kMaxIterations;
  // Ceres cost 1/2 sum rho(|r|^2) at the end of the last solve (data plus
  // penalties; before the projection of kPoseWithPenalties).
  double final_cost = 0.0;
  // At the returned pose, with the final gate: gated correspondences, their share of the samples,
  // and their RMS distance [m] (unweighted; see WeightedIcpOptions::quality_reach).
  size_t source_points = 0;   // all CAD samples
  size_t visible_points = 0;  // samples a scanner could see at the returned pose
  // Samples facing a scanner, in its window, but behind the surface it
  // scanned there (kOccluded at best): hidden by something in front, or
  // placed inside or behind a scanned surface.
  size_t occluded_points = 0;
  size_t inliers = 0;         // of the visible samples
  double inlier_share = 0.0;
  double rms = 0.0;
  double median_distance = 0.0;  // of the inliers [m]: robust where rms is not
  // kPoseWithPenalties on a joint: largest distance a sample moved when the
  // 6-DoF result was projected onto the joint [m] (0 otherwise), a measure
  // of how far the penalties let the link leave its joint.
  double projection_shift = 0.0;
  double seconds = 0.0;  // wall time of Fit [s]

  // One line: iterations, stop reason, inliers, RMS [mm], cost.
  std::string BriefReport() const;
};

// The estimate the engine refines: T_world_link, and the joint value q
// (radians or metres) for a link on a joint, where T_world_link =
// motion.PoseAt(q).
struct LinkState {
  Pose T_world_link = Pose::Identity();
  double q = 0.0;
};

class WeightedIcp {
 public:
  // All borrowed and must outlive the engine. `search` holds the scans and
  // the target weights (uniform weights: a search without weights);
  // `normals_scanner` (nullptr: none) holds unit target normals per scan per
  // cell in the scanner frame, NaN where undefined
  // (EdgeDetectionResult::normals), for point_to_plane. `residuals` (copied)
  // holds the loss and the joint parameterisation of every Fit; Fit fails
  // when they are invalid.
  WeightedIcp(const ScanSet* scans, CorrespondenceSearch* search,
              const std::vector<std::vector<Eigen::Vector3f>>* normals_scanner = nullptr,
              const ResidualOptions& residuals = ResidualOptions());

  // Refines *state for the link whose CAD samples are `samples` (link
  // frame [m]; normals optional, for the visibility test) moving as
  // `motion`. The initial estimate is state->T_world_link for
  // a free link and state->q (clamped into the limits) on a joint; on return
  // both hold the result. Errors (state unchanged): invalid options, no
  // samples, point_to_plane without normals.
  // A fit that stops early is no error: see summary->stop_reason.
  Status Fit(const SurfaceSamples& samples, const LinkMotion& motion,
             const WeightedIcpOptions& options, LinkState* state, WeightedIcpSummary* summary);

  // The quality fields of a summary (visible_points, inliers, inlier_share,
  // rms) for the samples at T_world_link with the final gate, without
  // fitting. Errors: invalid options, no samples.
  Status Evaluate(const SurfaceSamples& samples, const Pose& T_world_link,
                  const WeightedIcpOptions& options, WeightedIcpSummary* summary);

 private:
  const ScanSet* scans_;
  CorrespondenceSearch* search_;
  const std::vector<std::vector<Eigen::Vector3f>>* normals_scanner_;
  const ResidualOptions residuals_;
  // Selects the samples used at pose T (WeightedIcpOptions::visibility)
  // into p_used_link_ and poses them into q_world_; `gate` [m] is the
  // occlusion tolerance (max_view_gap: WeightedIcpOptions). Returns how
  // many samples were occluded at best (0 without the range-image test).
  size_t SelectAndPose(const SurfaceSamples& samples, const Pose& T_world_link,
                       WeightedIcpOptions::Visibility visibility, double gate, double max_view_gap);
  // The quality fields of *summary at T_world_link with gate [m].
  void Measure(const SurfaceSamples& samples, const Pose& T_world_link,
               const WeightedIcpOptions& options, double gate,
               const Eigen::AlignedBox3d& crop_world, WeightedIcpSummary* summary);
  ScanVisibility visibility_;
  // Buffers reused between iterations and fits.
  std::vector<ScanView> views_;               // per sample, SelectAndPose's
  std::vector<Eigen::Vector3f> p_used_link_;  // the samples of the iteration
  std::vector<Eigen::Vector3f> n_used_link_;  // their normals, when the samples have them
  std::vector<Eigen::Vector3f> q_world_;      // the same, posed
  std::vector<Correspondence> correspondences_;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REGISTRATION_WEIGHTED_ICP_H_
