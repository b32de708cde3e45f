// Edge-weighted robust loss of the 1-DoF rough sweep, paper Eq. (9)
// (Sec. 5.2.1 revolute, reused by Sec. 6.2.1 prismatic):
//
//   Loss_i = D / w_edge    if D <  tau_dist   (inlier: edges count more),
//   Loss_i = D * w_edge    if D >= tau_dist   (outlier: high-weight points
//                                              far from the scan cost more)
//
// D [m]: distance from the transformed source point to its nearest scan point;
// w_edge > 0: the target's edge weight of Eq. (6) (dimensionless);
// tau_dist [m]: inlier threshold. Returns Loss_i [m]; the sweep sums it over
// points and keeps the step with the smallest total. Not a ceres::LossFunction:
// it is evaluated directly, never differentiated.
#ifndef EDGEFIT_COSTS_SWEEP_LOSS_H_
#define EDGEFIT_COSTS_SWEEP_LOSS_H_

#include <glog/logging.h>

namespace edgefit {

inline double SweepLoss(double distance, double w_edge, double tau_dist) {
  DCHECK_GT(w_edge, 0.0) << "Eq. (9) divides by the edge weight";
  return distance < tau_dist ? distance / w_edge : distance * w_edge;
}

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_SWEEP_LOSS_H_
