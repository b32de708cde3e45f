#include "edgefit/assets/rectangular_loft.h"

#include <glog/logging.h>

#include <algorithm>

#include "edgefit/assets/loft_mesh.h"

namespace edgefit {
namespace {

// The section's corners counter-clockwise about +z, starting on the -y side.
Ring SectionRing(const RectSection& s) {
  const double hx = 0.5 * s.size.x(), hy = 0.5 * s.size.y(), c = s.corner_chamfer;
  const double cx = s.centre.x(), cy = s.centre.y();
  std::vector<Eigen::Vector2d> xy;
  if (c > 0.0) {
    xy = {{-hx + c, -hy}, {hx - c, -hy}, {hx, -hy + c}, {hx, hy - c},
          {hx - c, hy},   {-hx + c, hy}, {-hx, hy - c}, {-hx, -hy + c}};
  } else {
    xy = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  }
  Ring ring;
  for (const Eigen::Vector2d& p : xy) ring.emplace_back(cx + p.x(), cy + p.y(), s.z);
  return ring;
}

}  // namespace

TriangleMesh MakeRectangularLoft(const std::vector<RectSection>& sections) {
  CHECK_GE(sections.size(), 2u);
  const bool chamfered = sections[0].corner_chamfer > 0.0;
  std::vector<Ring> rings;
  for (size_t k = 0; k < sections.size(); ++k) {
    const RectSection& s = sections[k];
    CHECK_EQ(s.corner_chamfer > 0.0, chamfered) << "section " << k << ": mixed chamfers";
    CHECK_LT(2.0 * s.corner_chamfer, std::min(s.size.x(), s.size.y())) << "section " << k;
    if (k > 0) CHECK_GE(s.z, sections[k - 1].z) << "sections must go up in z";
    rings.push_back(SectionRing(s));
  }
  return MakeLoftMesh(rings);
}

TriangleMesh MakeChamferedBox(const Eigen::Vector3d& size, double chamfer) {
  CHECK_GT(chamfer, 0.0);
  CHECK_LT(4.0 * chamfer, size.minCoeff());
  const Eigen::Vector2d full = size.head<2>();
  const Eigen::Vector2d inset = full - Eigen::Vector2d::Constant(2.0 * chamfer);
  const double hz = 0.5 * size.z();
  // Inset rings at the top and bottom faces; full rings one chamfer in. The
  // corner cut of the inset ring equals the chamfer too, which keeps each
  // corner facet planar (its two horizontal edges are parallel).
  return MakeRectangularLoft({{-hz, {0, 0}, inset, chamfer},
                              {-hz + chamfer, {0, 0}, full, chamfer},
                              {hz - chamfer, {0, 0}, full, chamfer},
                              {hz, {0, 0}, inset, chamfer}});
}

TriangleMesh MakeTaperedCasting(const Eigen::Vector2d& bottom_size, const Eigen::Vector2d& top_size,
                                const Eigen::Vector2d& top_offset, double height,
                                double corner_chamfer, double rim_chamfer) {
  CHECK_GT(height, 2.0 * rim_chamfer);
  const Eigen::Vector2d rim = Eigen::Vector2d::Constant(2.0 * rim_chamfer);
  std::vector<RectSection> sections;
  if (rim_chamfer > 0.0) {
    // The section one rim chamfer up: interpolated so the flank stays planar.
    const double t = rim_chamfer / height;
    sections.push_back({0.0, {0, 0}, bottom_size - rim, corner_chamfer});
    sections.push_back({rim_chamfer, t * top_offset, bottom_size + t * (top_size - bottom_size),
                        corner_chamfer});
    sections.push_back({height - rim_chamfer, (1.0 - t) * top_offset,
                        top_size + t * (bottom_size - top_size), corner_chamfer});
    sections.push_back({height, top_offset, top_size - rim, corner_chamfer});
  } else {
    sections.push_back({0.0, {0, 0}, bottom_size, corner_chamfer});
    sections.push_back({height, top_offset, top_size, corner_chamfer});
  }
  return MakeRectangularLoft(sections);
}

}  // namespace edgefit
