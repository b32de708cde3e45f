#include "solvers/base/base_rough.h"

#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "edgefit/core/split_mix64.h"
#include "solvers/base/point_grid2.h"

namespace edgefit {

bool BaseRoughOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (height_fractions.empty()) return fail("no section heights");
  for (const double f : height_fractions) {
    if (!(f >= 0.0 && f <= 1.0)) return fail("section height fractions must be in [0, 1]");
  }
  if (!(max_edge > 0.0) || !(model_spacing > 0.0))
    return fail("max_edge and model_spacing must be > 0");
  if (!(corners.radius > 0.0) || !(corners.separation >= 0.0)) return fail("bad corner options");
  if (iterations < 1) return fail("iterations must be >= 1");
  if (!(pair_tolerance > 0.0) || !(inlier_distance > 0.0)) return fail("tolerances must be > 0");
  if (score_points_per_section < 1) return fail("score_points_per_section must be >= 1");
  if (candidates < 1) return fail("candidates must be >= 1");
  if (!(single_corner_below_share >= 0.0) || !(single_corner_yaw_step > 0.0) ||
      single_corner_rescored < 1) {
    return fail("bad single-corner search options");
  }
  if (!(noise_reference > 0.0) || !(max_noise_scale >= 1.0) || !(noise_level_ratio > 1.0)) {
    return fail("noise_reference must be > 0, max_noise_scale >= 1, noise_level_ratio > 1");
  }
  return true;
}

double BaseRoughOptions::NoiseScale(double sigma) const {
  return std::isfinite(sigma) ? std::clamp(sigma / noise_reference, 1.0, max_noise_scale) : 1.0;
}

BaseRoughOptions BaseRoughOptions::ScaledToNoise(double sigma) const {
  BaseRoughOptions scaled = *this;
  const double k = NoiseScale(sigma);
  if (!(k > 1.0)) return scaled;
  scaled.corners.radius *= k;
  scaled.corners.separation *= k;
  scaled.pair_tolerance *= k;
  scaled.inlier_distance *= k;
  return scaled;
}

std::vector<double> BaseRoughOptions::NoiseLevels(const ScanNoise& noise) const {
  std::vector<double> levels = {noise.median_sigma};
  std::vector<double> bins;
  for (const double sigma : noise.sigma) {
    if (std::isfinite(sigma)) bins.push_back(sigma);
  }
  std::sort(bins.begin(), bins.end());
  for (const double sigma : bins) {
    const double k = NoiseScale(sigma);
    const bool apart = std::all_of(levels.begin(), levels.end(), [&](double kept) {
      const double ratio = k / NoiseScale(kept);
      return ratio > noise_level_ratio || ratio < 1.0 / noise_level_ratio;
    });
    if (apart) levels.push_back(sigma);
  }
  return levels;
}

namespace {

struct ModelPair {
  int a = 0, b = 0;  // indices into the section's corner list
  double length = 0.0;
};

// 2D rigid motion (yaw, t) mapping model a->scan a, with the direction of
// model b-a onto scan b-a.
Eigen::Isometry2d Hypothesis(const Eigen::Vector2d& ma, const Eigen::Vector2d& mb,
                             const Eigen::Vector2d& sa, const Eigen::Vector2d& sb) {
  const Eigen::Vector2d dm = mb - ma, ds = sb - sa;
  const double yaw = std::atan2(ds.y(), ds.x()) - std::atan2(dm.y(), dm.x());
  Eigen::Isometry2d T = Eigen::Isometry2d::Identity();
  T.linear() = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  // Midpoints match (halves the effect of corner noise).
  T.translation() = 0.5 * (sa + sb) - T.linear() * (0.5 * (ma + mb));
  return T;
}

}  // namespace

Status FitBaseRough(const ScanSet& scans, double floor_z, const TriangleMesh& base_mesh_link,
                    const BaseRoughOptions& options, BaseRoughResult* result) {
  CHECK(result != nullptr);
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("base rough registration: " + error);
  if (base_mesh_link.empty())
    return Status::Error("base rough registration: the base link has no mesh");
  *result = BaseRoughResult();

  result->floor_z = floor_z;

  const Eigen::AlignedBox3d box_link = base_mesh_link.BoundingBox();
  const double bottom = box_link.min().z(), height = box_link.sizes().z();
  std::vector<double> heights_model, heights_world;  // model: link frame; world: above the floor
  for (const double f : options.height_fractions) {
    const double h = std::max(options.min_height, f * height);
    if (h >= height) continue;
    heights_model.push_back(bottom + h);
    heights_world.push_back(floor_z + h);
  }
  if (heights_model.empty())
    return Status::Error("base rough registration: the base mesh is too flat");

  // Scan sections, limited to a margin around the floor-standing base when
  // an ROI is given; else the whole scan at those heights.
  const std::vector<Section> scan_sections =
      ScanSections(scans, heights_world, options.max_edge, options.roi_world);
  const std::vector<Section> model_sections =
      MeshSections(base_mesh_link, heights_model, options.model_spacing);

  const size_t H = heights_model.size();
  std::vector<std::vector<int>> scan_corners(H), model_corners(H);
  std::vector<std::vector<ModelPair>> model_pairs(H);
  double model_diameter = 0.0;
  for (size_t k = 0; k < H; ++k) {
    scan_corners[k] = SectionCorners(scan_sections[k], options.corners);
    model_corners[k] = SectionCorners(model_sections[k], options.corners);
    result->scan_corners += static_cast<int>(scan_corners[k].size());
    result->model_corners += static_cast<int>(model_corners[k].size());
    const std::vector<Eigen::Vector2d>& mp = model_sections[k].points;
    for (size_t i = 0; i < model_corners[k].size(); ++i) {
      for (size_t j = i + 1; j < model_corners[k].size(); ++j) {
        const double length = (mp[static_cast<size_t>(model_corners[k][j])] -
                               mp[static_cast<size_t>(model_corners[k][i])])
                                  .norm();
        model_diameter = std::max(model_diameter, length);
        if (length >= options.min_pair_length) {
          model_pairs[k].push_back({static_cast<int>(i), static_cast<int>(j), length});
        }
      }
    }
    std::sort(model_pairs[k].begin(), model_pairs[k].end(),
              [](const ModelPair& a, const ModelPair& b) { return a.length < b.length; });
  }
  if (result->model_corners < 1) {
    return Status::Error("base rough registration: the base mesh's sections have no corners");
  }
  if (result->scan_corners < 1) {
    return Status::Error(
        "base rough registration: no corners in the scan's cross-sections "
        "(is the robot in the scan?)");
  }

  // Scoring sets: model section points (a deterministic stride per height),
  // scan occupancy grids.
  std::vector<std::vector<Eigen::Vector2d>> score_points(H);
  size_t score_total = 0;
  std::vector<PointGrid2> occupancy;  // scan section points, per height
  occupancy.reserve(H);
  for (size_t k = 0; k < H; ++k) {
    const std::vector<Eigen::Vector2d>& mp = model_sections[k].points;
    const size_t stride =
        std::max<size_t>(1, mp.size() / static_cast<size_t>(options.score_points_per_section));
    for (size_t i = 0; i < mp.size(); i += stride) score_points[k].push_back(mp[i]);
    score_total += score_points[k].size();
    occupancy.emplace_back(scan_sections[k].points, options.inlier_distance);
  }
  // Every `stride`-th scoring point (1: all) that lands on the scan.
  auto score = [&](const Eigen::Isometry2d& T, size_t stride = 1) {
    size_t inliers = 0;
    for (size_t k = 0; k < H; ++k) {
      for (size_t j = 0; j < score_points[k].size(); j += stride) {
        inliers += occupancy[k].AnyWithin(T * score_points[k][j], options.inlier_distance);
      }
    }
    return inliers;
  };

  // Heights with scan corner pairs to draw from (none: the single-corner
  // search below).
  std::vector<size_t> drawable;
  for (size_t k = 0; k < H; ++k) {
    if (scan_corners[k].size() >= 2 && !model_pairs[k].empty()) drawable.push_back(k);
  }
  SplitMix64 rng(SplitMix64::StreamSeed(options.seed, 0xba5e));
  // The best distinct hypotheses, best first.
  std::vector<std::pair<size_t, Eigen::Isometry2d>> best;
  auto keep = [&best, &options](size_t inliers, const Eigen::Isometry2d& T) {
    if (inliers == 0) return;
    for (size_t i = 0; i < best.size(); ++i) {
      const Eigen::Isometry2d delta = best[i].second.inverse() * T;
      const double yaw = std::abs(std::atan2(delta.linear()(1, 0), delta.linear()(0, 0)));
      if (yaw < 3.0 * M_PI / 180.0 &&
          (best[i].second.translation() - T.translation()).norm() < 0.02) {
        if (inliers > best[i].first) {  // a better version of a kept one
          best.erase(best.begin() + static_cast<std::ptrdiff_t>(i));
          break;
        }
        return;
      }
    }
    auto at = std::find_if(best.begin(), best.end(),
                           [inliers](const auto& b) { return inliers > b.first; });
    best.insert(at, {inliers, T});
    if (best.size() > static_cast<size_t>(options.candidates)) best.pop_back();
  };
  // The hypotheses are drawn in order, scored in parallel, then kept in
  // order: the same result for any thread count.
  std::vector<Eigen::Isometry2d> hypotheses;
  for (int it = 0; !drawable.empty() && it < options.iterations; ++it) {
    const size_t k = drawable[static_cast<size_t>(rng.Next() % drawable.size())];
    const std::vector<int>& sc = scan_corners[k];
    const size_t i = static_cast<size_t>(rng.Next() % sc.size());
    size_t j = static_cast<size_t>(rng.Next() % (sc.size() - 1));
    if (j >= i) ++j;
    const Eigen::Vector2d& sa = scan_sections[k].points[static_cast<size_t>(sc[i])];
    const Eigen::Vector2d& sb = scan_sections[k].points[static_cast<size_t>(sc[j])];
    const double length = (sb - sa).norm();
    if (length < options.min_pair_length || length > model_diameter + options.pair_tolerance)
      continue;
    const std::vector<ModelPair>& pairs = model_pairs[k];
    auto lo = std::lower_bound(pairs.begin(), pairs.end(), length - options.pair_tolerance,
                               [](const ModelPair& p, double v) { return p.length < v; });
    const std::vector<Eigen::Vector2d>& mp = model_sections[k].points;
    for (; lo != pairs.end() && lo->length <= length + options.pair_tolerance; ++lo) {
      const Eigen::Vector2d& ma =
          mp[static_cast<size_t>(model_corners[k][static_cast<size_t>(lo->a)])];
      const Eigen::Vector2d& mb =
          mp[static_cast<size_t>(model_corners[k][static_cast<size_t>(lo->b)])];
      hypotheses.push_back(Hypothesis(ma, mb, sa, sb));
      hypotheses.push_back(Hypothesis(mb, ma, sa, sb));
    }
  }
  std::vector<size_t> inliers(hypotheses.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (std::ptrdiff_t h = 0; h < static_cast<std::ptrdiff_t>(hypotheses.size()); ++h) {
    inliers[static_cast<size_t>(h)] = score(hypotheses[static_cast<size_t>(h)]);
  }
  for (size_t h = 0; h < hypotheses.size(); ++h) keep(inliers[h], hypotheses[h]);
  result->hypotheses += static_cast<int>(hypotheses.size());
  // Few corners (a round base with one or two per section): one hidden
  // leaves no pair. Then every scan corner is matched to every model corner
  // at its height, the yaw on a grid; a sparse score ranks them, the best
  // are scored in full.
  const size_t pair_best = best.empty() ? 0 : best.front().first;
  if (static_cast<double>(pair_best) <
      options.single_corner_below_share * static_cast<double>(score_total)) {
    struct Single {
      size_t sparse = 0;
      Eigen::Isometry2d T;
    };
    std::vector<Single> singles;
    const int yaw_steps =
        std::max(1, static_cast<int>(std::lround(2.0 * M_PI / options.single_corner_yaw_step)));
    for (size_t k = 0; k < H; ++k) {
      for (const int sc : scan_corners[k]) {
        for (const int mc : model_corners[k]) {
          for (int step = 0; step < yaw_steps; ++step) {
            Eigen::Isometry2d T = Eigen::Isometry2d::Identity();
            T.linear() = Eigen::Rotation2Dd(2.0 * M_PI * step / yaw_steps).toRotationMatrix();
            T.translation() = scan_sections[k].points[static_cast<size_t>(sc)] -
                              T.linear() * model_sections[k].points[static_cast<size_t>(mc)];
            singles.push_back({0, T});
          }
        }
      }
    }
    constexpr size_t kSparseStride = 8;
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(singles.size()); ++i) {
      Single& single = singles[static_cast<size_t>(i)];
      single.sparse = score(single.T, kSparseStride);
    }
    std::stable_sort(singles.begin(), singles.end(),
                     [](const Single& a, const Single& b) { return a.sparse > b.sparse; });
    const size_t scored =
        std::min(singles.size(), static_cast<size_t>(options.single_corner_rescored));
    for (size_t i = 0; i < scored; ++i) keep(score(singles[i].T), singles[i].T);
    result->hypotheses += static_cast<int>(singles.size());
  }
  if (best.empty()) {
    char detail[160];
    std::snprintf(detail, sizeof(detail),
                  " (floor at z = %.3f m, %d scan and %d model corners, %d hypotheses)", floor_z,
                  result->scan_corners, result->model_corners, result->hypotheses);
    return Status::Error(
        "base rough registration: no corner match puts the base on the scan "
        "(is the robot in the scan?)" +
        std::string(detail));
  }
  result->inlier_share = static_cast<double>(best.front().first) / static_cast<double>(score_total);
  for (const auto& [inliers, T2] : best) {
    Pose T = Pose::Identity();
    const double yaw = std::atan2(T2.linear()(1, 0), T2.linear()(0, 0));
    T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(T2.translation().x(), T2.translation().y(), floor_z - bottom);
    result->candidates.push_back(T);
  }
  result->T_world_base = result->candidates.front();
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
