// Coverings (an extension of the paper): protective jackets, covers and
// dress packs that follow a link's surface a few millimetres off it. The
// scanner sees them instead of the link, and a fit that takes their points
// for the link's leans outwards (the bundled robot at weld_low, every
// realistic effect and jackets: joint_4 0.31 deg and joint_6 0.50 deg off
// without this and the stations' registration, 0.037 and 0.031 deg with).
// They are found where the points lie outside the fitted CAD surface,
// consistently over an area:
//
//   - every visible CAD sample of every link (front-facing to the scanner of
//     its match) is matched to its nearest cell within `gate` in each scan
//     (with the lattice; the kd-tree: over all scans); each cell keeps the
//     signed distance s = n . (p - q) along the CAD normal of its closest
//     sample (positive: outside the surface);
//   - a matched cell is a covering when the median of s over the matched
//     cells of its (2 window + 1)^2 lattice block exceeds area_offset, or
//     its own s exceeds point_offset;
//   - a cell whose closest sample is on a link a prismatic joint slides
//     (a weld gun's electrode) is never a covering: at a wrong slide value
//     the part of the link beyond the CAD's end lies off the CAD over an
//     area as a covering would, and taking it for one let the wrong value
//     fit the rest (the bundled gun's jaw 41 and 51 mm off on two realistic
//     scenes, right within 0.06 and 0.22 mm without it);
//   - a cell no sample matched (the samples are sparser than the scan)
//     takes the verdict of the nearest matched cell in its block within
//     `gate` of it, so that a fit whose samples move finds no unmarked
//     covering next to a marked one.
// On a 3 mm scan of the bundled robot with jackets, at the true pose
// (tests/solvers/coverings_test.cc): recall 0.934 of the jacket cells,
// 0.316 when only the nearest cell over all scans was judged.
//
// The whole-chain refinement then gives those cells weight 0 and runs
// again; `rounds` times, each from the last estimate, so a covering the
// first estimate leaned into shows fully once the link is back on its
// uncovered surface. A bulge of the as-built surface beyond area_offset
// counts too: fewer points, no bias.
#ifndef EDGEFIT_SOLVERS_REFINEMENT_COVERINGS_H_
#define EDGEFIT_SOLVERS_REFINEMENT_COVERINGS_H_

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/correspondence/correspondence_search.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct CoveringOptions {
  // Find coverings and refine without them, `rounds` times (0: never).
  int rounds = 2;
  double gate = 0.012;          // [m] CAD sample to scan point
  int window = 3;               // [cells] half-size of the lattice block
  double area_offset = 0.002;   // [m] median outside distance of a covering's block
  double point_offset = 0.004;  // [m] outside distance of a lone point
  // When coverings hide at least this share of some link's matched cells,
  // the chain is fitted again (sweeps and ICP, from the base) on the scan
  // without them: a jacket over most of a forearm can move a joint's sweep
  // into another basin, which no refinement leaves. On the bundled robot
  // with accessories but no jacket the largest share was 0.08, with jackets
  // on the upper arm and forearm 0.58 and 0.63.
  double refit_share = 0.2;
  // A revolute joint that the fit without the coverings puts more than this
  // away from the fit with them [rad] changed basin (a wrist flipped half a
  // turn): the two are compared on the scan without the coverings, and
  // unless the fit without them is clearly better the joint is ambiguous
  // (not ok; the pipeline's MarkBasinChanges).
  double basin_change = 5.0 * M_PI / 180.0;

  bool IsValid(std::string* error) const;
};


struct CoveringSummary {
  size_t matched = 0;  // cells matched to a CAD sample
  size_t covered = 0;  // of those, coverings
  // Per link (model.links() order): cells whose closest sample is on it,
  // and how many of those are coverings.
  std::vector<size_t> link_matched, link_covered;

  // The covered share of link l's matched cells (0 when none matched).
  double Share(size_t l) const {
    return link_matched[l] == 0
               ? 0.0
               : static_cast<double>(link_covered[l]) / static_cast<double>(link_matched[l]);
  }
  // Per link, 1 where more than `share` of its matched cells are covered.
  std::vector<uint8_t> LinksCoveredOver(double share) const {
    std::vector<uint8_t> over(link_matched.size(), 0);
    for (size_t l = 0; l < over.size(); ++l) over[l] = Share(l) > share;
    return over;
  }
};

// Does some link have at least refit_share of its matched cells covered?
bool CoveringsHideALink(const CoveringSummary& summary, const CoveringOptions& options);

// Finds the coverings of the model at (T_world_base, q). link_samples: per
// link (model.links() order, link frame, with normals; empty links are
// skipped). search: over `scans`, without a mask; use_lattice as the
// refinement's correspondences. An unorganized scan has no lattice block:
// its cells are judged by their own distance.
Status FindCoverings(const KinematicModel& model, const ScanSet& scans,
                     CorrespondenceSearch* search, const std::vector<SurfaceSamples>& link_samples,
                     const Pose& T_world_base, const std::vector<double>& q,
                     const CoveringOptions& options, bool use_lattice, CellMask* covered,
                     CoveringSummary* summary);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REFINEMENT_COVERINGS_H_
