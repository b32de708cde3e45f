// Horizontal cross-sections for the rough base registration (paper Sec.
// 5.1.1, Fig. 8): of a scan, by intersecting its wireframe (each valid grid
// point joined to its next row and next column neighbour) with horizontal
// planes; of a mesh, by slicing its triangles. Corners of a section are its
// points of high PCA curvature (Eq. 7).
#ifndef EDGEFIT_SOLVERS_BASE_CROSS_SECTIONS_H_
#define EDGEFIT_SOLVERS_BASE_CROSS_SECTIONS_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// Points of one section plane z = height, as (x, y) [m].
struct Section {
  double height = 0.0;  // [m], in the frame the section was cut in
  std::vector<Eigen::Vector2d> points;
};

// Sections of the scans' wireframes at world heights z = heights[k]. Grid
// neighbours farther apart than max_edge [m] are not joined (depth jumps).
// Only points inside crop_world (when not empty) are kept. Deterministic
// order (scan, column, row) for any thread count.
std::vector<Section> ScanSections(const ScanSet& scans, const std::vector<double>& heights,
                                  double max_edge, const Eigen::AlignedBox3d& crop_world);

// Sections of mesh (in its own frame) at z = heights[k], each crossing
// triangle's segment sampled every `spacing` [m] (end points included).
std::vector<Section> MeshSections(const TriangleMesh& mesh, const std::vector<double>& heights,
                                  double spacing);

struct CornerOptions {
  double radius = 0.015;          // PCA neighbourhood [m]
  int min_neighbors = 6;          // fewer: no curvature (isolated points)
  double ratio_to_mean = 3.0;     // corner: curvature > ratio * mean curvature of the section,
  double min_curvature = 0.06;    //   and above this (a 90 deg corner gives ~0.25)
  double separation = 0.03;       // corners closer than this are one corner [m]
};

// Eq. (7): curvature = lambda_1 / (lambda_0 + lambda_1) of the 2x2
// covariance of each point's neighbours within options.radius; points above
// both thresholds, thinned so that no two are closer than separation
// (highest curvature kept). Returns indices into section.points.
std::vector<int> SectionCorners(const Section& section, const CornerOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_CROSS_SECTIONS_H_
