// How far a point lies from the fitted model's surface: a kd-tree over the
// posed model's surface samples (the report's colours and histograms).
#ifndef EDGEFIT_REPORT_MODEL_DISTANCE_H_
#define EDGEFIT_REPORT_MODEL_DISTANCE_H_

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "edgefit/core/point_kdtree.h"
#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

class ModelDistance {
 public:
  // The model at (q, T_world_base), sampled every `spacing` [m]; points are
  // given relative to `origin` (world) in Distance.
  ModelDistance(const KinematicModel& model, const std::vector<double>& q,
                const Pose& T_world_base, double spacing, uint64_t seed,
                const Eigen::Vector3d& origin);
  ModelDistance(const ModelDistance&) = delete;
  ModelDistance& operator=(const ModelDistance&) = delete;

  bool empty() const { return samples_.empty(); }
  // Distance [m] from p (world minus origin) to the nearest sample, and its
  // link (model.links() order). Thread-safe.
  double Distance(const Eigen::Vector3f& p, int* link) const;

 private:
  std::vector<Eigen::Vector3f> samples_;  // world minus origin
  std::vector<uint16_t> link_of_;
  PointVectorAdaptor adaptor_{&samples_};
  std::unique_ptr<PointKdTree> tree_;
};

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_MODEL_DISTANCE_H_
