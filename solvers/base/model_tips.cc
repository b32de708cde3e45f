#include "solvers/base/model_tips.h"

#include <algorithm>

#include "edgefit/core/split_mix64.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/base/height_map.h"

namespace edgefit {

std::vector<double> ReferenceJoints(const KinematicModel& model) {
  std::vector<double> q = model.ZeroJoints();
  for (size_t k = 0; k < q.size(); ++k) {
    const Joint& j = model.joints()[k];
    if (j.IsIndependent() && j.has_limits) q[k] = std::min(std::max(q[k], j.lower), j.upper);
  }
  (void)model.ResolveDependentJoints(&q);
  return q;
}

Status FindModelTips(const KinematicModel& model, const std::vector<double>& q0,
                     const ConveyanceBaseRoughOptions& options, double bottom,
                     std::vector<ModelTip>* tips) {
  SamplingOptions sampling;
  sampling.spacing = options.model_spacing;
  sampling.seed = options.symmetry.seed;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);
  const std::vector<Pose> T_base_link = model.ForwardKinematics(q0, Pose::Identity());
  std::vector<ModelTip> points;  // every sample and vertex
  for (size_t l = 0; l < model.links().size(); ++l) {
    auto add = [&](const Eigen::Vector3d& p_link) {
      ModelTip t;
      t.link = static_cast<int>(l);
      t.p_link = p_link;
      t.p_base = T_base_link[l] * p_link;
      if (t.p_base.z() >= bottom + options.min_tip_height) points.push_back(t);
    };
    for (const Eigen::Vector3f& p : samples[l].points) add(p.cast<double>());
    for (const Eigen::Vector3d& v : model.links()[l].mesh.vertices) add(v);
  }
  Eigen::AlignedBox2d extent;
  for (const ModelTip& t : points) extent.extend(t.p_base.head<2>());
  HeightMap map;
  EDGEFIT_RETURN_IF_ERROR(HeightMap::Create(extent, options.cell, &map));
  for (size_t k = 0; k < points.size(); ++k) map.Add(points[k].p_base, static_cast<int>(k));
  tips->clear();
  for (const HeightMap::Tip& tip : map.ConvexTips(options.tips)) {
    tips->push_back(points[static_cast<size_t>(tip.source)]);
  }
  return Status::Ok();
}

ModelTipPair RangeOfPair(const KinematicModel& model, const std::vector<double>& q0,
                         const ModelTip& a, const ModelTip& b, const SymmetryAxis& axis,
                         uint64_t seed) {
  std::vector<int> joints;
  for (const int link : {a.link, b.link}) {
    for (int l = link; model.links()[static_cast<size_t>(l)].parent_joint >= 0;) {
      const int j = model.links()[static_cast<size_t>(l)].parent_joint;
      const Joint& joint = model.joints()[static_cast<size_t>(j)];
      if (joint.IsIndependent() && joint.has_limits &&
          std::find(joints.begin(), joints.end(), j) == joints.end()) {
        joints.push_back(j);
      }
      l = joint.parent_link;
    }
  }
  const Eigen::Vector2d normal(-axis.direction.y(), axis.direction.x());
  ModelTipPair range;
  const bool all_corners = joints.size() <= 10;
  const size_t corners = all_corners ? size_t{1} << joints.size() : 1024;
  SplitMix64 random(seed);
  for (size_t corner = 0; corner < corners; ++corner) {
    std::vector<double> q = q0;
    for (size_t k = 0; k < joints.size(); ++k) {
      const Joint& joint = model.joints()[static_cast<size_t>(joints[k])];
      const bool upper = all_corners ? ((corner >> k) & 1) != 0 : (random.Next() & 1) != 0;
      q[static_cast<size_t>(joints[k])] = upper ? joint.upper : joint.lower;
    }
    (void)model.ResolveDependentJoints(&q);
    const std::vector<Pose> T = model.ForwardKinematics(q, Pose::Identity());
    const Eigen::Vector3d pa = T[static_cast<size_t>(a.link)] * a.p_link;
    const Eigen::Vector3d pb = T[static_cast<size_t>(b.link)] * b.p_link;
    const Eigen::Vector2d mid = 0.5 * (pa + pb).head<2>() - axis.point;
    range.width.Extend((pa - pb).head<2>().norm());
    range.height.Extend(pa.z());
    range.height.Extend(pb.z());
    range.along.Extend(axis.direction.dot(mid));
    range.across.Extend(normal.dot(mid));
  }
  return range;
}

}  // namespace edgefit
