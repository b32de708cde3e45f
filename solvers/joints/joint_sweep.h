// The rough 1-DoF search of a link on a joint (paper Sec. 5.2.1 revolute,
// 6.2.1 prismatic): the link's CAD samples are moved through the joint's
// whole range at a fixed step, each step scored by the edge-weighted robust
// loss of Eq. (9) with lattice nearest neighbours, and the best step is
// refined at finer steps around it (coarse to fine).
//
// The score of a joint value q is a sum over every sample, so that all steps
// are compared on the same points:
//   seen by a scanner (scan_visibility.h)  Eq. (9) with D = distance to the
//                                          nearest scan point, capped at
//                                          max_distance when none is nearer;
//   hidden behind nearer scan points       occluded_loss (no evidence);
//   facing no scanner                      occluded_loss.
// A pose that puts the link where the scanners saw empty space or other
// surfaces pays the outlier branch of Eq. (9); hidden samples neither help
// nor hurt.
#ifndef EDGEFIT_SOLVERS_JOINTS_JOINT_SWEEP_H_
#define EDGEFIT_SOLVERS_JOINTS_JOINT_SWEEP_H_

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/correspondence/lattice_search.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/registration/link_motion.h"
#include "solvers/registration/scan_visibility.h"

namespace edgefit {

struct JointSweepOptions {
  // Coarse step over the range: 1 degree for revolute joints (1.7 cm at 1 m,
  // inside the Eq. (9) basin), 5 mm for prismatic ones.
  double revolute_step = M_PI / 180.0;  // [rad]
  double prismatic_step = 0.005;        // [m]
  // Refinements: each searches +/- one previous step around the best at a
  // tenth of it (1 -> 0.1 -> 0.01 degrees by default).
  int refinements = 2;
  // Eq. (9) inlier threshold tau_dist [m].
  double tau_dist = 0.01;
  // Distances are capped here [m] (the lattice search's gate): a seen sample
  // without a scan point this close costs max_distance * w.
  double max_distance = 0.05;
  // Loss of a hidden sample [m]: the inlier/outlier boundary, so hiding is
  // neither better than a good match nor as bad as a miss.
  double occluded_loss = 0.01;
  // Occlusion tolerance of the visibility test [m].
  double visibility_tolerance = 0.01;
  // A sample on a face seen so obliquely that the scan's points on it lie
  // farther apart than this [m] counts as hidden (ScanView::kGrazing; 0:
  // off). Its nearest scan point is then often beyond tau_dist although the
  // face is right there: a conveyor's lifter beam seen edge-on by scanners
  // at its height scored lower 1 cm off its true height than at it (5 mm
  // spacing; FitOptionsFor sets 1 cm for conveyance systems).
  double max_view_gap = 0.0;
  int lattice_window = 2;  // CorrespondenceOptions::window
  // The runner-up is the best coarse local minimum at least this far from
  // the best value: a second pose of the link that fits about as well
  // (a near-symmetric flange turned half a turn) makes the fit ambiguous.
  double distinct_revolute = 5.0 * M_PI / 180.0;  // [rad]
  double distinct_prismatic = 0.02;               // [m]

  bool IsValid(std::string* error) const;
};

struct JointSweepSummary {
  double q = 0.0;     // best joint value [rad] or [m]
  double loss = 0.0;  // its total Eq. (9) loss [m]
  // The runner-up (JointSweepOptions::distinct_*), refined like the best.
  bool has_runner_up = false;
  double runner_up_q = 0.0;
  double runner_up_loss = std::numeric_limits<double>::infinity();
  int evaluations = 0;  // joint values scored
  double seconds = 0.0;
};

// The range a sweep of `motion` covers [rad] or [m]: its limits; one turn
// for a continuous joint, and for a revolute range over a turn the turn
// nearest zero that the limits hold.
void SweptRange(const LinkMotion& motion, double* lower, double* upper);
// lower, lower + step, ..., upper (upper always included).
std::vector<double> SweepValues(double lower, double upper, double step);

class JointSweep {
 public:
  // Borrowed: the scans' lattice search (organized scans) and visibility.
  JointSweep(const LatticeSearch* lattice, const ScanVisibility* visibility);

  // The total loss of `samples` (link frame, with normals) with the link at
  // T_world_link; Loss at a joint value of `motion`. LossAt also scores
  // free-link hypotheses (the base candidates of robot_fit). losses (may be
  // null): each sample's loss, -1 for a hidden one. Thread-safe.
  double LossAt(const SurfaceSamples& samples, const Pose& T_world_link,
                const JointSweepOptions& options, std::vector<float>* losses = nullptr) const;
  double Loss(const SurfaceSamples& samples, const LinkMotion& motion, double q,
              const JointSweepOptions& options) const {
    return LossAt(samples, motion.PoseAt(q), options);
  }
  // Sweeps motion's range (a continuous joint: one turn) and returns the best
  // value and the runner-up; joint values are scored in parallel (OpenMP),
  // the result is the same for any thread count. Fails on invalid options,
  // a free motion or no samples.
  Status Sweep(const SurfaceSamples& samples, const LinkMotion& motion,
               const JointSweepOptions& options, JointSweepSummary* summary) const;

 private:
  // One sample at world point p with world normal n (null: seen from
  // everywhere): occluded_loss when hidden (*seen false), else Eq. (9).
  double SampleLoss(const Eigen::Vector3d& p, const Eigen::Vector3d* n,
                    const JointSweepOptions& options, bool* seen) const;

  const LatticeSearch* lattice_;
  const ScanVisibility* visibility_;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_JOINTS_JOINT_SWEEP_H_
