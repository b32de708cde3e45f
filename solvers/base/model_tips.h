// The arm tips of the CAD model (Sec. 6.1): the convex tips of the model's
// height map at a reference posture, and what a symmetric pair of them can
// look like over the ranges of the joints that carry them. Internal to
// conveyance_base_rough.cc.
#ifndef EDGEFIT_SOLVERS_BASE_MODEL_TIPS_H_
#define EDGEFIT_SOLVERS_BASE_MODEL_TIPS_H_

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "solvers/base/conveyance_base_rough.h"
#include "solvers/base/symmetry_axis.h"

namespace edgefit {

struct Interval {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Extend(double x) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  bool Contains(double x, double slack) const { return x >= lo - slack && x <= hi + slack; }
};

// A tip of the model: the link it is on and where.
struct ModelTip {
  int link = -1;
  Eigen::Vector3d p_link = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_base = Eigen::Vector3d::Zero();  // at q0
};

// What a symmetric pair of model tips can look like over its joints'
// ranges, in the coordinates of the model's axis (point c, direction e).
struct ModelTipPair {
  Interval width, height, along, across;  // midpoint along / across the axis
};

// The model's posture the CAD tips are taken at: every independent joint at
// zero, or at its nearest limit.
std::vector<double> ReferenceJoints(const KinematicModel& model);

// The model's convex tips at q0 (base frame) at least options.min_tip_height
// above `bottom` [m].
Status FindModelTips(const KinematicModel& model, const std::vector<double>& q0,
                     const ConveyanceBaseRoughOptions& options, double bottom,
                     std::vector<ModelTip>* tips);

// The ranges of a model pair over the corners of the ranges of the
// independent joints between the base and its two links (exact for chains
// of prismatic joints; 1024 seeded corners when there are more than 10).
ModelTipPair RangeOfPair(const KinematicModel& model, const std::vector<double>& q0,
                         const ModelTip& a, const ModelTip& b, const SymmetryAxis& axis,
                         uint64_t seed);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_MODEL_TIPS_H_
