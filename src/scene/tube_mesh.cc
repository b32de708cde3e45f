#include "edgefit/scene/tube_mesh.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "edgefit/core/angles.h"

namespace edgefit {
namespace {

constexpr double kMinGap = 1e-9;  // [m] points closer than this are merged

std::vector<Eigen::Vector3d> Distinct(const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& p : points) {
    if (out.empty() || (p - out.back()).norm() > kMinGap) out.push_back(p);
  }
  return out;
}

// Barry-Goldman pyramid evaluation of the Catmull-Rom segment between p1
// and p2 with knots t0..t3, at t in [t1, t2].
Eigen::Vector3d EvaluateSegment(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                const Eigen::Vector3d& p2, const Eigen::Vector3d& p3, double t0,
                                double t1, double t2, double t3, double t) {
  const Eigen::Vector3d a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1;
  const Eigen::Vector3d a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2;
  const Eigen::Vector3d a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3;
  const Eigen::Vector3d b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2;
  const Eigen::Vector3d b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3;
  return (t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2;
}

}  // namespace

std::vector<Eigen::Vector3d> CatmullRomCurve(const std::vector<Eigen::Vector3d>& control,
                                             double max_step) {
  CHECK_GT(max_step, 0.0);
  const std::vector<Eigen::Vector3d> p = Distinct(control);
  if (p.size() < 2) return p;
  const size_t n = p.size();
  // Phantom end points reflect the first and last chords.
  std::vector<Eigen::Vector3d> q;
  q.push_back(2 * p[0] - p[1]);
  q.insert(q.end(), p.begin(), p.end());
  q.push_back(2 * p[n - 1] - p[n - 2]);
  // Centripetal knots: t_{i+1} = t_i + |q_{i+1} - q_i|^(1/2).
  std::vector<double> t(q.size(), 0.0);
  for (size_t i = 1; i < q.size(); ++i) t[i] = t[i - 1] + std::sqrt((q[i] - q[i - 1]).norm());

  std::vector<Eigen::Vector3d> curve{p[0]};
  for (size_t i = 1; i + 2 < q.size(); ++i) {
    const double chord = (q[i + 1] - q[i]).norm();
    const int steps = std::max(1, static_cast<int>(std::ceil(chord / max_step)));
    for (int s = 1; s <= steps; ++s) {
      if (s == steps) {
        curve.push_back(q[i + 1]);  // exact control point, no rounding drift
        continue;
      }
      const double u = t[i] + (t[i + 1] - t[i]) * s / steps;
      curve.push_back(EvaluateSegment(q[i - 1], q[i], q[i + 1], q[i + 2], t[i - 1], t[i],
                                      t[i + 1], t[i + 2], u));
    }
  }
  return curve;
}

std::vector<Eigen::Vector3d> SaggingSpan(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                         double sag, const Eigen::Vector3d& down, int count) {
  CHECK_GE(count, 2);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / (count - 1);
    points.push_back((1 - s) * a + s * b + 4.0 * sag * s * (1 - s) * down);
  }
  return points;
}

TriangleMesh MakeTubeMesh(const std::vector<Eigen::Vector3d>& centerline, double radius,
                          int segments) {
  CHECK_GT(radius, 0.0);
  CHECK_GE(segments, 3);
  TriangleMesh mesh;
  const std::vector<Eigen::Vector3d> c = Distinct(centerline);
  const int n = static_cast<int>(c.size());
  if (n < 2) return mesh;

  // Tangents: central differences, one-sided at the ends.
  std::vector<Eigen::Vector3d> tangent(n);
  for (int i = 0; i < n; ++i) {
    tangent[i] = (c[std::min(i + 1, n - 1)] - c[std::max(i - 1, 0)]).normalized();
  }
  // Initial normal: any unit vector perpendicular to the first tangent.
  Eigen::Vector3d r = tangent[0].unitOrthogonal();
  std::vector<Eigen::Vector3d> normal{r};
  for (int i = 0; i + 1 < n; ++i) {
    // Double reflection: reflect (r, t) in the bisector plane of the step,
    // then in the plane that maps the reflected tangent onto t_{i+1}.
    const Eigen::Vector3d v1 = c[i + 1] - c[i];
    const double c1 = v1.squaredNorm();
    const Eigen::Vector3d rl = r - (2.0 / c1) * v1.dot(r) * v1;
    const Eigen::Vector3d tl = tangent[i] - (2.0 / c1) * v1.dot(tangent[i]) * v1;
    const Eigen::Vector3d v2 = tangent[i + 1] - tl;
    const double c2 = v2.squaredNorm();
    r = c2 > 1e-18 ? Eigen::Vector3d(rl - (2.0 / c2) * v2.dot(rl) * v2) : rl;
    // Re-orthogonalize against numeric drift.
    r = (r - r.dot(tangent[i + 1]) * tangent[i + 1]).normalized();
    if (!r.allFinite()) r = tangent[i + 1].unitOrthogonal();
    normal.push_back(r);
  }

  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d binormal = tangent[i].cross(normal[i]);
    for (int s = 0; s < segments; ++s) {
      const double a = 2.0 * kPi * s / segments;
      mesh.vertices.push_back(c[i] + radius * (std::cos(a) * normal[i] + std::sin(a) * binormal));
    }
  }
  // Side quads: ring i to ring i+1, counter-clockwise seen from outside
  // (the ring runs counter-clockwise about the tangent).
  for (int i = 0; i + 1 < n; ++i) {
    for (int s = 0; s < segments; ++s) {
      const int a = i * segments + s, b = i * segments + (s + 1) % segments;
      const int a2 = a + segments, b2 = b + segments;
      mesh.triangles.emplace_back(a, b, b2);
      mesh.triangles.emplace_back(a, b2, a2);
    }
  }
  // Caps: the start cap faces -tangent, the end cap +tangent.
  const int start_center = static_cast<int>(mesh.vertices.size());
  mesh.vertices.push_back(c[0]);
  const int end_center = start_center + 1;
  mesh.vertices.push_back(c[n - 1]);
  const int last = (n - 1) * segments;
  for (int s = 0; s < segments; ++s) {
    const int s1 = (s + 1) % segments;
    mesh.triangles.emplace_back(start_center, s1, s);
    mesh.triangles.emplace_back(end_center, last + s, last + s1);
  }
  return mesh;
}

}  // namespace edgefit
