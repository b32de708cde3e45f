// Fits every instance of several models in the scans of one cell: each
// model in turn (SearchOrder: robots first), instance after instance,
// Fit() on the points that are left, the instance's points removed before
// the next (the paper's purpose: the fitted equipment replaced by movable
// models, the rest kept as the background).
//
// The scans' edges (Sec. 4) are detected once, before the first fit, with
// the first model's edge options (and its mixed pixels removed first when
// it asks so); every fit reads them (FitWithEdges), cropped to its
// instance after its rough base poses (FitOptions::crop, turned on here),
// and stops after the base where the base cannot pass its verdict
// (FitOptions::min_base_inlier_share, the quality's inlier share here: after
// their precise ICP the right bases of the demo and the realistic cell had
// 99.9-100 % of their visible samples within the gate, the places where a
// search for one more instance fitted a whole chain for nothing 43-51 %).
//
// A fit is an instance when its base matches the scan and no body is a
// mismatch (IsInstance): a part the stations did not see, or a joint the
// scan leaves ambiguous, makes the instance's own quality not ok and says
// which joint, but the machine is there. A model's search stops at its
// count, or at the first fit that is not an instance, which is recorded
// with its reason and never counted.
#ifndef EDGEFIT_PIPELINE_CELL_FIT_H_
#define EDGEFIT_PIPELINE_CELL_FIT_H_

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/pipeline/attached_points.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/pipeline/fit_options.h"
#include "edgefit/pipeline/fit_result.h"
#include "edgefit/pipeline/model_points.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct CellModel {
  std::string name;
  const KinematicModel* model = nullptr;
  FitOptions options;
  // Instances to find; 0 = every instance (until a fit is not ok).
  int count = 0;
};

struct CellOptions {
  // Each instance's points (within this of its fitted surface) leave the
  // scans before the next fit; also the background's removal distance.
  ModelPointsOptions removal;
  // And with them the points attached to them (dress packs, hoses, covers).
  AttachedPointsOptions attached;
  // At most this many instances of one model with count 0.
  int max_instances = 16;
  // Optional region (world frame; empty: the whole scan): instances are
  // looked for and fitted on its points only; each found instance's points
  // leave the whole scan, inside the region or not.
  Eigen::AlignedBox3d roi_world;
};

struct CellInstance {
  int model = -1;  // index into the models
  int index = 0;   // 1, 2, ... within its model
  FitResult fit;
  size_t removed_points = 0;
};

struct CellModelOutcome {
  int found = 0;
  // Why the search of this model stopped: "" when its count was met, else
  // the message of the fit that was not an instance (or "at most N instances").
  std::string stopped;
  Pose T_world_base_rejected = Pose::Identity();  // that fit's base pose
  bool rejected = false;
  bool count_met = true;  // false when a count was asked and not reached
};

struct CellResult {
  std::vector<CellInstance> instances;  // in the order found
  std::vector<CellModelOutcome> models;
  size_t points = 0, background_points = 0;
  size_t roi_points = 0;      // in CellOptions::roi_world (when given)
  size_t mixed_pixels = 0;    // removed before the edges
  double edge_seconds = 0.0;  // the one edge detection
  double seconds = 0.0;       // in all
};

// The order the models are looked for in: those whose base is found by its
// cross sections (robots) before those found by their arm tips (conveyance
// systems), each group in the order given. A conveyor looked for first took
// the robots' tips for its own (the bar cell: not found) or, found, took a
// robot's gun beside it as its attached parts (the ABB then not counted).
std::vector<size_t> SearchOrder(const std::vector<CellModel>& models);

// Whether a fit is an instance of its model: the base body ok and no body a
// mismatch.
bool IsInstance(const FitResult& fit);

// `scans` becomes the background: every found instance's points removed.
// Fails (Status) where Fit() fails, and on a region that holds no point.
Status FitCell(const std::vector<CellModel>& models, const CellOptions& options,
               const ProgressFn& progress, ScanSet* scans, CellResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_CELL_FIT_H_
