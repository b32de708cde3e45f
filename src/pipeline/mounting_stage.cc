// Any mounting (BaseOptions::Mounting): the base's rough poses voted on
// oriented point pairs (stages.h, solvers/base/pose_voting.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "solvers/base/base_hypotheses.h"
#include "solvers/base/pose_voting.h"
#include "solvers/base/pose_evidence.h"
#include "stages.h"

namespace edgefit {
namespace {

// The first independent joint, parents first, whose parent link is one of
// `links`; -1 when none.
int FirstJointBelow(const KinematicModel& model, const std::vector<int>& links) {
  for (const int j : model.joint_order()) {
    const Joint& joint = model.joints()[static_cast<size_t>(j)];
    if (joint.IsIndependent() &&
        std::find(links.begin(), links.end(), joint.parent_link) != links.end()) {
      return j;
    }
  }
  return -1;
}

// Appends the samples of `body`'s links at the links' poses in the base frame.
void AppendPosed(const Body& body, const std::vector<Pose>& T_base_link,
                 const std::vector<SurfaceSamples>& link_samples, SurfaceSamples* out) {
  for (const int link : body.links) {
    const Pose& T = T_base_link[static_cast<size_t>(link)];
    const SurfaceSamples& s = link_samples[static_cast<size_t>(link)];
    for (size_t i = 0; i < s.size(); ++i) {
      out->points.push_back((T * s.points[i].cast<double>()).cast<float>());
      out->normals.push_back((T.linear() * s.normals[i].cast<double>()).cast<float>());
    }
  }
}

// The bodies voted for, in the base frame: the base body with the body of
// the first joint below it (at zero: a round base turned is the same base,
// so the first joint's zero loses nothing there) and of the second (at
// options.base.voting_joint_values values over its range); the base alone
// when the model has no such joints. A round base alone matches every
// cylinder of a room; with its first links the shape is the robot's own.
std::vector<SurfaceSamples> VotingBodies(const KinematicModel& model, const Body& base,
                                         const CadSamples& cad, const FitOptions& options) {
  const int max_samples = options.samples.max_icp_samples;
  const int j1 = FirstJointBelow(model, base.links);
  if (j1 < 0) return {BodySamples(base, cad.icp, max_samples)};
  const Body first = MakeBody(model, model.joints()[static_cast<size_t>(j1)].child_link, j1);
  const int j2 = FirstJointBelow(model, first.links);
  std::vector<double> values = {0.0};
  if (j2 >= 0) {
    const Joint& joint = model.joints()[static_cast<size_t>(j2)];
    const int n = options.base.voting_joint_values;
    const double lower = joint.has_limits ? joint.lower : -M_PI;
    const double upper = joint.has_limits ? joint.upper : M_PI;
    values.clear();
    for (int k = 0; k < n; ++k) values.push_back(lower + (k + 0.5) * (upper - lower) / n);
  }
  std::vector<SurfaceSamples> bodies;
  for (const double value : values) {
    std::vector<double> q = model.ZeroJoints();
    q[static_cast<size_t>(j1)] = std::clamp(0.0, model.joints()[static_cast<size_t>(j1)].lower,
                                            model.joints()[static_cast<size_t>(j1)].upper);
    if (j2 >= 0) q[static_cast<size_t>(j2)] = value;
    (void)model.ResolveDependentJoints(&q);  // a closure not met still places the links
    const std::vector<Pose> T_base_link = model.ForwardKinematics(q);
    SurfaceSamples body = BodySamples(base, cad.icp, max_samples);
    AppendPosed(first, T_base_link, cad.icp, &body);
    if (j2 >= 0) {
      AppendPosed(MakeBody(model, model.joints()[static_cast<size_t>(j2)].child_link, j2),
                  T_base_link, cad.icp, &body);
    }
    ThinSamples(max_samples, &body);
    bodies.push_back(std::move(body));
  }
  return bodies;
}

struct ScoredPose {
  Pose T_world_base = Pose::Identity();
  double evidence = 0.0;  // PoseEvidence::Share of the voted body
  double loss = 0.0;      // Eq. (9) per sample of the voted body
};

}  // namespace

Status VoteBasePoses(const KinematicModel& model, const ScanSet& scans, const Body& base,
                     const CadSamples& cad, const FitOptions& options, ScanTools* tools,
                     const ProgressFn& say, std::vector<RoughPose>* roughs) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SurfaceSamples> bodies = VotingBodies(model, base, cad, options);
  const double voxel = VotingVoxel(bodies, options.base.voting);
  const OrientedCloud scene = VotingScene(scans, voxel, options.base.voting);
  WeightedIcpOptions register_vote = options.base.icp;
  register_vote.correspondence.max_distance = std::max(2.0 * voxel, options.noise.gate);
  register_vote.final_gate = options.noise.gate;
  register_vote.max_iterations = options.base.voted_icp_iterations;
  register_vote.point_to_plane = true;
  // Ranked by their evidence (pose_evidence.h): inliers within the sweep's
  // tau_dist, seen and hidden at the noise gate (a centimetre of noise puts
  // the right pose's surface beyond 1 cm behind or in front of the scan's);
  // ties by the Eq. (9) loss with tau_dist at the gate.
  const double inlier = options.chain.sweep.tau_dist;
  JointSweepOptions rank = options.chain.sweep;
  rank.tau_dist = rank.occluded_loss = rank.visibility_tolerance = options.noise.gate;
  rank.max_distance = std::max(rank.max_distance, options.noise.gate);
  std::vector<ScoredPose> scored;
  size_t voted_poses = 0;
  for (const SurfaceSamples& body : bodies) {
    std::vector<VotedPose> voted;
    PoseVotingSummary summary;
    const Status status = VoteModelPoses(scene, voxel, body, options.base.voting, &voted, &summary);
    if (!status.ok()) continue;  // this posture matched nothing
    SurfaceSamples few = body;
    ThinSamples(options.base.voted_icp_samples, &few);
    for (const VotedPose& v : voted) {
      LinkState state;
      state.T_world_link = v.T_world_model;
      WeightedIcpSummary registered;
      EDGEFIT_RETURN_IF_ERROR(
          tools->icp.Fit(few, LinkMotion::Free(), register_vote, &state, &registered));
      std::vector<float> losses;
      const double loss = tools->sweep.LossAt(few, state.T_world_link, rank, &losses);
      PoseEvidence evidence;
      evidence.Add(losses, inlier, rank.max_distance);
      scored.push_back(
          {state.T_world_link, evidence.Share(), loss / static_cast<double>(few.size())});
    }
    voted_poses += voted.size();
  }
  if (scored.empty()) return Status::Error("no pair of scan points matches the model's");
  std::stable_sort(scored.begin(), scored.end(), [](const ScoredPose& a, const ScoredPose& b) {
    return a.evidence != b.evidence ? a.evidence > b.evidence : a.loss < b.loss;
  });
  for (const ScoredPose& s : scored) {
    if (static_cast<int>(roughs->size()) >= options.base.voted_roughs) break;
    const bool distinct = std::all_of(roughs->begin(), roughs->end(), [&s](const RoughPose& r) {
      return IsDistinctPose(r.T_world_base, s.T_world_base);
    });
    if (distinct) roughs->push_back({s.T_world_base, /*registered=*/true});
  }
  char line[300];
  std::snprintf(line, sizeof(line),
                "base: any mounting: %zu poses voted for %zu postures of the base and its first "
                "links on %zu scan points (%.1f cm voxels), each registered; the best: "
                "evidence %.3f (inliers less free space), %.2f mm per sample (Eq. 9); %zu kept; "
                "%.2f s",
                voted_poses, bodies.size(), scene.size(), 100.0 * voxel, scored.front().evidence,
                1e3 * scored.front().loss, roughs->size(), Since(start));
  say(line);
  return Status::Ok();
}

}  // namespace edgefit
