// Weighted ICP engine (solvers/registration/weighted_icp.h) on the ~5 M point virtual scan
// of the bundled robot (bundled_robot_scan.h: posture "home", 3 scanners,
// 1 mm noise) with the edge detector's weights:
//   - one ICP iteration (visibility test, lattice correspondences, one Ceres
//     solve, and the closing quality search) for 20 k CAD samples of link_2,
//     free 6-DoF / joint-space / 6-DoF with Eq. (10) penalties;
//   - each main joint fitted alone (parent at the truth, start 2 degrees
//     off, 3 mm samples) with the two joint parameterisations; counters give
//     the joint errors [deg] and the mean time per joint.
//   build/benchmarks/icp_benchmark --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bundled_robot_scan.h"
#include "edgefit/core/angles.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/registration/weighted_icp.h"

namespace edgefit {
namespace {

#ifndef EDGEFIT_SOURCE_DIR
#define EDGEFIT_SOURCE_DIR "."
#endif

struct Fixture {
  BundledRobotScan robot;
  EdgeDetectionResult edges;
  std::vector<Pose> T_world_link;  // truth
};

Fixture& GetFixture() {
  static Fixture* fixture = [] {
    auto* f = new Fixture;
    f->robot = ScanBundledRobot();
    CHECK(DetectEdges(f->robot.scans, EdgeDetectionOptions(), &f->edges).ok());
    f->T_world_link = f->robot.model.ForwardKinematics(f->robot.q);
    LOG(INFO) << "scan: " << f->robot.scans.TotalValid() << " valid points, "
              << f->edges.edge_points << " edge points";
    return f;
  }();
  return *fixture;
}

// Every k-th sample so that about `count` remain (normals kept).
SurfaceSamples Thin(const SurfaceSamples& all, size_t count) {
  const size_t stride = std::max<size_t>(1, all.size() / count);
  SurfaceSamples out;
  for (size_t i = 0; i < all.size(); i += stride) {
    out.points.push_back(all.points[i]);
    out.normals.push_back(all.normals[i]);
  }
  return out;
}

// Arg 0: free 6-DoF; 1: joint space; 2: 6-DoF + Eq. (10) penalties.
void BM_IcpIteration(benchmark::State& state) {
  Fixture& f = GetFixture();
  const KinematicModel& model = f.robot.model;
  const int joint = model.JointIndex("joint_2");
  const int link = model.joints()[static_cast<size_t>(joint)].child_link;
  SamplingOptions sampling;
  sampling.spacing = 0.002;
  const SurfaceSamples samples =
      Thin(SampleModelSurfaces(model, sampling)[static_cast<size_t>(link)], 20000);
  const Joint& j = model.joints()[static_cast<size_t>(joint)];
  const LinkMotion motion =
      state.range(0) == 0
          ? LinkMotion::Free()
          : LinkMotion::FromJoint(j, f.T_world_link[static_cast<size_t>(j.parent_link)]);
  WeightedIcpOptions options;
  options.max_iterations = 1;
  ResidualOptions residuals;
  residuals.parameterization = state.range(0) == 2 ? JointParameterization::kPoseWithPenalties
                                                   : JointParameterization::kJointSpace;
  CorrespondenceSearch search(&f.robot.scans, &f.edges.w_edge);
  WeightedIcp icp(&f.robot.scans, &search, nullptr, residuals);
  WeightedIcpSummary summary;
  for (auto _ : state) {
    LinkState s;
    s.q = f.robot.q[static_cast<size_t>(joint)] + 1.0 * kDeg;
    s.T_world_link = motion.constrained() ? motion.PoseAt(s.q)
                                          : f.T_world_link[static_cast<size_t>(link)] *
                                                PoseFromXyzRpy({0.002, 0.0, 0.0}, {0.0, 0.0, 0.01});
    CHECK(icp.Fit(samples, motion, options, &s, &summary).ok());
  }
  state.counters["samples"] = static_cast<double>(samples.size());
  state.counters["visible"] = static_cast<double>(summary.visible_points);
  state.SetLabel(state.range(0) == 0   ? "free 6-DoF"
                 : state.range(0) == 1 ? "joint_space"
                                       : "pose_penalty");
}
BENCHMARK(BM_IcpIteration)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Arg 0: joint space; 1: 6-DoF + Eq. (10) penalties + projection.
void BM_FitMainJoints(benchmark::State& state) {
  Fixture& f = GetFixture();
  const KinematicModel& model = f.robot.model;
  SamplingOptions sampling;
  sampling.spacing = 0.003;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);
  WeightedIcpOptions options;
  ResidualOptions residuals;
  residuals.parameterization = state.range(0) == 0 ? JointParameterization::kJointSpace
                                                   : JointParameterization::kPoseWithPenalties;
  options.correspondence.max_distance = 0.03;
  options.max_iterations = 60;
  CorrespondenceSearch search(&f.robot.scans, &f.edges.w_edge);
  WeightedIcp icp(&f.robot.scans, &search, nullptr, residuals);
  std::vector<double> errors;
  std::vector<double> joint_error(model.joints().size(), 0.0);  // mean of the two starts
  int iterations = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    errors.clear();
    iterations = 0;
    seconds = 0.0;
    for (const int joint : model.IndependentJoints()) {
      const Joint& j = model.joints()[static_cast<size_t>(joint)];
      const LinkMotion motion =
          LinkMotion::FromJoint(j, f.T_world_link[static_cast<size_t>(j.parent_link)]);
      const double q_true = f.robot.q[static_cast<size_t>(joint)];
      for (const double offset : {-2.0 * kDeg, 2.0 * kDeg}) {
        LinkState s;
        s.q = q_true + offset;
        WeightedIcpSummary summary;
        CHECK(icp.Fit(samples[static_cast<size_t>(j.child_link)], motion, options, &s, &summary)
                  .ok());
        errors.push_back(std::abs(s.q - q_true) / kDeg);
        joint_error[static_cast<size_t>(joint)] += 0.5 * errors.back();
        iterations += summary.iterations;
        seconds += summary.seconds;
      }
    }
  }
  double sum = 0.0;
  for (const double e : errors) sum += e;
  state.counters["fits"] = static_cast<double>(errors.size());
  for (const int joint : model.IndependentJoints()) {
    state.counters["err_" + model.joints()[static_cast<size_t>(joint)].name] =
        joint_error[static_cast<size_t>(joint)];
  }
  state.counters["mean_err_deg"] = sum / static_cast<double>(errors.size());
  state.counters["max_err_deg"] = *std::max_element(errors.begin(), errors.end());
  state.counters["iter_per_fit"] = iterations / static_cast<double>(errors.size());
  state.counters["s_per_fit"] = seconds / static_cast<double>(errors.size());
  state.SetLabel(state.range(0) == 0 ? "joint_space" : "pose_penalty");
}
BENCHMARK(BM_FitMainJoints)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace edgefit

BENCHMARK_MAIN();
