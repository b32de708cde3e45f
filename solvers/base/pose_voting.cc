#include "solvers/base/pose_voting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include "edgefit/core/point_kdtree.h"

namespace edgefit {
namespace {

struct PairEntry {
  uint32_t model_point;
  float theta;  // of the second point about +x, after T_m [rad]
};

// Moves p (its normal n) to the origin with n along +x.
Eigen::Isometry3f ToReferenceFrame(const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
  const Eigen::Quaternionf q = Eigen::Quaternionf::FromTwoVectors(n, Eigen::Vector3f::UnitX());
  Eigen::Isometry3f T = Eigen::Isometry3f::Identity();
  T.linear() = q.toRotationMatrix();
  T.translation() = -(T.linear() * p);
  return T;
}

class PairFeatures {
 public:
  PairFeatures(double distance_step, int angle_bins)
      : distance_step_(static_cast<float>(distance_step)),
        angle_step_(static_cast<float>(2.0 * M_PI / angle_bins)) {}

  // The quantized feature of (p1, n1) -> (p2, n2); false for coincident
  // points and for two points of one plane (normals parallel, both across
  // d): every plane of the scene has them, they tell no pose, and on a
  // floor they are most of the pairs.
  bool Key(const Eigen::Vector3f& p1, const Eigen::Vector3f& n1, const Eigen::Vector3f& p2,
           const Eigen::Vector3f& n2, uint32_t* key) const {
    const Eigen::Vector3f d = p2 - p1;
    const float length = d.norm();
    if (!(length > 1e-9f)) return false;
    const Eigen::Vector3f u = d / length;
    constexpr float kCoplanar = 0.26f;  // sin 15 degrees
    if (std::abs(n1.dot(u)) < kCoplanar && std::abs(n2.dot(u)) < kCoplanar &&
        n1.dot(n2) > 1.0f - 0.5f * kCoplanar * kCoplanar) {
      return false;
    }
    auto bin = [this](float cosine) {
      return static_cast<uint32_t>(std::acos(std::clamp(cosine, -1.0f, 1.0f)) / angle_step_);
    };
    const uint32_t dist = static_cast<uint32_t>(length / distance_step_);
    *key = (std::min(dist, 1023u) << 18) | (bin(n1.dot(u)) << 12) | (bin(n2.dot(u)) << 6) |
           bin(n1.dot(n2));
    return true;
  }
  float angle_step() const { return angle_step_; }

 private:
  float distance_step_, angle_step_;
};

// theta of p after T (the angle of (y, z) about +x) [rad].
float Theta(const Eigen::Isometry3f& T, const Eigen::Vector3f& p) {
  const Eigen::Vector3f q = T * p;
  return std::atan2(q.z(), q.y());
}

// The voxels of `voxel` [m] the model's samples occupy.
size_t OccupiedVoxels(const SurfaceSamples& model, double voxel) {
  std::unordered_set<int64_t> keys;
  for (const Eigen::Vector3f& p : model.points) keys.insert(VoxelKey(p.cast<double>(), voxel));
  return keys.size();
}

// One sample per voxel of the model: the sample nearest the voxel centre.
void ThinModel(const SurfaceSamples& model, double voxel, std::vector<Eigen::Vector3f>* points,
               std::vector<Eigen::Vector3f>* normals) {
  std::unordered_map<int64_t, std::pair<float, size_t>> best;  // voxel -> (distance, sample)
  std::vector<int64_t> order;
  for (size_t i = 0; i < model.size(); ++i) {
    const int64_t key = VoxelKey(model.points[i].cast<double>(), voxel);
    const Eigen::Vector3f c = model.points[i] / static_cast<float>(voxel);
    const Eigen::Vector3f f(std::floor(c.x()), std::floor(c.y()), std::floor(c.z()));
    const float d = (c - f - Eigen::Vector3f::Constant(0.5f)).squaredNorm();
    auto it = best.find(key);
    if (it == best.end()) {
      best.emplace(key, std::make_pair(d, i));
      order.push_back(key);
    } else if (d < it->second.first) {
      it->second = {d, i};
    }
  }
  for (const int64_t key : order) {  // the samples' order: deterministic
    const size_t i = best[key].second;
    points->push_back(model.points[i]);
    normals->push_back(model.normals[i].normalized());
  }
}

// Greedy clustering of the references' poses, most votes first.
std::vector<VotedPose> Cluster(std::vector<VotedPose> candidates, double max_translation,
                               double max_rotation, int max_poses) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const VotedPose& a, const VotedPose& b) { return a.votes > b.votes; });
  std::vector<VotedPose> clusters;
  // |D.translation()| below is the distance between the two positions up
  // to rounding (1e-14 m here): farther than max_translation + 1 nm, the
  // pair fails its test without the product.
  const double reject_sq = (max_translation + 1e-9) * (max_translation + 1e-9);
  for (const VotedPose& c : candidates) {
    bool joined = false;
    for (VotedPose& cluster : clusters) {
      if ((cluster.T_world_model.translation() - c.T_world_model.translation()).squaredNorm() >
          reject_sq) {
        continue;
      }
      const Pose D = cluster.T_world_model.inverse() * c.T_world_model;
      if (D.translation().norm() <= max_translation &&
          Eigen::AngleAxisd(D.linear()).angle() <= max_rotation) {
        cluster.votes += c.votes;
        joined = true;
        break;
      }
    }
    if (!joined) clusters.push_back(c);
  }
  std::stable_sort(clusters.begin(), clusters.end(),
                   [](const VotedPose& a, const VotedPose& b) { return a.votes > b.votes; });
  if (static_cast<int>(clusters.size()) > max_poses) clusters.resize(static_cast<size_t>(max_poses));
  return clusters;
}

}  // namespace

bool PoseVotingOptions::IsValid(std::string* error) const {
  if (!(sampling_share > 0.0 && sampling_share < 1.0)) *error = "sampling_share must be in (0, 1)";
  else if (min_model_points < 3) *error = "min_model_points must be >= 3";
  else if (!(min_voxel > 0.0)) *error = "min_voxel must be > 0";
  else if (angle_bins < 4 || angle_bins > 63) *error = "angle_bins must be in [4, 63]";
  else if (reference_stride < 1) *error = "reference_stride must be >= 1";
  else if (max_references < 1) *error = "max_references must be >= 1";
  else if (!(normal_radius_voxels >= 1.0)) *error = "normal_radius_voxels must be >= 1";
  else if (max_poses < 1) *error = "max_poses must be >= 1";
  else return true;
  return false;
}

double VotingVoxel(const std::vector<SurfaceSamples>& bodies, const PoseVotingOptions& options) {
  double diameter = 0.0;
  for (const SurfaceSamples& body : bodies) diameter = std::max(diameter, SamplesDiameter(body));
  double voxel = std::max(options.min_voxel, options.sampling_share * diameter);
  // A surface's voxels grow as 1 / voxel^2: a few steps reach the count.
  for (int step = 0; step < 6 && voxel > options.min_voxel; ++step) {
    size_t fewest = SIZE_MAX;
    for (const SurfaceSamples& body : bodies) {
      fewest = std::min(fewest, OccupiedVoxels(body, voxel));
    }
    const double need = static_cast<double>(options.min_model_points);
    if (bodies.empty() || static_cast<double>(fewest) >= 0.95 * need) break;
    voxel = std::max(options.min_voxel,
                     voxel * std::sqrt(static_cast<double>(std::max<size_t>(fewest, 1)) / need));
  }
  return voxel;
}

OrientedCloud VotingScene(const ScanSet& scans, double voxel, const PoseVotingOptions& options) {
  OrientedCloudOptions cloud_options;
  cloud_options.voxel = voxel;
  cloud_options.normal_radius = options.normal_radius_voxels * voxel;
  cloud_options.roi_world = options.roi_world;
  return MakeOrientedCloud(scans, cloud_options);
}

double SamplesDiameter(const SurfaceSamples& samples) {
  Eigen::AlignedBox3f box;
  for (const Eigen::Vector3f& p : samples.points) box.extend(p);
  return samples.points.empty() ? 0.0 : static_cast<double>(box.sizes().norm());
}

Status VoteModelPoses(const OrientedCloud& scene, double voxel, const SurfaceSamples& model,
                      const PoseVotingOptions& options, std::vector<VotedPose>* poses,
                      PoseVotingSummary* summary) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("pose voting: " + error);
  poses->clear();
  *summary = PoseVotingSummary();
  if (model.size() < 3) return Status::Error("pose voting: the model has no surface");
  const double diameter = SamplesDiameter(model);
  summary->diameter = diameter;
  summary->voxel = voxel;

  std::vector<Eigen::Vector3f> m_points, m_normals;
  ThinModel(model, voxel, &m_points, &m_normals);
  const PairFeatures features(voxel, options.angle_bins);
  // The model's pairs, hashed by their feature.
  std::unordered_map<uint32_t, std::vector<PairEntry>> table;
  for (size_t i = 0; i < m_points.size(); ++i) {
    const Eigen::Isometry3f T_m = ToReferenceFrame(m_points[i], m_normals[i]);
    for (size_t j = 0; j < m_points.size(); ++j) {
      uint32_t key;
      if (i == j || !features.Key(m_points[i], m_normals[i], m_points[j], m_normals[j], &key)) {
        continue;
      }
      table[key].push_back({static_cast<uint32_t>(i), Theta(T_m, m_points[j])});
    }
  }

  summary->model_points = m_points.size();
  summary->scene_points = scene.size();
  if (m_points.size() < 3) return Status::Error("pose voting: the model has too few samples");
  if (scene.size() < 3) return Status::Error("pose voting: too few scan points with normals");

  PointVectorAdaptor adaptor{&scene.points};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  const float radius_sq = static_cast<float>(diameter * diameter);
  const int bins = options.angle_bins;
  const size_t stride =
      std::max({static_cast<size_t>(options.reference_stride),
                (scene.size() + static_cast<size_t>(options.max_references) - 1) /
                    static_cast<size_t>(options.max_references),
                size_t{1}});
  const int references = static_cast<int>((scene.size() + stride - 1) / stride);
  summary->references = static_cast<size_t>(references);
  std::vector<VotedPose> best(static_cast<size_t>(references));
#pragma omp parallel
  {
    std::vector<uint32_t> votes(m_points.size() * static_cast<size_t>(bins), 0);
    std::vector<size_t> touched;
    std::vector<std::pair<uint32_t, float>> found;
#pragma omp for schedule(dynamic, 16)
    for (int r = 0; r < references; ++r) {
      const size_t s = static_cast<size_t>(r) * stride;
      const Eigen::Vector3f& p = scene.points[s];
      const Eigen::Vector3f& n = scene.normals[s];
      const Eigen::Isometry3f T_s = ToReferenceFrame(p, n);
      found.clear();
      tree.radiusSearch(p.data(), radius_sq, found, nanoflann::SearchParams(32, 0.0f, false));
      std::sort(found.begin(), found.end());  // the tree's order is not the thread's business
      for (const auto& [i, distance_sq] : found) {
        uint32_t key;
        if (i == s || !features.Key(p, n, scene.points[i], scene.normals[i], &key)) continue;
        const auto entries = table.find(key);
        if (entries == table.end()) continue;
        const float theta_s = Theta(T_s, scene.points[i]);
        for (const PairEntry& e : entries->second) {
          float alpha = theta_s - e.theta;
          alpha -= static_cast<float>(2.0 * M_PI) * std::floor(alpha / static_cast<float>(2.0 * M_PI));
          const int a = std::min(bins - 1, static_cast<int>(alpha / features.angle_step()));
          const size_t cell = static_cast<size_t>(e.model_point) * static_cast<size_t>(bins) +
                              static_cast<size_t>(a);
          if (votes[cell]++ == 0) touched.push_back(cell);
        }
      }
      size_t top = 0;
      uint32_t top_votes = 0;
      for (const size_t cell : touched) {
        if (votes[cell] > top_votes || (votes[cell] == top_votes && cell < top)) {
          top = cell;
          top_votes = votes[cell];
        }
      }
      for (const size_t cell : touched) votes[cell] = 0;
      touched.clear();
      if (top_votes == 0) continue;
      const size_t m = top / static_cast<size_t>(bins);
      const float alpha = (static_cast<float>(top % static_cast<size_t>(bins)) + 0.5f) *
                          features.angle_step();
      const Eigen::Isometry3f T_m = ToReferenceFrame(m_points[m], m_normals[m]);
      const Eigen::Isometry3f T =
          T_s.inverse() * Eigen::AngleAxisf(alpha, Eigen::Vector3f::UnitX()) * T_m;
      VotedPose& b = best[static_cast<size_t>(r)];
      b.T_world_model = T.cast<double>();
      b.votes = top_votes;
    }
  }
  std::vector<VotedPose> candidates;
  for (const VotedPose& b : best) {
    if (b.votes > 0.0) candidates.push_back(b);
  }
  *poses = Cluster(std::move(candidates), options.cluster_translation_share * diameter,
                   options.cluster_rotation, options.max_poses);
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (poses->empty()) return Status::Error("pose voting: no pair of the scan matches the model's");
  return Status::Ok();
}

}  // namespace edgefit
