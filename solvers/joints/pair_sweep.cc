#include "solvers/joints/pair_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>

namespace edgefit {

int BendBelow(const KinematicModel& model, int joint, const std::vector<int>& links,
              const std::vector<double>& q) {
  const std::vector<Pose> T_root_link = model.ForwardKinematics(q);
  const Joint& j = model.joints()[static_cast<size_t>(joint)];
  const Eigen::Vector3d axis =
      T_root_link[static_cast<size_t>(j.child_link)].linear() * j.axis.normalized();
  for (const int c : model.joint_order()) {
    const Joint& child = model.joints()[static_cast<size_t>(c)];
    if (!child.IsIndependent() ||
        std::find(links.begin(), links.end(), child.parent_link) == links.end()) {
      continue;
    }
    if (child.type != JointType::kRevolute && child.type != JointType::kContinuous) return -1;
    const Eigen::Vector3d child_axis =
        T_root_link[static_cast<size_t>(child.child_link)].linear() * child.axis.normalized();
    return std::abs(axis.dot(child_axis)) < std::cos(30.0 * M_PI / 180.0) ? c : -1;
  }
  return -1;
}

Status SweepPair(const KinematicModel& model, const JointSweep& sweep,
                 const JointSweepOptions& options, const Pose& T_world_base,
                 const std::vector<double>& q, const Body& body, int bend,
                 const std::vector<SurfaceSamples>& link_samples, int max_samples, double step,
                 PairSweepSummary* summary) {
  const auto start = std::chrono::steady_clock::now();
  if (!(step > 0.0)) return Status::Error("pair sweep: the step must be positive");
  const int joint = body.joint, child_joint = bend;
  const Joint& j = model.joints()[static_cast<size_t>(joint)];
  const Joint& c = model.joints()[static_cast<size_t>(child_joint)];
  SurfaceSamples body_samples, child_samples;
  AppendBodySamples(body, link_samples, Pose::Identity(), &body_samples);
  AppendBodySamples(MakeBody(model, c.child_link, child_joint), link_samples, Pose::Identity(),
                    &child_samples);
  ThinSamples(max_samples, &body_samples);
  ThinSamples(max_samples, &child_samples);
  if (body_samples.points.empty() && child_samples.points.empty()) {
    return Status::Error("pair sweep: the bodies have no CAD samples");
  }
  // The coarse grid on a quarter of the samples: it only has to find the
  // basin, and it holds most of the evaluations.
  SurfaceSamples coarse_body = body_samples, coarse_child = child_samples;
  ThinSamples(std::max(1, max_samples / 4), &coarse_body);
  ThinSamples(std::max(1, max_samples / 4), &coarse_child);
  *summary = PairSweepSummary();
  double lower, upper, child_lower, child_upper;
  SweptRange(LinkMotion::FromJoint(j, Pose::Identity()), &lower, &upper);
  SweptRange(LinkMotion::FromJoint(c, Pose::Identity()), &child_lower, &child_upper);
  const size_t body_link = static_cast<size_t>(j.child_link);
  const size_t child_link = static_cast<size_t>(c.child_link);
  // Both bodies' loss at a pair of values, the other joints at q.
  auto loss_at = [&](const SurfaceSamples& body_samples, const SurfaceSamples& child_samples,
                     double a, double b) {
    std::vector<double> values = q;
    values[static_cast<size_t>(joint)] = a;
    values[static_cast<size_t>(child_joint)] = b;
    (void)model.ResolveDependentJoints(&values);
    const std::vector<Pose> T_world_link = model.ForwardKinematics(values, T_world_base);
    return sweep.LossAt(body_samples, T_world_link[body_link], options) +
           sweep.LossAt(child_samples, T_world_link[child_link], options);
  };
  // The best of a grid, scored in parallel; ties to the first in grid order.
  auto best_of = [&](const SurfaceSamples& body_samples, const SurfaceSamples& child_samples,
                     const std::vector<double>& as, const std::vector<double>& bs) {
    const int64_t n = static_cast<int64_t>(as.size() * bs.size());
    std::vector<double> losses(static_cast<size_t>(n));
#pragma omp parallel for schedule(dynamic, 4)
    for (int64_t k = 0; k < n; ++k) {
      const size_t i = static_cast<size_t>(k) / bs.size(), m = static_cast<size_t>(k) % bs.size();
      losses[static_cast<size_t>(k)] = loss_at(body_samples, child_samples, as[i], bs[m]);
    }
    summary->evaluations += static_cast<int>(n);
    const size_t best =
        static_cast<size_t>(std::min_element(losses.begin(), losses.end()) - losses.begin());
    summary->loss = losses[best];
    summary->q = as[best / bs.size()];
    summary->q_child = bs[best % bs.size()];
  };
  best_of(coarse_body, coarse_child, SweepValues(lower, upper, step),
          SweepValues(child_lower, child_upper, step));
  for (int refinement = 0; refinement < 2; ++refinement) {
    const double fine = step / 5.0;
    best_of(
        body_samples, child_samples,
        SweepValues(std::max(lower, summary->q - step), std::min(upper, summary->q + step), fine),
        SweepValues(std::max(child_lower, summary->q_child - step),
                    std::min(child_upper, summary->q_child + step), fine));
    step = fine;
  }
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
