// Tubes for cables and hoses: a smooth centre line through control points
// and a closed mesh of a circle swept along it.
#ifndef EDGEFIT_SCENE_TUBE_MESH_H_
#define EDGEFIT_SCENE_TUBE_MESH_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// Centripetal Catmull-Rom spline (alpha = 1/2; Yuksel et al. 2011: no cusps
// or self-intersections within a segment, little overshoot) through every
// control point, sampled so that consecutive points are at most `max_step`
// [m] apart. The end tangents come from reflected phantom points. Coincident
// consecutive control points are merged first. Fewer than two distinct
// points give those points back.
std::vector<Eigen::Vector3d> CatmullRomCurve(const std::vector<Eigen::Vector3d>& control,
                                             double max_step);

// Points of a cable hanging between a and b (both included), `count` >= 2
// points: the chord plus a parabolic droop s(t) = 4 sag t (1 - t) along the
// unit `down` direction, the small-sag approximation of a catenary; `sag` [m]
// is the droop at mid-span.
std::vector<Eigen::Vector3d> SaggingSpan(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                         double sag, const Eigen::Vector3d& down, int count);

// Closed tube of `radius` [m] around `centerline` (>= 2 distinct points):
// `segments` (>= 3) vertices per ring, rings oriented by rotation-minimizing
// frames (double reflection, Wang et al. 2008) so the tube does not twist,
// and flat end caps fanned around a centre vertex. Every edge is shared by
// two triangles; outward counter-clockwise triangles. Returns an empty mesh
// for fewer than two distinct points.
TriangleMesh MakeTubeMesh(const std::vector<Eigen::Vector3d>& centerline, double radius,
                          int segments);

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_TUBE_MESH_H_
