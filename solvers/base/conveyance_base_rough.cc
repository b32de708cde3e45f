#include "solvers/base/conveyance_base_rough.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "edgefit/core/split_mix64.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/base/base_rough.h"
#include "solvers/base/model_tips.h"

namespace edgefit {

bool ConveyanceBaseRoughOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!(cell > 0.0) || !(model_spacing > 0.0)) return fail("cell and model_spacing must be > 0");
  if (!tips.IsValid(error) || !scan_support.IsValid(error) || !symmetry.IsValid(error)) {
    return false;
  }
  if (!(min_tip_height >= 0.0) || !(match_tolerance >= 0.0)) {
    return fail("min_tip_height and match_tolerance must be >= 0");
  }
  if (!(along_step > 0.0) || !(fine_step > 0.0) || candidates < 1) {
    return fail("along_step and fine_step must be > 0, candidates >= 1");
  }
  return true;
}

namespace {

// One way of laying the model's axis onto a scan axis, and the stretch of
// the scan axis where the base can be: the base's model axis point lies at
// o + s d + r n (o, d: scan axis point and direction, n its normal).
struct Placement {
  int scan_axis = 0, model_axis = 0;
  double flip = 1.0;  // the model's axis direction onto +d or -d
  Interval s, r;
  int support = 0;  // matched scan pairs
};

Pose PlacementPose(const SymmetryAxis& scan_axis, const SymmetryAxis& model_axis, double flip,
                   double s, double r, double z) {
  const Eigen::Vector2d d = flip * scan_axis.direction;
  const double yaw =
      std::atan2(d.y(), d.x()) - std::atan2(model_axis.direction.y(), model_axis.direction.x());
  const Eigen::Rotation2Dd R(yaw);
  const Eigen::Vector2d n(-scan_axis.direction.y(), scan_axis.direction.x());
  const Eigen::Vector2d origin =
      scan_axis.point + s * scan_axis.direction + r * n - R * model_axis.point;
  Pose T = Pose::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(origin.x(), origin.y(), z);
  return T;
}

// The stretches of s where the most scan pairs agree. Each match (scan pair
// k, a model pair) allows an s interval and an r interval.
struct Match {
  int scan_pair = 0;
  Interval s, r;
};

std::vector<Placement> MostSupported(const std::vector<Match>& matches, int scan_axis,
                                     int model_axis, double flip) {
  std::vector<double> ends;
  for (const Match& m : matches) {
    ends.push_back(m.s.lo);
    ends.push_back(m.s.hi);
  }
  std::sort(ends.begin(), ends.end());
  std::vector<Placement> placements;
  int best = 0;
  for (size_t k = 0; k + 1 < ends.size(); ++k) {
    if (!(ends[k + 1] > ends[k])) continue;
    const double mid = 0.5 * (ends[k] + ends[k + 1]);
    std::vector<int> pairs;
    Interval r_hull, r_common;
    r_common.lo = -std::numeric_limits<double>::infinity();
    r_common.hi = std::numeric_limits<double>::infinity();
    for (const Match& m : matches) {
      if (!m.s.Contains(mid, 0.0)) continue;
      if (std::find(pairs.begin(), pairs.end(), m.scan_pair) == pairs.end()) {
        pairs.push_back(m.scan_pair);
      }
      r_hull.Extend(m.r.lo);
      r_hull.Extend(m.r.hi);
      r_common.lo = std::max(r_common.lo, m.r.lo);
      r_common.hi = std::min(r_common.hi, m.r.hi);
    }
    const int support = static_cast<int>(pairs.size());
    if (support == 0 || support < best) continue;
    if (support > best) placements.clear();
    best = support;
    Placement p;
    p.scan_axis = scan_axis;
    p.model_axis = model_axis;
    p.flip = flip;
    p.s.lo = ends[k];
    p.s.hi = ends[k + 1];
    p.r = r_common.lo <= r_common.hi ? r_common : r_hull;
    p.support = support;
    placements.push_back(p);
  }
  return placements;
}

// Values from lo to hi at about `step` (both ends; the middle of a short one).
std::vector<double> Steps(const Interval& range, double step) {
  const double length = range.hi - range.lo;
  if (!(length > step)) return {0.5 * (range.lo + range.hi)};
  const int n = static_cast<int>(std::ceil(length / step));
  std::vector<double> values;
  for (int k = 0; k <= n; ++k) values.push_back(range.lo + length * k / n);
  return values;
}

}  // namespace

Status FitConveyanceBaseRough(const ScanSet& scans, double floor_z, const KinematicModel& model,
                              const TriangleMesh& base_mesh_link,
                              const ConveyanceBaseRoughOptions& options, const BasePoseLoss& loss,
                              ConveyanceBaseRoughResult* result) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("conveyance base rough: " + error);
  if (base_mesh_link.vertices.empty()) {
    return Status::Error("conveyance base rough: the base link has no mesh");
  }
  *result = ConveyanceBaseRoughResult();
  result->floor_z = floor_z;
  double bottom = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& v : base_mesh_link.vertices) bottom = std::min(bottom, v.z());
  const double base_z = result->floor_z - bottom;

  // CAD tips (base frame) and their pairs' ranges.
  const std::vector<double> q0 = ReferenceJoints(model);
  std::vector<ModelTip> model_tips;
  EDGEFIT_RETURN_IF_ERROR(FindModelTips(model, q0, options, bottom, &model_tips));
  std::vector<Eigen::Vector3d> model_points;
  for (const ModelTip& t : model_tips) model_points.push_back(t.p_base);
  result->model_tips = model_points;
  const std::vector<SymmetryAxis> model_axes = FindSymmetryAxes(model_points, options.symmetry);
  if (model_axes.empty()) {
    return Status::Error("conveyance base rough: the model has no symmetric pair among its " +
                         std::to_string(model_tips.size()) + " convex tips (arm tips)");
  }
  std::vector<std::vector<ModelTipPair>> model_pairs(model_axes.size());
  for (size_t m = 0; m < model_axes.size(); ++m) {
    for (const auto& [a, b] : model_axes[m].pairs) {
      model_pairs[m].push_back(RangeOfPair(model, q0, model_tips[static_cast<size_t>(a)],
                                           model_tips[static_cast<size_t>(b)], model_axes[m],
                                           options.symmetry.seed));
    }
  }

  // Scan tips (world frame): the corroborated height map of the points
  // above the floor, and of its convex tips those at a height one of the
  // CAD pairs can take (no other can match one).
  const double min_z = result->floor_z + options.min_tip_height;
  std::vector<Eigen::Vector3d> high;
  std::vector<float> areas;  // spacing^2 at each point's range
  Eigen::AlignedBox2d extent;
  for (const OrganizedScan& scan : scans.scans) {
    const double step = std::max(std::abs(scan.lattice().row_step()),
                                 std::abs(scan.lattice().col_step()));
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i)) continue;
      const Eigen::Vector3d p = scan.PointWorld(i);
      if (p.z() < min_z || (!options.roi_world.isEmpty() && !options.roi_world.contains(p))) {
        continue;
      }
      high.push_back(p);
      areas.push_back(static_cast<float>(std::pow(step * scan.point_scanner(i).norm(), 2)));
      extent.extend(p.head<2>());
    }
  }
  HeightMap scan_map;
  EDGEFIT_RETURN_IF_ERROR(HeightMap::Create(extent, options.cell, &scan_map));
  scan_map.AddCorroborated(high, areas, options.scan_support);
  high = std::vector<Eigen::Vector3d>();
  areas = std::vector<float>();
  auto in_reach = [&](double height) {
    for (const std::vector<ModelTipPair>& pairs : model_pairs) {
      for (const ModelTipPair& pair : pairs) {
        if (pair.height.Contains(height, options.match_tolerance)) return true;
      }
    }
    return false;
  };
  for (const HeightMap::Tip& tip : scan_map.ConvexTips(options.tips)) {
    ++result->convex_scan_tips;
    if (in_reach(tip.p.z() - base_z)) result->scan_tips.push_back(tip.p);
  }
  const std::vector<SymmetryAxis> scan_axes = FindSymmetryAxes(result->scan_tips, options.symmetry);
  if (scan_axes.empty()) {
    return Status::Error("conveyance base rough: no symmetric pair among the scan's " +
                         std::to_string(result->scan_tips.size()) +
                         " convex tips at the heights of the model's (of " +
                         std::to_string(result->convex_scan_tips) + ")");
  }
  result->symmetric_scan_tips = 2 * static_cast<int>(scan_axes.front().pairs.size());

  // Matches and the placements they support.
  const double tol = options.match_tolerance;
  std::vector<Placement> placements;
  for (size_t sa = 0; sa < scan_axes.size(); ++sa) {
    const SymmetryAxis& axis = scan_axes[sa];
    const Eigen::Vector2d n(-axis.direction.y(), axis.direction.x());
    // The pairs of every axis parallel to this one (clamps opened unequally
    // shift their pair's axis sideways; its midpoint still constrains the
    // base along the axis).
    std::vector<std::pair<int, int>> pairs;
    for (const SymmetryAxis& other : scan_axes) {
      if (std::abs(other.direction.dot(axis.direction)) < std::cos(options.symmetry.distinct_angle))
        continue;
      for (const auto& pair : other.pairs) {
        if (std::find(pairs.begin(), pairs.end(), pair) == pairs.end()) pairs.push_back(pair);
      }
    }
    for (size_t m = 0; m < model_axes.size(); ++m) {
      for (const double flip : {1.0, -1.0}) {
        std::vector<Match> matches;
        for (size_t k = 0; k < pairs.size(); ++k) {
          const Eigen::Vector3d& a = result->scan_tips[static_cast<size_t>(pairs[k].first)];
          const Eigen::Vector3d& b = result->scan_tips[static_cast<size_t>(pairs[k].second)];
          const double width = (a - b).head<2>().norm();
          const Eigen::Vector2d mid = 0.5 * (a + b).head<2>() - axis.point;
          const double u = axis.direction.dot(mid), v = n.dot(mid);
          for (const ModelTipPair& pair : model_pairs[m]) {
            if (!pair.width.Contains(width, tol) || !pair.height.Contains(a.z() - base_z, tol) ||
                !pair.height.Contains(b.z() - base_z, tol)) {
              continue;
            }
            Match match;
            match.scan_pair = static_cast<int>(k);
            match.s.Extend(u - flip * pair.along.lo);
            match.s.Extend(u - flip * pair.along.hi);
            match.r.Extend(v - flip * pair.across.lo);
            match.r.Extend(v - flip * pair.across.hi);
            match.s.lo -= tol;  // the tips' own error; r is searched exactly
            match.s.hi += tol;
            matches.push_back(match);
          }
        }
        result->matches += static_cast<int>(matches.size());
        for (const Placement& p :
             MostSupported(matches, static_cast<int>(sa), static_cast<int>(m), flip)) {
          placements.push_back(p);
        }
      }
    }
  }
  if (placements.empty()) {
    char line[300];
    std::snprintf(line, sizeof(line),
                  "conveyance base rough: none of the scan's %zu symmetric tip pairs matches "
                  "one of the model's %zu (width and height)",
                  scan_axes.front().pairs.size(), model_axes.front().pairs.size());
    return Status::Error(line);
  }
  // Only the best-supported placements are searched.
  int best_support = 0;
  for (const Placement& p : placements) best_support = std::max(best_support, p.support);

  // The search along the axis: coarse, then fine around the best.
  struct Scored {
    size_t placement;
    double s, r, loss;
  };
  auto score_all = [&](std::vector<Scored>* poses) {
    const int n = static_cast<int>(poses->size());
#pragma omp parallel for schedule(dynamic, 4)
    for (int k = 0; k < n; ++k) {
      Scored& c = (*poses)[static_cast<size_t>(k)];
      const Placement& p = placements[c.placement];
      c.loss = loss(PlacementPose(scan_axes[static_cast<size_t>(p.scan_axis)],
                                  model_axes[static_cast<size_t>(p.model_axis)], p.flip, c.s, c.r,
                                  base_z));
    }
    result->scored += n;
  };
  auto by_loss = [](const Scored& a, const Scored& b) {
    return a.loss != b.loss ? a.loss < b.loss
                            : (a.placement != b.placement ? a.placement < b.placement : a.s < b.s);
  };
  std::vector<Scored> coarse;
  for (size_t k = 0; k < placements.size(); ++k) {
    if (placements[k].support < best_support) continue;
    for (const double s : Steps(placements[k].s, options.along_step)) {
      for (const double r : Steps(placements[k].r, options.along_step)) {
        coarse.push_back({k, s, r, 0.0});
      }
    }
  }
  score_all(&coarse);
  std::sort(coarse.begin(), coarse.end(), by_loss);
  std::vector<Scored> fine;
  std::vector<Scored> seeds;
  // Two poses are one candidate when they lay the same axes the same way
  // round within `near` along and across.
  auto distinct = [&](const Scored& c, const std::vector<Scored>& kept, double near) {
    for (const Scored& k : kept) {
      const Placement& a = placements[c.placement];
      const Placement& b = placements[k.placement];
      if (a.scan_axis == b.scan_axis && a.model_axis == b.model_axis && a.flip == b.flip &&
          std::abs(c.s - k.s) <= near && std::abs(c.r - k.r) <= near) {
        return false;
      }
    }
    return true;
  };
  for (const Scored& c : coarse) {
    if (!distinct(c, seeds, 2.0 * options.along_step)) continue;
    seeds.push_back(c);
    Interval around;
    around.lo = c.s - options.along_step;
    around.hi = c.s + options.along_step;
    for (const double s : Steps(around, options.fine_step))
      fine.push_back({c.placement, s, c.r, 0.0});
    if (static_cast<int>(seeds.size()) == options.candidates) break;
  }
  score_all(&fine);
  std::sort(fine.begin(), fine.end(), by_loss);
  std::vector<Scored> kept;
  for (const Scored& c : fine) {
    if (!distinct(c, kept, options.along_step)) continue;
    kept.push_back(c);
    const Placement& p = placements[c.placement];
    result->candidates.push_back(PlacementPose(scan_axes[static_cast<size_t>(p.scan_axis)],
                                               model_axes[static_cast<size_t>(p.model_axis)],
                                               p.flip, c.s, c.r, base_z));
    if (static_cast<int>(kept.size()) == options.candidates) break;
  }
  result->T_world_base = result->candidates.front();
  result->loss = kept.front().loss;
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
