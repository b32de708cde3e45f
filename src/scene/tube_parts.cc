// Harness and hose centre lines over the posed links (accessory_parts.h).
#include <glog/logging.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "accessory_parts.h"
#include "edgefit/core/angles.h"
#include "edgefit/scene/tube_mesh.h"

namespace edgefit {
namespace scene_internal {
namespace {

constexpr double kCurveStep = 0.02;  // [m] centre-line resolution

// The segment a cable follows along a link [m, world]: from the joint into
// the link to the joint to the next chain link, or for the last link (or
// coincident joints) the principal axis of the link's surface samples.
struct LinkRun {
  Eigen::Vector3d a, u;  // start and unit direction
  double length = 0.0;
};

LinkRun PrincipalRun(const SurfaceCloud& cloud, const Eigen::Vector3d& from) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : cloud.p_world) mean += p;
  mean /= static_cast<double>(cloud.p_world.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : cloud.p_world) scatter += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  Eigen::Vector3d u = solver.eigenvectors().col(2);
  // Run away from the parent joint.
  if (u.dot(mean - from) < 0) u = -u;
  double lo = 0, hi = 0;
  for (const Eigen::Vector3d& p : cloud.p_world) {
    lo = std::min(lo, (p - mean).dot(u));
    hi = std::max(hi, (p - mean).dot(u));
  }
  return {mean + lo * u, u, hi - lo};
}

LinkRun MakeRun(const PartContext& context, int chain_index) {
  const int link = context.chain[chain_index];
  const SurfaceCloud& cloud = context.clearance->LinkCloud(link);
  const Eigen::Vector3d a = (*context.T_world_link)[link].translation();
  if (chain_index + 1 < static_cast<int>(context.chain.size())) {
    const Eigen::Vector3d b = (*context.T_world_link)[context.chain[chain_index + 1]].translation();
    if ((b - a).norm() > 0.1) return {a, (b - a).normalized(), (b - a).norm()};
  }
  return PrincipalRun(cloud, a);
}

// The unit direction perpendicular to u closest to the preferred one.
Eigen::Vector3d SideDirection(const Eigen::Vector3d& u, const Eigen::Vector3d& preferred) {
  const Eigen::Vector3d s = preferred - preferred.dot(u) * u;
  return s.norm() > 0.1 ? Eigen::Vector3d(s.normalized()) : u.unitOrthogonal();
}

// Cable points along one link. Stations are spread over the fractions
// [t0, t1] of the part of the run the link's surface actually covers (a
// link frame can sit far from its mesh). At each station the slab
// |t' - t| <= half_width of surface samples gives the point: the outermost
// sample along s, lifted by `lift` [m]. Beyond that level the slab holds no
// link surface, so the cable cannot cut the link there.
std::vector<Eigen::Vector3d> RunPoints(const SurfaceCloud& cloud, const LinkRun& run,
                                       const Eigen::Vector3d& s, double t0, double t1,
                                       int stations, double lift) {
  std::vector<Eigen::Vector3d> points;
  if (cloud.p_world.empty()) return points;
  double lo = 1e9, hi = -1e9;
  for (const Eigen::Vector3d& p : cloud.p_world) {
    lo = std::min(lo, (p - run.a).dot(run.u));
    hi = std::max(hi, (p - run.a).dot(run.u));
  }
  if (std::min(hi, run.length) > std::max(lo, 0.0)) {
    lo = std::max(lo, 0.0);
    hi = std::min(hi, run.length);
  }
  const double covered = hi - lo;
  const double spacing = stations > 1 ? (t1 - t0) * covered / (stations - 1) : covered;
  const double half_width = std::max(0.6 * spacing, 0.04);
  for (int i = 0; i < stations; ++i) {
    const double f = stations > 1 ? t0 + (t1 - t0) * i / (stations - 1) : 0.5 * (t0 + t1);
    const double t = lo + f * covered;
    // The outermost sample in the slab: the cable rests on the link there.
    double height = -1e9;
    Eigen::Vector3d outermost = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : cloud.p_world) {
      if (std::abs((p - run.a).dot(run.u) - t) <= half_width && p.dot(s) > height) {
        height = p.dot(s);
        outermost = p;
      }
    }
    if (height == -1e9) continue;
    points.push_back(outermost + lift * s);
  }
  return points;
}

// Resamples, then alternately pushes the centre line out to `wanted`
// clearance and relaxes it (Laplacian smoothing, ends fixed), finishing with
// a push so the result keeps the clearance.
std::vector<Eigen::Vector3d> FitCenterline(const PartContext& context,
                                           const std::vector<Eigen::Vector3d>& control,
                                           double wanted) {
  std::vector<Eigen::Vector3d> curve = CatmullRomCurve(control, kCurveStep);
  for (int round = 0; round < 4; ++round) {
    for (Eigen::Vector3d& p : curve) p = context.clearance->PushOut(p, wanted);
    if (round == 3) break;
    std::vector<Eigen::Vector3d> smooth = curve;
    for (size_t i = 1; i + 1 < curve.size(); ++i) {
      smooth[i] = 0.5 * curve[i] + 0.25 * (curve[i - 1] + curve[i + 1]);
    }
    curve.swap(smooth);
  }
  return curve;
}

}  // namespace

bool BuildHarness(const PartContext& context, int first, int last, SplitMix64* rng,
                  TriangleMesh* mesh, double* radius, std::vector<int>* links,
                  std::vector<ClampSite>* clamps) {
  CHECK_LT(first, last);
  const AccessoryOptions& options = *context.options;
  *radius = rng->Uniform(options.harness_radius_min, options.harness_radius_max);
  const double lift = *radius + options.clearance + 0.002;
  // Preferred side: a seeded azimuth in the root frame, tilted up, so that
  // like a dress pack the harness runs over the top and sides of the arm.
  const double azimuth = rng->Uniform(-kPi, kPi);
  const Pose& T_world_root = (*context.T_world_link)[context.model->root_link()];
  const Eigen::Vector3d preferred =
      T_world_root.linear() *
      Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), rng->Uniform(0.3, 1.0)).normalized();
  const Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();

  std::vector<Eigen::Vector3d> control;
  std::vector<ClampSite> sites;
  links->clear();
  for (int i = first; i <= last; ++i) {
    const int link = context.chain[i];
    const LinkRun run = MakeRun(context, i);
    const Eigen::Vector3d s = SideDirection(run.u, preferred);
    const int stations =
        run.length < 0.15 ? 1 : std::max(2, static_cast<int>(std::ceil(0.7 * run.length / 0.2)) + 1);
    std::vector<Eigen::Vector3d> points =
        RunPoints(context.clearance->LinkCloud(link), run, s, 0.15, 0.85, stations, lift);
    // Continue from where the cable is: a link whose frame sits at its far
    // end (a forearm hung from the wrist joint) is run backwards.
    if (!control.empty() && !points.empty() &&
        (points.front() - control.back()).norm() > (points.back() - control.back()).norm()) {
      std::reverse(points.begin(), points.end());
    }
    VLOG(2) << "harness run link " << link << " a " << run.a.transpose() << " u "
            << run.u.transpose() << " length " << run.length << " side " << s.transpose()
            << " points " << points.size();
    if (points.empty()) continue;
    if (!control.empty()) {
      // The span across the joint hangs: droop sag = fraction * chord.
      const Eigen::Vector3d& a = control.back();
      const Eigen::Vector3d& b = points.front();
      const double sag = std::min(
          options.sag_max,
          rng->Uniform(options.sag_fraction_min, options.sag_fraction_max) * (b - a).norm());
      const std::vector<Eigen::Vector3d> span = SaggingSpan(a, b, sag, down, 5);
      control.insert(control.end(), span.begin() + 1, span.end() - 1);
    }
    control.insert(control.end(), points.begin(), points.end());
    links->push_back(link);
    for (size_t k = 0; k < points.size(); k += 2) sites.push_back({link, points[k], run.u, *radius});
  }
  if (links->size() < 2) return false;
  const std::vector<Eigen::Vector3d> curve =
      FitCenterline(context, control, *radius + options.clearance);
  if (VLOG_IS_ON(2)) {
    double length = 0.0;
    for (size_t i = 1; i < curve.size(); ++i) length += (curve[i] - curve[i - 1]).norm();
    VLOG(2) << "harness length " << length << " m";
    for (const Eigen::Vector3d& p : control) VLOG(2) << "harness control " << p.transpose();
  }
  *mesh = MakeTubeMesh(curve, *radius, options.tube_segments);
  if (mesh->empty()) return false;
  // Clamp sites on the fitted line: the nearest curve point and its tangent.
  for (ClampSite& site : sites) {
    size_t best = 0;
    for (size_t k = 1; k < curve.size(); ++k) {
      if ((curve[k] - site.p_world).squaredNorm() < (curve[best] - site.p_world).squaredNorm()) best = k;
    }
    const size_t lo = best > 0 ? best - 1 : 0, hi = std::min(best + 1, curve.size() - 1);
    site.p_world = curve[best];
    if (hi > lo) site.tangent_world = (curve[hi] - curve[lo]).normalized();
  }
  *clamps = sites;
  return true;
}

bool BuildHose(const PartContext& context, SplitMix64* rng, TriangleMesh* mesh, double* radius,
               std::vector<int>* links) {
  const int n = static_cast<int>(context.chain.size());
  if (n < 2) return false;
  const AccessoryOptions& options = *context.options;
  *radius = rng->Uniform(options.hose_radius_min, options.hose_radius_max);
  const double lift = *radius + options.clearance + 0.002;
  const int from = n <= 3 ? n - 2 : n - 3;
  const int to = n - 1;
  const double azimuth = rng->Uniform(-kPi, kPi);
  const Eigen::Vector3d preferred =
      Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), 0.5).normalized();

  const LinkRun run_from = MakeRun(context, from);
  const LinkRun run_to = MakeRun(context, to);
  const Eigen::Vector3d s_from = SideDirection(run_from.u, preferred);
  const Eigen::Vector3d s_to = SideDirection(run_to.u, preferred);
  const double t = rng->Uniform(0.4, 0.7);
  std::vector<Eigen::Vector3d> start =
      RunPoints(context.clearance->LinkCloud(context.chain[from]), run_from, s_from, t, t + 0.2, 2, lift);
  std::vector<Eigen::Vector3d> end =
      RunPoints(context.clearance->LinkCloud(context.chain[to]), run_to, s_to, 0.5, 0.9, 2, lift);
  if (start.size() < 2 || end.size() < 2) return false;

  // The loop: three points bulging out from the chord, away from the arm.
  const Eigen::Vector3d a = start.back(), b = end.front();
  Eigen::Vector3d out = 0.5 * (s_from + s_to) + 0.3 * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d chord = b - a;
  if (chord.norm() > 1e-6) out -= out.dot(chord.normalized()) * chord.normalized();
  out = out.norm() > 1e-6 ? Eigen::Vector3d(out.normalized()) : chord.unitOrthogonal();
  const double loop = rng->Uniform(options.hose_loop_min, options.hose_loop_max);
  std::vector<Eigen::Vector3d> control = start;
  control.push_back(a + 0.25 * chord + 0.7 * loop * out);
  control.push_back(a + 0.5 * chord + loop * out);
  control.push_back(a + 0.75 * chord + 0.7 * loop * out);
  control.insert(control.end(), end.begin(), end.end());
  const std::vector<Eigen::Vector3d> curve =
      FitCenterline(context, control, *radius + options.clearance);
  *mesh = MakeTubeMesh(curve, *radius, options.tube_segments);
  *links = {context.chain[from], context.chain[to]};
  return !mesh->empty();
}

}  // namespace scene_internal
}  // namespace edgefit
