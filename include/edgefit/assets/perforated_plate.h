// Plates with through-holes (floor plates with anchor-bolt holes, mounting
// brackets, feet): a rectangle with circular holes extruded to a thickness.
//
// The face is split into a grid of rectangular cells whose lines pass at
// each hole's cell borders; a cell without a hole is two triangles, a cell
// with a hole is fanned from its four corners to the hole's circle (one
// triangle per circle segment plus one per side). Cells only meet at their
// corners' grid lines, so the mesh is closed and welded with no
// T-junctions. Holes must lie in rows and columns (a hole's cell must be a
// whole grid cell): bolt patterns do.
#ifndef EDGEFIT_ASSETS_PERFORATED_PLATE_H_
#define EDGEFIT_ASSETS_PERFORATED_PLATE_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct PlateHole {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // [m] in the plate's (x, y).
  double radius = 0.01;                              // [m]
};

struct PerforatedPlateOptions {
  Eigen::Vector2d size = Eigen::Vector2d(0.2, 0.2);  // [m] full extents along x and y.
  double thickness = 0.02;                           // [m] along z, centred on z = 0.
  std::vector<PlateHole> holes;
  // Segments around each hole (a multiple of 4 so that a vertex faces each
  // cell side). 32: facet angle 11.25 deg, far below the 30 deg sharp-edge
  // threshold, so the hole wall is smooth and its rims are sharp.
  int hole_segments = 32;
  // Half-width of a hole's square cell as a multiple of its radius (> 1).
  double cell_scale = 1.6;
};

// CHECKs that every hole cell lies inside the plate and is a whole grid cell.
TriangleMesh MakePerforatedPlate(const PerforatedPlateOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_PERFORATED_PLATE_H_
