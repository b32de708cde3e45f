#include "edgefit/scanner/random_joints.h"

#include <cmath>

#include "counter_rng.h"
#include "edgefit/core/angles.h"

namespace edgefit {

std::vector<double> RandomJointValues(const KinematicModel& model, uint64_t seed) {
  constexpr int kMaxDraws = 64;
  SplitMix64 rng(seed);
  const std::vector<int> independent = model.IndependentJoints();
  std::vector<double> q;
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    q = model.ZeroJoints();
    for (int j : independent) {
      const Joint& joint = model.joints()[j];
      const bool bounded = joint.type != JointType::kContinuous && joint.has_limits &&
                           joint.upper >= joint.lower;
      const double lo = bounded ? joint.lower : -kPi;
      const double hi = bounded ? joint.upper : kPi;
      q[j] = rng.Uniform(lo, hi);
    }
    if (model.ResolveDependentJoints(&q).ok()) break;
  }
  return q;
}

bool RandomJointValuesAboveFloor(const KinematicModel& model, const Pose& T_world_base,
                                 double floor_z, uint64_t seed, std::vector<double>* q,
                                 double tolerance, int max_draws) {
  SplitMix64 seeds(seed);
  for (int draw = 0; draw < max_draws; ++draw) {
    *q = RandomJointValues(model, draw == 0 ? seed : seeds.Next());
    const Eigen::AlignedBox3d box = model.BoundingBox(*q, T_world_base);
    if (box.isEmpty() || box.min().z() >= floor_z - tolerance) return true;
  }
  return false;
}

}  // namespace edgefit
