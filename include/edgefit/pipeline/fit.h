// Fits a kinematic model (a KinematicModel, end effectors attached) of an
// articulated robot or a conveyance system to a scan: the paper's pipeline.
//   Sec. 4    edges and their weights on the scan lattice (with edge
//             weighting; the default uniform weighting needs none);
//   Sec. 5.1  the base: rough poses (5.1.1 cross sections, or 6.1 arm tips),
//             then the precise weighted ICP (5.1.2);
//   Sec. 5.2  every joint, parents first: the Eq. (9) sweep, then the
//             joint-constrained weighted ICP; 5.3 end effectors alike;
//   extensions for real scans: mixed pixels removed first (optional), every
//   station registered to the fitted model (station residuals), the whole
//   chain refined at once without the coverings found on it (jackets,
//   covers), and, when a station moved or a covering hides much of a link,
//   the chain fitted again from the base on the aligned stations without
//   the coverings; every joint's basin checked at the final values (a joint
//   whose body another value fits better is fitted from there with the
//   joints below it, the better branch taken and the chain refined again)
//   and whether the scan pins each joint there; the covariance, and the
//   verdict of each body against the scan.
// A "body" is the link moved by a joint together with every link fixed to
// it (fixed joints, attached end effectors): they move as one.
#ifndef EDGEFIT_PIPELINE_FIT_H_
#define EDGEFIT_PIPELINE_FIT_H_

#include <functional>
#include <string>

#include "edgefit/core/status.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/pipeline/fit_options.h"
#include "edgefit/pipeline/fit_result.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// Progress lines ("base: rough ...") for long steps; may be empty.
using ProgressFn = std::function<void(const std::string&)>;

// Fails (Status) on invalid options, a model without a base mesh or a scan
// the stages cannot work on; a fit that runs but does not match the scan
// returns Ok with result->ok = false and a message.
Status Fit(const KinematicModel& model, const ScanSet& scans, const FitOptions& options,
           const ProgressFn& progress, FitResult* result);

// Fit() after its first steps: the same pipeline on `scans` whose edges
// (Sec. 4: normals and weights) were detected before, e.g. once for the
// scans of a whole cell (cell_fit.h) from which instances were removed
// since (their cells are missing now, so their normals are not read).
// With uniform weights `edges` may be empty (Fit() detects none then).
// Mixed pixels are not removed here; timings.edges stays 0.
Status FitWithEdges(const KinematicModel& model, const ScanSet& scans,
                    const EdgeDetectionResult& edges, const FitOptions& options,
                    const ProgressFn& progress, FitResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_FIT_H_
