#include "edgefit/assets/revolved_mesh.h"

#include <glog/logging.h>

#include <cmath>

#include "edgefit/assets/loft_mesh.h"

namespace edgefit {
namespace {

Ring Circle(const RadialSection& s, int segments, double phase) {
  if (s.r == 0.0) return {Eigen::Vector3d(0.0, 0.0, s.z)};
  Ring ring;
  ring.reserve(segments);
  for (int i = 0; i < segments; ++i) {
    const double theta = phase + 2.0 * M_PI * i / segments;
    ring.emplace_back(s.r * std::cos(theta), s.r * std::sin(theta), s.z);
  }
  return ring;
}

}  // namespace

TriangleMesh MakeRevolvedSolid(const std::vector<RadialSection>& profile, int segments,
                               double phase) {
  CHECK_GE(segments, 3);
  CHECK_GE(profile.size(), 2u);
  std::vector<Ring> rings;
  for (size_t k = 0; k < profile.size(); ++k) {
    CHECK_GE(profile[k].r, 0.0);
    CHECK(profile[k].r > 0.0 || k == 0 || k + 1 == profile.size())
        << "r = 0 only at the ends of a revolved profile";
    rings.push_back(Circle(profile[k], segments, phase));
  }
  return MakeLoftMesh(rings);
}

TriangleMesh MakeRevolvedRing(const std::vector<RadialSection>& closed_profile, int segments) {
  CHECK_GE(segments, 3);
  CHECK_GE(closed_profile.size(), 3u);
  std::vector<Ring> rings;
  for (const RadialSection& s : closed_profile) {
    CHECK_GT(s.r, 0.0);
    rings.push_back(Circle(s, segments, 0.0));
  }
  return MakeClosedLoftMesh(rings);
}

TriangleMesh MakeTube(double r_inner, double r_outer, double length, double chamfer,
                      int segments) {
  CHECK_GT(r_inner, 0.0);
  CHECK_GT(r_outer, r_inner + 2.0 * chamfer);
  CHECK_GT(length, 2.0 * chamfer);
  // Counter-clockwise in (r, z): up the outside, in across the top, down the bore.
  if (chamfer <= 0.0) {
    return MakeRevolvedRing({{0.0, r_outer}, {length, r_outer}, {length, r_inner}, {0.0, r_inner}},
                            segments);
  }
  return MakeRevolvedRing({{chamfer, r_outer},
                           {length - chamfer, r_outer},
                           {length, r_outer - chamfer},
                           {length, r_inner},
                           {0.0, r_inner},
                           {0.0, r_outer - chamfer}},
                          segments);
}

}  // namespace edgefit
