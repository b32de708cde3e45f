// Robust loss factory: ceres::LossFunction by name, for the precise-stage
// data terms (Eqs. (8), (10), (14)) when outliers remain after the edge
// weighting. Ceres minimises 1/2 sum rho(|r|^2) with s = |r|^2.
//
// `scale` is always in units of the residual norm (metres * sqrt(weight) for
// the costs/ data terms): the loss stays quadratic for |r| well below scale.
//   "trivial"  rho(s) = s                           (scale ignored)
//   "huber"    ceres::HuberLoss(scale)
//   "cauchy"   ceres::CauchyLoss(scale)
//   "soft_l1"  ceres::SoftLOneLoss(scale)
//   "arctan"   ceres::ArctanLoss(scale^2)  — Ceres' ArctanLoss takes its
//              level in units of s, hence the square: rho(s) = a atan(s / a),
//              a = scale^2
//   "tukey"    ceres::TukeyLoss(scale)
#ifndef EDGEFIT_COSTS_ROBUST_LOSS_H_
#define EDGEFIT_COSTS_ROBUST_LOSS_H_

#include <ceres/loss_function.h>

#include <memory>
#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {

// The valid names for MakeLoss, in the order listed above.
const std::vector<std::string>& LossNames();

// Sets *loss to a new loss function named `name` with the given scale.
// "trivial" gives a ceres::TrivialLoss (never null, so rho can always be
// evaluated). The caller owns *loss; to hand it to a ceres::Problem (which
// takes ownership by default) pass loss.release() — or share one loss across
// residual blocks with Problem::Options::loss_function_ownership =
// DO_NOT_TAKE_OWNERSHIP and keep the unique_ptr alive.
// Errors: unknown name (message lists LossNames()), or scale not finite and
// positive for a non-trivial loss; *loss is left unchanged on error.
Status MakeLoss(const std::string& name, double scale, std::unique_ptr<ceres::LossFunction>* loss);

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_ROBUST_LOSS_H_
