#include "model_distance.h"

#include <cmath>
#include <limits>

#include "edgefit/model/surface_sampler.h"

namespace edgefit {

ModelDistance::ModelDistance(const KinematicModel& model, const std::vector<double>& q,
                             const Pose& T_world_base, double spacing, uint64_t seed,
                             const Eigen::Vector3d& origin) {
  SamplingOptions sampling;
  sampling.spacing = spacing;
  sampling.seed = seed;
  const std::vector<SurfaceSamples> link_samples = SampleModelSurfaces(model, sampling);
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  for (size_t l = 0; l < link_samples.size(); ++l) {
    for (const Eigen::Vector3f& p : link_samples[l].points) {
      samples_.push_back((T_world_link[l] * p.cast<double>() - origin).cast<float>());
      link_of_.push_back(static_cast<uint16_t>(l));
    }
  }
  if (!samples_.empty()) {
    tree_ = std::make_unique<PointKdTree>(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  }
}

double ModelDistance::Distance(const Eigen::Vector3f& p, int* link) const {
  uint32_t nearest = 0;
  float d2 = 0.0f;
  if (tree_ == nullptr || tree_->knnSearch(p.data(), 1, &nearest, &d2) == 0) {
    if (link != nullptr) *link = -1;
    return std::numeric_limits<double>::infinity();
  }
  if (link != nullptr) *link = link_of_[nearest];
  return std::sqrt(static_cast<double>(d2));
}

}  // namespace edgefit
