// CAD-like prismatic parts built from rectangular sections: chamfered boxes,
// tapered castings (frustums whose sections shrink or shift along the axis),
// beams. Every section is a rectangle with 45-degree chamfered corners, so
// side faces between sections are planar and all creases (section changes,
// chamfers) are sharp edges at 45 degrees or more.
#ifndef EDGEFIT_ASSETS_RECTANGULAR_LOFT_H_
#define EDGEFIT_ASSETS_RECTANGULAR_LOFT_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// One cross-section of a rectangular loft along the local z-axis.
struct RectSection {
  double z = 0.0;                                 // [m] height of the section plane.
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // [m] (x, y) of its centre.
  Eigen::Vector2d size = Eigen::Vector2d::Ones();    // [m] full extents along x and y.
  double corner_chamfer = 0.0;  // [m] cut of each vertical corner along x and y (>= 0).
};

// Sections ordered by increasing z (>= 2); either every corner_chamfer is 0
// (4-vertex rings) or every one is > 0 and below half the smaller size
// (8-vertex rings). Closed, outward counter-clockwise.
TriangleMesh MakeRectangularLoft(const std::vector<RectSection>& sections);

// A box of full edge lengths `size`, centred on the origin, with every one of
// its 12 edges cut by a 45-degree chamfer of leg `chamfer` [m] (0 < chamfer <
// min(size) / 4): 6 faces, 12 edge chamfers, 8 corner facets.
TriangleMesh MakeChamferedBox(const Eigen::Vector3d& size, double chamfer);

// A tapered casting along +z from z = 0 to `height`: bottom and top
// sections of sizes `bottom_size` and `top_size` (top centred at
// `top_offset` in x, y), vertical corners chamfered by `corner_chamfer`, the
// top and bottom rims by `rim_chamfer` [m] (0 for none).
TriangleMesh MakeTaperedCasting(const Eigen::Vector2d& bottom_size, const Eigen::Vector2d& top_size,
                                const Eigen::Vector2d& top_offset, double height,
                                double corner_chamfer, double rim_chamfer);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_RECTANGULAR_LOFT_H_
